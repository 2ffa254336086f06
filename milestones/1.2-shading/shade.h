/* shade.h: Blinn-Phong shading (slides 17-21, textbook 4.5): diffuse plus specular, per light. */
#ifndef RAYTRA_SHADE_H
#define RAYTRA_SHADE_H

#include <stdbool.h>

#include "color.h"
#include "hit.h"
#include "light.h"
#include "ray.h"
#include "scene.h"

extern const Material shade_back_face_material;

Color shade_blinn_phong(const Material *m, Vec3 n, Vec3 v, const Incident *in);
Vec3 shade_normal(const Hit *hit);
bool shade_shows_back_face(const Hit *hit);
const Material *shade_material(const Scene *scene, const Hit *hit, bool two_sided);
Color shade_direct_radiance(const Scene *scene, const Hit *hit, Ray r, bool two_sided);

#endif
