/* scene.h: the scene model: camera, materials, geometry and lights as a scene file gives them. */
#ifndef RAYTRA_SCENE_H
#define RAYTRA_SCENE_H

#include <stdbool.h>
#include <stdio.h>

#include "color.h"
#include "input.h"
#include "vec3.h"

/* Positive sizes (a radius, a focal length, ...) and the lengths of directions must be at
 * least this: their squares stay far from underflow, as LEX_MAX_NUMBER keeps them from
 * overflow, so that nothing computed from them becomes 0, infinite or NaN. */
#define SCENE_MIN_SIZE 1e-12

/* How a scene's planes and point lights are to be read (docs/scene-format.md). */
typedef enum {
    CONVENTION_LECTURE,  /* planes p.N + d = 0; point lights do not fall off */
    CONVENTION_FALL2016, /* planes p.N = d; point lights fall off as 1/r^2 */
    CONVENTION_COUNT
} Convention;

/* The camera as the c line describes it; milestone 1.1 builds its frame. */
typedef struct {
    Vec3 eye;      /* e: the eye point */
    Vec3 view;     /* D: the viewing direction, unit length */
    double focal;  /* d: distance from the eye to the image plane */
    double width;  /* iw: width of the image plane, in scene units */
    double height; /* ih: its height */
    int nx, ny;    /* pixels across and down */
} CameraSpec;

typedef struct {
    Color diffuse;     /* kd */
    Color specular;    /* ks */
    double phong;      /* the Blinn-Phong exponent p */
    Color mirror;      /* km: ideal (mirror) specular reflectance */
    double ior;        /* index of refraction; 0 for an opaque material */
    Color attenuation; /* transmitted fraction per unit distance inside, (0, 1] */
    int line;          /* the scene file's line that gave it; 0 for none */
} Material;

typedef struct {
    Vec3 center;
    double radius;
    int material;
    int line; /* the scene file's line that gave it, for messages and --trace-pixel */
} Sphere;

/* A plane, always stored in the lecture's form p.normal + d = 0 with |normal| = 1. */
typedef struct {
    Vec3 normal;
    double d;
    int material;
    int line;
} Plane;

/* A triangle whose front side sees a, b, c counterclockwise, as the intersection test
 * and the box of a triangle take it: where its corners are, in the scene's vertices or
 * anywhere else, so that nothing is copied to test it. */
typedef struct {
    const Vec3 *a, *b, *c;
} Triangle;

/* A triangle as the scene keeps it: its corners a, b, c as indices into the scene's
 * vertices, which the triangles of a mesh share, so that a corner is stored once for
 * the five or six triangles around it (pbrt's meshes do the same). */
typedef struct {
    int corner[3]; /* a, b, c */
    int material;
    int line; /* its t line, or the w line of its mesh */
} Face;

typedef enum { LIGHT_POINT, LIGHT_DIRECTIONAL, LIGHT_AREA } LightKind;

typedef struct {
    LightKind kind;
    Vec3 position;  /* point: where it is; area: the centre of the square */
    Vec3 direction; /* directional: unit direction the light travels;
                       area: unit normal the square faces */
    Vec3 u, v;      /* area: unit edge directions, v = u x direction */
    double size;    /* area: length of a side */
    Color color;    /* r g b, times i when the line gives one */
    int line;
} Light;

typedef struct {
    char *path; /* the scene file, for messages */
    Convention convention;
    CameraSpec camera;
    Material *materials;
    int material_count;
    Sphere *spheres;
    int sphere_count;
    Plane *planes;
    int plane_count;
    Vec3 *vertices; /* the corners of the triangles: three for each t line, and the
                       vertices of each w mesh as its OBJ file lists them */
    int vertex_count;
    Face *triangles; /* t lines and every triangle of every w mesh */
    int triangle_count;
    int mesh_count;
    Light *lights; /* point, directional and area lights */
    int light_count;
    Color ambient; /* the l a light; black when there is none */
    FileId *files; /* every file read: the scene file, then each mesh */
    int file_count;
} Scene;

/* What a scene uses, so that a part can say which of it it ignores. */
enum {
    FEATURE_SPHERES = 1u << 0,
    FEATURE_PLANES = 1u << 1,
    FEATURE_TRIANGLES = 1u << 2,
    FEATURE_POINT_LIGHTS = 1u << 3,
    FEATURE_DIRECTIONAL_LIGHTS = 1u << 4,
    FEATURE_AMBIENT_LIGHT = 1u << 5,
    FEATURE_AREA_LIGHTS = 1u << 6,
    FEATURE_MIRRORS = 1u << 7,
    FEATURE_REFRACTION = 1u << 8,
    FEATURE_SHADING = 1u << 9, /* materials' diffuse and specular terms */
    FEATURE_COUNT = 10
};

/* How a scene is to be loaded. */
typedef struct {
    Convention convention; /* used unless the file says otherwise */
    bool forced;           /* the convention was chosen on the command line:
                              an o line cannot change it */
    FILE *messages;        /* where diagnostics go; stderr when NULL */
} SceneLoadOptions;

/* The material geometry gets when no m line came before it. */
extern const Material scene_default_material;

bool scene_load(Scene *scene, const char *path, const SceneLoadOptions *opts);
bool scene_load_stream(Scene *scene, FILE *f, const char *path, const SceneLoadOptions *opts);
void scene_free(Scene *scene);
unsigned scene_features(const Scene *scene);
unsigned scene_light_feature(LightKind kind);
const Light *scene_light_too_bright(const Scene *scene);
const char *scene_feature_name(unsigned feature);
bool scene_triangle_is_degenerate(Vec3 a, Vec3 b, Vec3 c);
const char *convention_name(Convention c);
bool convention_from_name(const char *name, Convention *c);

/* Returns where the corners of triangle k of scene are. */
static inline Triangle scene_triangle(const Scene *scene, int k)
{
    const int *v = scene->triangles[k].corner;
    return (Triangle){&scene->vertices[v[0]], &scene->vertices[v[1]], &scene->vertices[v[2]]};
}

/* Tells whether point lights fall off with the square of the distance. */
static inline bool scene_light_falls_off(const Scene *scene)
{
    return scene->convention == CONVENTION_FALL2016;
}

#endif
