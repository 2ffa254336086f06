/* scene.c: the scene model's helpers: freeing, feature lists, conventions, degeneracy. */
#include "scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Mid-grey and purely diffuse: visible under any light, reflecting nothing. */
const Material scene_default_material = {
    .diffuse = {0.5, 0.5, 0.5},
    .attenuation = {1.0, 1.0, 1.0},
};

static const char *const convention_names[CONVENTION_COUNT] = {
    [CONVENTION_LECTURE] = "lecture",
    [CONVENTION_FALL2016] = "fall2016",
};

/* Returns the name of a convention as the command line and o lines spell it. */
const char *convention_name(Convention c)
{
    return convention_names[c];
}

/* Finds the convention called name; false when there is none. */
bool convention_from_name(const char *name, Convention *c)
{
    for (int k = 0; k < CONVENTION_COUNT; k++)
        if (strcmp(name, convention_names[k]) == 0) {
            *c = (Convention)k;
            return true;
        }
    return false;
}

/* Releases everything the scene owns. */
void scene_free(Scene *scene)
{
    free(scene->path);
    free(scene->materials);
    free(scene->spheres);
    free(scene->planes);
    free(scene->vertices);
    free(scene->triangles);
    free(scene->lights);
    for (int k = 0; k < scene->file_count; k++)
        free(scene->files[k].path);
    free(scene->files);
    memset(scene, 0, sizeof *scene);
}

/* Returns the FEATURE_ bit of the lights of kind. */
/* Returns the scene's brightest point or area light when the scene's convention has no
 * falloff and that light is 100 or more: two orders of magnitude above the lecture's lights
 * near 1, it is one of the Fall 2016 term's, made for 1/r^2 falloff. NULL otherwise. */
const Light *scene_light_too_bright(const Scene *scene)
{
    const Light *brightest = NULL;
    double most = 0;
    for (int k = 0; k < scene->light_count; k++) {
        const Light *l = &scene->lights[k];
        double v = fmax(l->color.r, fmax(l->color.g, l->color.b));
        if (l->kind != LIGHT_DIRECTIONAL && v > most)
            brightest = l, most = v;
    }
    return scene_light_falls_off(scene) || most < 100 ? NULL : brightest;
}

unsigned scene_light_feature(LightKind kind)
{
    static const unsigned kind_feature[] = {
        [LIGHT_POINT] = FEATURE_POINT_LIGHTS,
        [LIGHT_DIRECTIONAL] = FEATURE_DIRECTIONAL_LIGHTS,
        [LIGHT_AREA] = FEATURE_AREA_LIGHTS,
    };
    return kind_feature[kind];
}

/* Returns the FEATURE_ bits of everything the scene contains. */
unsigned scene_features(const Scene *scene)
{
    unsigned f = 0;
    if (scene->sphere_count > 0)
        f |= FEATURE_SPHERES;
    if (scene->plane_count > 0)
        f |= FEATURE_PLANES;
    if (scene->triangle_count > 0)
        f |= FEATURE_TRIANGLES;
    for (int k = 0; k < scene->light_count; k++)
        f |= scene_light_feature(scene->lights[k].kind);
    if (!color_is_black(scene->ambient))
        f |= FEATURE_AMBIENT_LIGHT;
    for (int k = 0; k < scene->material_count; k++) {
        const Material *m = &scene->materials[k];
        f |= FEATURE_SHADING;
        if (!color_is_black(m->mirror))
            f |= FEATURE_MIRRORS;
        if (m->ior > 0)
            f |= FEATURE_REFRACTION;
    }
    return f;
}

/* Returns a plural noun for one FEATURE_ bit, for messages. */
const char *scene_feature_name(unsigned feature)
{
    switch (feature) {
    case FEATURE_SPHERES: return "spheres";
    case FEATURE_PLANES: return "planes";
    case FEATURE_TRIANGLES: return "triangles";
    case FEATURE_POINT_LIGHTS: return "point lights";
    case FEATURE_DIRECTIONAL_LIGHTS: return "directional lights";
    case FEATURE_AMBIENT_LIGHT: return "ambient light";
    case FEATURE_AREA_LIGHTS: return "area lights";
    case FEATURE_MIRRORS: return "mirrors";
    case FEATURE_REFRACTION: return "refraction";
    case FEATURE_SHADING: return "materials";
    }
    return "something";
}

/* Tells whether a triangle has no area: its corners coincide or lie on a line.
 * The test is |e1 x e2| <= 1e-12 |e1| |e2|, the sine of the corner angle,
 * so it does not depend on the size of the triangle; a triangle so small that
 * |e1 x e2| is below SCENE_MIN_SIZE^2 counts too, as its normal could not be normalised. */
bool scene_triangle_is_degenerate(Vec3 a, Vec3 b, Vec3 c)
{
    Vec3 e1 = vec3_sub(b, a), e2 = vec3_sub(c, a);
    double cross = vec3_length(vec3_cross(e1, e2));
    return !(cross > 1e-12 * vec3_length(e1) * vec3_length(e2)) ||
           !(cross >= SCENE_MIN_SIZE * SCENE_MIN_SIZE);
}
