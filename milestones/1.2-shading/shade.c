/* shade.c: the Blinn-Phong model, summed over the lights of the scene (no shadows yet). */
#include "shade.h"

#include <math.h>

/* starter: todo */
/* Returns the two terms of the light reflected towards v from what one light sends
 * along in->dir, by Blinn-Phong: I (.) kd max(0, n.l) and I (.) ks max(0, n.h)^p with
 * h = normalize(l + v). n, v and l are unit vectors; v points from the surface to the eye. */
BlinnPhong shade_blinn_phong_terms(const Material *m, Vec3 n, Vec3 v, const Incident *in)
{
    Vec3 l = in->dir;
    double n_dot_l = vec3_dot(n, l);
    /* A light behind the surface (or exactly in its plane) adds nothing, highlight
     * included: seen from the light, this side of the surface is in its own shadow. */
    if (n_dot_l <= 0)
        return (BlinnPhong){{0, 0, 0}, {0, 0, 0}};
    /* Diffuse (Lambert): light spread over an area 1/cos(theta) larger. */
    Color diffuse = color_scale(m->diffuse, n_dot_l);
    /* Specular: the half vector h lies halfway between l and v; it lines up with n
     * exactly when v is the mirror image of l, where the highlight peaks. */
    Vec3 h = vec3_normalize(vec3_add(l, v));
    double n_dot_h = fmax(0, vec3_dot(n, h));
    Color specular = color_scale(m->specular, pow(n_dot_h, m->phong));
    return (BlinnPhong){color_mul(in->radiance, diffuse), color_mul(in->radiance, specular)};
}

/* Returns the light reflected towards v from one light: diffuse plus specular. */
Color shade_blinn_phong(const Material *m, Vec3 n, Vec3 v, const Incident *in)
{
    BlinnPhong terms = shade_blinn_phong_terms(m, n, v, in);
    return color_add(terms.diffuse, terms.specular);
}

/* Says, for --trace-pixel, when a back face is shaded in the yellow material. */
void shade_explain_material(const Explain *e, int depth, const Material *m)
{
    if (e != NULL && m == &shade_back_face_material)
        explain_line(e, depth,
                     "a back face: shaded in the yellow back-face material, "
                     "kd (1, 1, 0), no specular, no mirror");
}

/* Prints what light k brings to a point for --trace-pixel: where from, how much, and
 * its diffuse and specular terms. */
void shade_explain_light(const Explain *e, int depth, int k, const Incident *in, BlinnPhong terms)
{
    if (e == NULL)
        return;
    static const char *const kinds[] = {"point", "directional", "area"};
    const Light *light = &e->scene->lights[k];
    char where[300], l[96];
    explain_line(e, depth, "light %d, %s%s: towards it %s, arriving (%.6g, %.6g, %.6g)", k,
                 kinds[light->kind], explain_where(e, light->line, where, sizeof where),
                 explain_vec3(in->dir, l, sizeof l), in->radiance.r, in->radiance.g,
                 in->radiance.b);
    explain_color(e, depth + 1, "diffuse", terms.diffuse);
    explain_color(e, depth + 1, "specular", terms.specular);
}

/* excerpt: shade-normal */
/* Returns the normal to shade with: the geometric normal turned to face the ray, so
 * that the side the ray sees is lit as a front (the back of a triangle in
 * --two-sided mode, the inside of a sphere seen from within). */
Vec3 shade_normal(const Hit *hit)
{
    return hit->back_face ? vec3_neg(hit->normal) : hit->normal;
}

/* Tells whether the ray hit the back of a triangle or plane, which the course shows
 * yellow; a sphere seen from inside is not a wrongly wound surface. */
bool shade_shows_back_face(const Hit *hit)
{
    return hit->back_face && hit->kind != SURFACE_SPHERE;
}
/* end excerpt: shade-normal */

/* excerpt: shade-material */
/* The material of the back of a triangle or plane: yellow, diffuse only. The slides
 * give no rule; every public renderer of the course's Fall 2016 term shades back
 * faces so, lit like any surface (docs/1.2-shading.md). */
const Material shade_back_face_material = {.diffuse = {1, 1, 0}, .attenuation = {1, 1, 1}};

/* Returns the material to shade hit with: its own, or the yellow back-face material
 * when the ray meets the back of a triangle or plane (unless two_sided). */
const Material *shade_material(const Scene *scene, const Hit *hit, bool two_sided)
{
    if (shade_shows_back_face(hit) && !two_sided)
        return &shade_back_face_material;
    return &scene->materials[hit->material];
}
/* end excerpt: shade-material */

/* starter: todo */
/* Returns the light that hit's surface reflects back along ray r straight from the
 * scene's point and directional lights, without shadows; part 1.3's direct_radiance
 * replaces it, with shadows and the ambient light. Area lights wait for part 1.6. */
Color shade_direct_radiance(const Scene *scene, const Hit *hit, Ray r, bool two_sided)
{
    const Material *m = shade_material(scene, hit, two_sided);
    Vec3 n = shade_normal(hit);
    Vec3 v = vec3_neg(r.dir);
    Color sum = color(0, 0, 0);
    for (int k = 0; k < scene->light_count; k++) {
        if (scene->lights[k].kind == LIGHT_AREA)
            continue;
        Incident in = light_incident(&scene->lights[k], hit->point, scene_light_falls_off(scene));
        sum = color_add(sum, shade_blinn_phong(m, n, v, &in));
    }
    return sum;
}

/* Prints, for --trace-pixel, how part 1.2 lights hit: its material, and each light's
 * Blinn-Phong terms, as shade_direct_radiance adds them up. */
void shade_explain_lights(const Explain *e, const Scene *scene, const Hit *hit, Ray r,
                          bool two_sided)
{
    if (e == NULL)
        return;
    const Material *m = shade_material(scene, hit, two_sided);
    shade_explain_material(e, 1, m);
    for (int k = 0; k < scene->light_count; k++) {
        if (scene->lights[k].kind == LIGHT_AREA) {
            explain_line(e, 1, "light %d: an area light, lit from part 1.6 on", k);
            continue;
        }
        Incident in = light_incident(&scene->lights[k], hit->point, scene_light_falls_off(scene));
        shade_explain_light(e, 1, k, &in,
                            shade_blinn_phong_terms(m, shade_normal(hit), vec3_neg(r.dir), &in));
    }
}
