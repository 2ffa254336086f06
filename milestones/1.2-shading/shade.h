/* shade.h: Blinn-Phong shading, diffuse plus specular, per light (textbook 4.5).
 * Slides 18-20 ("diffuse (lambertian) shading"). */
#ifndef RAYTRA_SHADE_H
#define RAYTRA_SHADE_H

#include <stdbool.h>

#include "cli.h"
#include "color.h"
#include "explain.h"
#include "hit.h"
#include "light.h"
#include "ray.h"
#include "scene.h"

/* The two terms of Blinn-Phong for one light, each already times the light's I. */
typedef struct {
    Color diffuse, specular;
} BlinnPhong;

extern const Material shade_back_face_material;

extern const CliOption shade_options[];
extern const CliOption *const shade_part_options[];

BlinnPhong shade_blinn_phong_terms(const Material *m, Vec3 n, Vec3 v, const Incident *in);
Color shade_blinn_phong(const Material *m, Vec3 n, Vec3 v, const Incident *in);
Vec3 shade_normal(const Hit *hit);
bool shade_shows_back_face(const Hit *hit);
const Material *shade_material(const Scene *scene, const Hit *hit, bool two_sided);
Color shade_direct_radiance(const Scene *scene, const Hit *hit, Ray r, bool two_sided);
void shade_explain_lights(const Explain *e, const Scene *scene, const Hit *hit, Ray r,
                          bool two_sided);
void shade_explain_material(const Explain *e, int depth, const Material *m);
void shade_explain_light(const Explain *e, int depth, int k, const Incident *in, BlinnPhong terms);

#endif
