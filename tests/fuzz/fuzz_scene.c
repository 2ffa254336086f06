/* fuzz_scene.c: the libFuzzer harness of the scene reader: any bytes, then the invariants. */
#include <ctype.h>
#include <math.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "fuzz.h"
#include "image.h"
#include "lex.h"
#include "scene.h"

/* The meshes a fuzzed scene may name with w; the folder they are in is made at start-up. */
static const struct {
    const char *name;
    const char *text; /* NULL: a folder */
} meshes[] = {
    {"mesh.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
                 "f 1 2 3 4\nf -5 -4 -1\nf 1 1 2\nf 1/1 3//3 5/5/5\n"},
    {"bad.obj", "v 0 0 0\nf 1 2 3\n"},
    {"empty.obj", ""},
    {"folder.obj", NULL},
};

/* A mesh that no folder holds: looking for it (access() only) reaches the root, but it is
 * never there, so the answer is always the same. */
static const char missing_mesh[] = "raytra-fuzz-missing.obj";

/* Where diagnostics go: they are formatted (and so tested) but not kept. */
static FILE *messages;

/* The folder the harness works in: a fresh one in $TMPDIR (or /tmp), holding only the
 * meshes above. */
static char *folder;

/* Removes the working folder and closes the sink for diagnostics when the fuzzer or the
 * driver exits. */
static void clean_up(void)
{
    fclose(messages);
    for (size_t k = 0; k < sizeof meshes / sizeof meshes[0]; k++)
        if (meshes[k].text != NULL)
            unlink(meshes[k].name);
        else
            rmdir(meshes[k].name);
    if (chdir("/") == 0)
        rmdir(folder);
    free(folder);
}

/* Makes the working folder with its meshes and moves into it, so that w lines resolve there. */
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    messages = fopen("/dev/null", "w");
    FUZZ_CHECK(messages != NULL);
    const char *tmp = getenv("TMPDIR");
    if (tmp == NULL || *tmp == '\0')
        tmp = "/tmp";
    size_t size = strlen(tmp) + sizeof "/raytra-fuzz.XXXXXX";
    folder = malloc(size);
    FUZZ_CHECK(folder != NULL);
    snprintf(folder, size, "%s/raytra-fuzz.XXXXXX", tmp);
    FUZZ_CHECK(mkdtemp(folder) != NULL);
    atexit(clean_up);
    FUZZ_CHECK(chdir(folder) == 0);
    for (size_t k = 0; k < sizeof meshes / sizeof meshes[0]; k++) {
        if (meshes[k].text == NULL) {
            FUZZ_CHECK(mkdir(meshes[k].name, 0700) == 0);
            continue;
        }
        FILE *f = fopen(meshes[k].name, "w");
        FUZZ_CHECK(f != NULL);
        fputs(meshes[k].text, f);
        FUZZ_CHECK(fclose(f) == 0);
    }
    return 0;
}

/* Tells whether a w line's path (n bytes at name) is one the harness allows: none at all,
 * or one of its meshes, perhaps written "./mesh.obj". */
static bool mesh_allowed(const uint8_t *name, size_t n)
{
    while (n >= 2 && memcmp(name, "./", 2) == 0) {
        name += 2;
        n -= 2;
    }
    if (n == 0 || (n == strlen(missing_mesh) && memcmp(name, missing_mesh, n) == 0))
        return true;
    for (size_t k = 0; k < sizeof meshes / sizeof meshes[0]; k++)
        if (n == strlen(meshes[k].name) && memcmp(name, meshes[k].name, n) == 0)
            return true;
    return false;
}

/* Tells whether every w line of the input names an allowed mesh, reading lines as the
 * parser does (or more strictly), so that no input reads files outside the folder. */
static bool meshes_allowed(const uint8_t *data, size_t size)
{
    const uint8_t *end = data + size;
    for (const uint8_t *line = data; line < end;) {
        const uint8_t *eol = memchr(line, '\n', (size_t)(end - line));
        if (eol == NULL)
            eol = end;
        const uint8_t *p = line;
        while (p < eol && isspace(*p))
            p++;
        if (p < eol && *p == 'w' && (p + 1 == eol || isspace(p[1]) || p[1] == '\0')) {
            const uint8_t *name = p + 1, *last = eol;
            while (name < last && isspace(*name))
                name++;
            while (last > name && isspace(last[-1]))
                last--;
            if (!mesh_allowed(name, (size_t)(last - name)))
                return false;
        }
        line = eol + 1;
    }
    return true;
}

/* Asserts that v is a unit vector. */
static void check_unit(Vec3 v)
{
    FUZZ_CHECK(vec3_is_finite(v));
    FUZZ_CHECK(fabs(vec3_length(v) - 1) < 1e-9);
}

/* Asserts that c is a colour of finite, non-negative components. */
static void check_color(Color c)
{
    FUZZ_CHECK(color_is_finite(c));
    FUZZ_CHECK(c.r >= 0 && c.g >= 0 && c.b >= 0);
}

/* Asserts that v is a length the renderer can square and divide by. */
static void check_size(double v)
{
    FUZZ_CHECK(isfinite(v));
    FUZZ_CHECK(v >= SCENE_MIN_SIZE && v <= LEX_MAX_NUMBER);
}

/* Asserts that material index m is in range. */
static void check_material_index(const Scene *s, int m)
{
    FUZZ_CHECK(m >= 0 && m < s->material_count);
}

/* Checks the camera: a sane frame and an image that can be allocated. */
static void check_camera(const CameraSpec *c)
{
    FUZZ_CHECK(vec3_is_finite(c->eye) && vec3_max_abs(c->eye) <= LEX_MAX_NUMBER);
    check_unit(c->view);
    check_size(c->focal);
    check_size(c->width);
    check_size(c->height);
    FUZZ_CHECK(image_size_ok(c->nx, c->ny));
}

/* Checks every material: the ranges docs/scene-format.md promises. */
static void check_materials(const Scene *s)
{
    for (int k = 0; k < s->material_count; k++) {
        const Material *m = &s->materials[k];
        check_color(m->diffuse);
        check_color(m->specular);
        check_color(m->mirror);
        FUZZ_CHECK(isfinite(m->phong) && m->phong >= 0);
        FUZZ_CHECK(m->ior == 0 || (m->ior >= SCENE_MIN_SIZE && m->ior <= LEX_MAX_NUMBER));
        check_color(m->attenuation);
        FUZZ_CHECK(m->attenuation.r > 0 && m->attenuation.g > 0 && m->attenuation.b > 0);
        FUZZ_CHECK(m->attenuation.r <= 1 && m->attenuation.g <= 1 && m->attenuation.b <= 1);
    }
}

/* Checks the spheres, planes and triangles. */
static void check_geometry(const Scene *s)
{
    for (int k = 0; k < s->sphere_count; k++) {
        const Sphere *sp = &s->spheres[k];
        FUZZ_CHECK(vec3_is_finite(sp->center));
        check_size(sp->radius);
        check_material_index(s, sp->material);
    }
    for (int k = 0; k < s->plane_count; k++) {
        const Plane *pl = &s->planes[k];
        check_unit(pl->normal);
        FUZZ_CHECK(isfinite(pl->d));
        check_material_index(s, pl->material);
    }
    FUZZ_CHECK(s->vertex_count == 0 || s->vertices != NULL);
    for (int k = 0; k < s->triangle_count; k++) {
        const int *corner = s->triangles[k].corner;
        for (int c = 0; c < 3; c++)
            FUZZ_CHECK(corner[c] >= 0 && corner[c] < s->vertex_count);
        Triangle t = scene_triangle(s, k);
        FUZZ_CHECK(vec3_is_finite(*t.a) && vec3_is_finite(*t.b) && vec3_is_finite(*t.c));
        FUZZ_CHECK(!scene_triangle_is_degenerate(*t.a, *t.b, *t.c));
        check_unit(vec3_normalize(vec3_cross(vec3_sub(*t.b, *t.a), vec3_sub(*t.c, *t.a))));
        check_material_index(s, s->triangles[k].material);
    }
}

/* Checks the lights: finite colours, unit directions, a square frame for area lights. */
static void check_lights(const Scene *s)
{
    check_color(s->ambient);
    for (int k = 0; k < s->light_count; k++) {
        const Light *l = &s->lights[k];
        check_color(l->color);
        switch (l->kind) {
        case LIGHT_POINT: FUZZ_CHECK(vec3_is_finite(l->position)); break;
        case LIGHT_DIRECTIONAL: check_unit(l->direction); break;
        case LIGHT_AREA:
            FUZZ_CHECK(vec3_is_finite(l->position));
            check_unit(l->direction);
            check_unit(l->u);
            check_unit(l->v);
            FUZZ_CHECK(fabs(vec3_dot(l->u, l->direction)) < 1e-9);
            FUZZ_CHECK(fabs(vec3_dot(l->v, l->direction)) < 1e-9);
            check_size(l->size);
            break;
        default: FUZZ_CHECK(!"unknown light kind");
        }
    }
}

/* Checks everything a part's renderer relies on in a scene that loaded. */
static void check_scene(const Scene *s)
{
    FUZZ_CHECK(s->path != NULL);
    FUZZ_CHECK(s->convention >= 0 && s->convention < CONVENTION_COUNT);
    FUZZ_CHECK(s->material_count >= 0 && s->sphere_count >= 0 && s->plane_count >= 0);
    FUZZ_CHECK(s->triangle_count >= 0 && s->light_count >= 0 && s->mesh_count >= 0);
    check_camera(&s->camera);
    check_materials(s);
    check_geometry(s);
    check_lights(s);
}

/* Reads data as a scene file from memory and checks the scene it makes, if any. Inputs
 * whose w lines name other files are refused (-1: not kept in the corpus). */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (!meshes_allowed(data, size))
        return -1;
    static const char empty[1];
    FILE *f = fmemopen(size > 0 ? (void *)data : (void *)empty, size, "r");
    FUZZ_CHECK(f != NULL);
    /* The convention as the command line may give it, chosen by the input's size so that
     * an input always loads the same way. */
    static const SceneLoadOptions choices[] = {
        {CONVENTION_LECTURE, false, NULL},
        {CONVENTION_LECTURE, true, NULL},
        {CONVENTION_FALL2016, true, NULL},
    };
    SceneLoadOptions opts = choices[size % 3];
    opts.messages = messages;
    Scene scene;
    bool ok = scene_load_stream(&scene, f, "./fuzz.scn", &opts);
    fclose(f);
    if (ok) {
        check_scene(&scene);
        scene_free(&scene);
    }
    return 0;
}
