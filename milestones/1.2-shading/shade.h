/* shade.h: Blinn-Phong shading (slides 17-21, textbook 4.5): diffuse plus specular, per light. */
#ifndef RAYTRA_SHADE_H
#define RAYTRA_SHADE_H

#include "color.h"
#include "hit.h"
#include "light.h"
#include "ray.h"
#include "scene.h"

/* The course's flat colour for the back of a triangle or plane: it shows wrong winding. */
#define SHADE_BACK_FACE_COLOR ((Color){1, 1, 0})

Color shade_blinn_phong(const Material *m, Vec3 n, Vec3 v, const Incident *in);
Vec3 shade_normal(const Hit *hit);
bool shade_shows_back_face(const Hit *hit);
Color shade_lights(const Scene *scene, const Hit *hit, Ray r);

#endif
