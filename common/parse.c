/* parse.c: the scene-file reader: every command of the lecture and the assignment, checked. */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "array.h"
#include "diag.h"
#include "image.h"
#include "lex.h"
#include "obj.h"
#include "scene.h"
#include "stop.h"

typedef struct Parser Parser;

/* A command's handler gets its numbers already counted and read. */
typedef void (*CommandFn)(Parser *p, const double *v, int n, char *const *words);

typedef struct {
    const char *name; /* as written: "s", or "l p" for a light */
    const char *what; /* for messages: "sphere" */
    const char *args; /* the numbers' names; optional ones in brackets */
    int min, max;     /* how many numbers it takes */
    CommandFn parse;
} Command;

struct Parser {
    Scene *scene;
    Diag *diag;
    const char *path;
    int line;
    int camera_line;     /* where the camera was given; 0 before */
    int camera_tried;    /* the last c line, whether or not it could be read; 0 if none */
    int material;        /* the current material; -1 before the first m */
    int ambient_line;    /* where the ambient light was given; 0 before */
    int convention_line; /* where an o line chose a convention; 0 if none */
    Convention convention;
    int obj_lines; /* v and f lines: a mesh given where a scene belongs */
    int material_capacity, sphere_capacity, plane_capacity, triangle_capacity, light_capacity;
    int vertex_capacity, file_capacity;
    char head[8]; /* the first bytes of the file, to name an image given as a scene */
    bool stopped; /* reading ended early: a stop request, a binary file or a read error */
};

/* Reports an error on the line being read. */
#define ERROR(p, ...) diag_error((p)->diag, (p)->path, (p)->line, __VA_ARGS__)

/* Makes room for one more item in array a of the scene, items called what in messages;
 * false (reported) when out of memory or at the limit. */
#define ROOM_FOR(p, a, count, capacity, what)                                                      \
    room_for((p), &(a), &(capacity), (count), sizeof *(a), (what))

/* The function behind ROOM_FOR. */
static bool room_for(Parser *p, void *items, int *capacity, int count, size_t size,
                     const char *what)
{
    if (array_grow(items, capacity, count, size))
        return true;
    if (count >= ARRAY_MAX_ITEMS)
        ERROR(p, "more than %d %s: the limit of the scene format", ARRAY_MAX_ITEMS, what);
    else
        ERROR(p, "out of memory for %d %s", count + 1, what);
    /* Every later line would fail the same way: one message is enough. */
    p->stopped = true;
    return false;
}

/* Returns the current material, giving geometry before any m line the default one. */
static int current_material(Parser *p)
{
    if (p->material >= 0)
        return p->material;
    Scene *s = p->scene;
    if (!ROOM_FOR(p, s->materials, s->material_count, p->material_capacity, "materials"))
        return 0;
    diag_warn(p->diag, p->path, p->line,
              "geometry before the first material (m) gets the default material "
              "(grey diffuse 0.5, no highlight, no mirror)");
    s->materials[s->material_count] = scene_default_material;
    s->materials[s->material_count].line = p->line;
    p->material = s->material_count++;
    return p->material;
}

/* Tells whether a colour is non-negative; reports it otherwise. */
static bool check_color(Parser *p, const char *what, const double *v, char *const *words)
{
    for (int k = 0; k < 3; k++)
        if (v[k] < 0) {
            ERROR(p, "%s must not be negative, got %s", what, words[k]);
            return false;
        }
    return true;
}

/* Tells whether a material's colour is a reflectance, each component in [0, 1]; reports it
 * otherwise. A surface reflects at most the light that falls on it: the lecture gives
 * material colours "on [0 1]" and only light colours "may be > 1":
 * slide 66 ("these may be > 1"). A mirror
 * colour above 1 would even multiply the light at every bounce, up to infinity. */
static bool check_reflectance(Parser *p, const char *what, const double *v, char *const *words)
{
    if (!check_color(p, what, v, words))
        return false;
    for (int k = 0; k < 3; k++)
        if (v[k] > 1) {
            /* 85 for 0.85 is the usual slip: say so. */
            ERROR(p,
                  "%s must be in [0, 1] (a material reflects at most the light it gets), "
                  "got %s%s",
                  what, words[k], v[k] <= 100 ? "; a percentage? write it as a fraction" : "");
            return false;
        }
    return true;
}

/* Tells whether a size is positive and not too small to compute with; reports it otherwise. */
static bool check_positive(Parser *p, const char *what, double v, const char *word)
{
    if (!(v > 0)) {
        ERROR(p, "%s must be positive, got %s", what, word);
        return false;
    }
    if (v < SCENE_MIN_SIZE) {
        ERROR(p, "%s %s is too small (the limit is %g)", what, word, SCENE_MIN_SIZE);
        return false;
    }
    return true;
}

/* Tells whether a direction is long enough to be normalised; reports it otherwise. */
static bool check_direction(Parser *p, const char *what, Vec3 v)
{
    double length = vec3_length(v);
    if (length >= SCENE_MIN_SIZE)
        return true;
    if (length > 0)
        ERROR(p, "%s is too short to have a direction (its length must be at least %g)", what,
              SCENE_MIN_SIZE);
    else
        ERROR(p, "%s must not be the zero vector", what);
    return false;
}

/* Reads a pixel count: a whole number from 1 to IMAGE_MAX_SIDE. */
static bool pixel_count(Parser *p, const char *what, double v, const char *word, int *out)
{
    if (!(v >= 1) || v != floor(v)) {
        ERROR(p, "camera %s must be a positive whole number, got %s", what, word);
        return false;
    }
    *out = v > IMAGE_MAX_SIDE ? IMAGE_MAX_SIDE + 1 : (int)v;
    return true;
}

/* s x y z r: a sphere of radius r centred at (x, y, z). */
static void parse_sphere(Parser *p, const double *v, int n, char *const *words)
{
    (void)n;
    if (!check_positive(p, "sphere radius", v[3], words[3]))
        return;
    Scene *s = p->scene;
    int material = current_material(p);
    if (ROOM_FOR(p, s->spheres, s->sphere_count, p->sphere_capacity, "spheres"))
        s->spheres[s->sphere_count++] = (Sphere){vec3(v[0], v[1], v[2]), v[3], material, p->line};
}

/* Appends vertex v to the scene; false (reported) when there is no room. */
static bool add_vertex(Parser *p, Vec3 v)
{
    Scene *s = p->scene;
    if (!ROOM_FOR(p, s->vertices, s->vertex_count, p->vertex_capacity, "vertices"))
        return false;
    s->vertices[s->vertex_count++] = v;
    return true;
}

/* Appends the triangle of vertices a, b and c of the scene, given on the line being read
 * (a t or w line), in material; false (reported) when there is no room. */
static bool add_triangle(Parser *p, int a, int b, int c, int material)
{
    Scene *s = p->scene;
    if (!ROOM_FOR(p, s->triangles, s->triangle_count, p->triangle_capacity, "triangles"))
        return false;
    s->triangles[s->triangle_count++] = (Face){{a, b, c}, material, p->line};
    return true;
}

/* t x1 y1 z1 x2 y2 z2 x3 y3 z3: a triangle, counterclockwise seen from its front. */
static void parse_triangle(Parser *p, const double *v, int n, char *const *words)
{
    (void)n, (void)words;
    Vec3 a = vec3(v[0], v[1], v[2]), b = vec3(v[3], v[4], v[5]), c = vec3(v[6], v[7], v[8]);
    if (scene_triangle_is_degenerate(a, b, c)) {
        diag_warn(p->diag, p->path, p->line, "degenerate triangle (no area) skipped");
        return;
    }
    int material = current_material(p);
    int first = p->scene->vertex_count;
    if (add_vertex(p, a) && add_vertex(p, b) && add_vertex(p, c))
        add_triangle(p, first, first + 1, first + 2, material);
}

/* p nx ny nz d: a plane; its normal and d are put in the lecture's form by finish_planes. */
static void parse_plane(Parser *p, const double *v, int n, char *const *words)
{
    (void)n, (void)words;
    Vec3 normal = vec3(v[0], v[1], v[2]);
    if (!check_direction(p, "plane normal", normal))
        return;
    Scene *s = p->scene;
    int material = current_material(p);
    if (ROOM_FOR(p, s->planes, s->plane_count, p->plane_capacity, "planes"))
        s->planes[s->plane_count++] = (Plane){normal, v[3], material, p->line};
}

/* c x y z vx vy vz d iw ih pw ph: the camera (exactly one per scene). */
static void parse_camera(Parser *p, const double *v, int n, char *const *words)
{
    (void)n;
    if (p->camera_line > 0) {
        ERROR(p, "a second camera (c); the first is on line %d", p->camera_line);
        return;
    }
    CameraSpec c = {.eye = vec3(v[0], v[1], v[2]),
                    .view = vec3(v[3], v[4], v[5]),
                    .focal = v[6],
                    .width = v[7],
                    .height = v[8]};
    bool ok = check_direction(p, "camera view direction", c.view);
    ok = check_positive(p, "camera focal length", c.focal, words[6]) && ok;
    ok = check_positive(p, "camera image-plane width", c.width, words[7]) && ok;
    ok = check_positive(p, "camera image-plane height", c.height, words[8]) && ok;
    ok = pixel_count(p, "pixel width", v[9], words[9], &c.nx) && ok;
    ok = pixel_count(p, "pixel height", v[10], words[10], &c.ny) && ok;
    if (ok && !image_size_ok(c.nx, c.ny)) {
        ERROR(p, "an image of %s x %s pixels is too large (at most %d on a side and %ld in all)",
              words[9], words[10], IMAGE_MAX_SIDE, IMAGE_MAX_PIXELS);
        ok = false;
    }
    p->camera_line = p->line;
    if (ok) {
        c.view = vec3_normalize(c.view);
        p->scene->camera = c;
    }
}

/* Reads a light's colour r g b and its optional intensity i (at v[3]), multiplied in. */
static bool light_color(Parser *p, const double *v, int n, char *const *words, Color *out)
{
    if (!check_color(p, "light colour", v, words))
        return false;
    double i = n > 3 ? v[3] : 1.0;
    if (i < 0) {
        ERROR(p, "light intensity must not be negative, got %s", words[3]);
        return false;
    }
    /* Stored, the light is a number as any other: at most 1e12, so that every pixel stays
     * far below the largest float (docs/robustness.md), where a light of 1e12 1e12 1e12
     * 1e12 (1e24) made them overflow. Without i, the lexer has checked the colour. */
    for (int k = 0; k < 3; k++)
        if (v[k] * i > LEX_MAX_NUMBER) {
            ERROR(p, "light colour times intensity must be at most 1e12, got %s x %s = %g",
                  words[k], words[3], v[k] * i);
            return false;
        }
    *out = color_scale(color(v[0], v[1], v[2]), i);
    return true;
}

/* Appends light to the scene. */
static void add_light(Parser *p, Light light)
{
    Scene *s = p->scene;
    light.line = p->line;
    if (ROOM_FOR(p, s->lights, s->light_count, p->light_capacity, "lights"))
        s->lights[s->light_count++] = light;
}

/* l p x y z r g b [i]: a point light. */
static void parse_point_light(Parser *p, const double *v, int n, char *const *words)
{
    Light l = {.kind = LIGHT_POINT, .position = vec3(v[0], v[1], v[2])};
    if (light_color(p, v + 3, n - 3, words + 3, &l.color))
        add_light(p, l);
}

/* l d vx vy vz r g b [i]: a directional light shining along v. */
static void parse_directional_light(Parser *p, const double *v, int n, char *const *words)
{
    Light l = {.kind = LIGHT_DIRECTIONAL, .direction = vec3(v[0], v[1], v[2])};
    bool ok = check_direction(p, "directional light direction", l.direction);
    if (light_color(p, v + 3, n - 3, words + 3, &l.color) && ok) {
        l.direction = vec3_normalize(l.direction);
        add_light(p, l);
    }
}

/* l a r g b [i]: the ambient light; a second one adds to the first. */
static void parse_ambient_light(Parser *p, const double *v, int n, char *const *words)
{
    Color c;
    if (!light_color(p, v, n, words, &c))
        return;
    if (p->ambient_line > 0)
        diag_warn(p->diag, p->path, p->line,
                  "more than one ambient light (l a); they are added together");
    p->ambient_line = p->line;
    Color sum = color_add(p->scene->ambient, c);
    if (fmax(sum.r, fmax(sum.g, sum.b)) > LEX_MAX_NUMBER) {
        ERROR(p, "the ambient lights (l a) add up to more than 1e12");
        return;
    }
    p->scene->ambient = sum;
}

/* l s x y z nx ny nz ux uy uz len r g b [i]: a square area light facing n. */
static void parse_area_light(Parser *p, const double *v, int n, char *const *words)
{
    Vec3 normal = vec3(v[3], v[4], v[5]), u = vec3(v[6], v[7], v[8]);
    bool ok = check_direction(p, "area light normal", normal);
    ok = check_direction(p, "area light u direction", u) && ok;
    ok = check_positive(p, "area light side length", v[9], words[9]) && ok;
    Light l = {.kind = LIGHT_AREA, .position = vec3(v[0], v[1], v[2]), .size = v[9]};
    ok = light_color(p, v + 10, n - 10, words + 10, &l.color) && ok;
    if (!ok)
        return;
    /* Make u exactly perpendicular to the normal (Gram-Schmidt), then v = u x n. */
    l.direction = vec3_normalize(normal);
    Vec3 u_perp = vec3_add_scaled(u, l.direction, -vec3_dot(u, l.direction));
    if (!(vec3_length(u_perp) > 1e-9 * vec3_length(u))) {
        ERROR(p, "area light u direction must not be parallel to its normal");
        return;
    }
    l.u = vec3_normalize(u_perp);
    l.v = vec3_cross(l.u, l.direction);
    add_light(p, l);
}

/* m dr dg db sr sg sb p ir ig ib [n [ar ag ab]]: the material of the geometry that follows. */
static void parse_material(Parser *p, const double *v, int n, char *const *words)
{
    if (n == 12 || n == 13) {
        ERROR(p,
              "material (m) takes 10 numbers, 11 with an index of refraction, "
              "or 14 with an rgb attenuation too; got %d",
              n);
        return;
    }
    bool ok = check_reflectance(p, "diffuse colour", v, words);
    ok = check_reflectance(p, "specular colour", v + 3, words + 3) && ok;
    ok = check_reflectance(p, "mirror colour", v + 7, words + 7) && ok;
    if (v[6] < 0) {
        ERROR(p, "phong exponent must not be negative, got %s", words[6]);
        ok = false;
    }
    Material m = {.diffuse = color(v[0], v[1], v[2]),
                  .specular = color(v[3], v[4], v[5]),
                  .phong = v[6],
                  .mirror = color(v[7], v[8], v[9]),
                  .attenuation = color(1, 1, 1)};
    if (n >= 11) {
        ok = check_positive(p, "index of refraction", v[10], words[10]) && ok;
        m.ior = v[10];
    }
    if (n == 14) {
        for (int k = 11; k < 14; k++)
            if (!(v[k] > 0 && v[k] <= 1)) {
                ERROR(p, "attenuation must be in (0, 1], got %s", words[k]);
                ok = false;
            }
        m.attenuation = color(v[11], v[12], v[13]);
    }
    Scene *s = p->scene;
    if (ok && ROOM_FOR(p, s->materials, s->material_count, p->material_capacity, "materials")) {
        m.line = p->line;
        s->materials[s->material_count] = m;
        p->material = s->material_count++;
    }
}

static const Command commands[] = {
    {"s", "sphere", "x y z r", 4, 4, parse_sphere},
    {"t", "triangle", "x1 y1 z1 x2 y2 z2 x3 y3 z3", 9, 9, parse_triangle},
    {"p", "plane", "nx ny nz d", 4, 4, parse_plane},
    {"c", "camera", "x y z vx vy vz d iw ih pw ph", 11, 11, parse_camera},
    {"l p", "point light", "x y z r g b [i]", 6, 7, parse_point_light},
    {"l d", "directional light", "vx vy vz r g b [i]", 6, 7, parse_directional_light},
    {"l a", "ambient light", "r g b [i]", 3, 4, parse_ambient_light},
    {"l s", "area light", "x y z nx ny nz ux uy uz len r g b [i]", 13, 14, parse_area_light},
    {"m", "material", "dr dg db sr sg sb p ir ig ib [n ar ag ab]", 10, 14, parse_material},
};

/* Copies the name of number k of a command (from its args string) into buf. */
static const char *arg_name(const char *args, int k, char *buf, size_t size)
{
    const char *s = args;
    for (;;) {
        while (*s == ' ' || *s == '[' || *s == ']')
            s++;
        size_t len = strcspn(s, " []");
        if (len == 0)
            return "?";
        if (k-- == 0) {
            snprintf(buf, size, "%.*s", (int)len, s);
            return buf;
        }
        s += len;
    }
}

/* Checks the count of numbers on a command's line, reads them and calls its handler. */
static void run_command(Parser *p, const Command *c, char *const *words, int n)
{
    /* Noted first, so that a c line with a wrong number is not also told "no camera". */
    if (c->parse == parse_camera)
        p->camera_tried = p->line;
    if (n < c->min || n > c->max) {
        if (c->min == c->max)
            ERROR(p, "%s (%s) takes %d numbers (%s), got %d", c->what, c->name, c->min, c->args, n);
        else
            ERROR(p, "%s (%s) takes %d to %d numbers (%s), got %d", c->what, c->name, c->min,
                  c->max, c->args, n);
        return;
    }
    double v[LEX_MAX_WORDS];
    for (int k = 0; k < n; k++) {
        NumberStatus st = lex_number(words[k], &v[k]);
        if (st == NUMBER_DASH)
            diag_warn(p->diag, p->path, p->line, lex_dash_warning, words[k], v[k]);
        else if (st != NUMBER_OK) {
            char name[16];
            ERROR(p, "%s (%s): %s is '%s', %s", c->what, c->name,
                  arg_name(c->args, k, name, sizeof name), words[k], lex_number_problem(st));
            return;
        }
    }
    c->parse(p, v, n, words);
}

/* Appends candidate folder/name to the list of places tried, for the error message. */
static void note_tried(char *tried, size_t size, const char *candidate)
{
    size_t used = strlen(tried);
    snprintf(tried + used, size - used, "\n    %s", candidate);
}

/* Finds the OBJ file a w line names: beside the scene file, then in each folder above
 * it, then in the working directory. Returns a path to free, or NULL (reported). */
static char *find_mesh(Parser *p, const char *name)
{
    char tried[4096] = "";
    size_t cap = strlen(name) + PATH_MAX + 2;
    char *candidate = malloc(cap);
    char *dir = NULL;
    if (candidate == NULL)
        goto fail;
    if (name[0] != '/') {
        /* The scene's folder, made absolute so that its parents can be walked up. */
        char *scene_dir = strdup(p->path);
        char *slash = scene_dir ? strrchr(scene_dir, '/') : NULL;
        if (scene_dir != NULL) {
            if (slash == NULL)
                strcpy(scene_dir, ".");
            else
                slash[slash == scene_dir] = '\0';
            dir = realpath(scene_dir, NULL);
            free(scene_dir);
        }
        /* "./x.obj" beside the scene is just "x.obj" there. */
        const char *rel = name;
        while (strncmp(rel, "./", 2) == 0)
            rel += 2;
        for (bool more = dir != NULL; more;) {
            bool root = strcmp(dir, "/") == 0;
            snprintf(candidate, cap, "%s/%s", root ? "" : dir, rel);
            if (access(candidate, F_OK) == 0)
                goto found;
            note_tried(tried, sizeof tried, candidate);
            char *up = strrchr(dir, '/');
            more = !root;
            if (up != NULL)
                up[up == dir] = '\0';
        }
    }
    snprintf(candidate, cap, "%s", name);
    if (access(candidate, F_OK) == 0)
        goto found;
    note_tried(tried, sizeof tried, candidate);
    ERROR(p, "cannot find mesh '%s'; looked for it at:%s", name, tried);
    goto fail;
found:
    free(dir);
    return candidate;
fail:
    free(dir);
    free(candidate);
    return NULL;
}

/* Records that the scene reads the file id, so that the image is never written over it;
 * takes id's path. False (reported) when out of memory. */
static bool note_file(Parser *p, FileId id)
{
    Scene *s = p->scene;
    if (!ROOM_FOR(p, s->files, s->file_count, p->file_capacity, "files")) {
        free(id.path);
        return false;
    }
    s->files[s->file_count++] = id;
    return true;
}

/* Tells whether a mesh's n items called what fit beside the scene's have of them;
 * reports it on the w line when they do not. */
static bool mesh_fits(Parser *p, const char *name, int n, int have, const char *what)
{
    if (n <= ARRAY_MAX_ITEMS - have)
        return true;
    ERROR(p, "mesh '%s' has %d %s: with the scene's %d, more than %d, the limit", name, n, what,
          have, ARRAY_MAX_ITEMS);
    return false;
}

/* w path: the triangles of an OBJ mesh, in the current material. */
static void parse_mesh(Parser *p, const char *name)
{
    if (*name == '\0') {
        ERROR(p, "mesh (w) needs the path of an OBJ file");
        return;
    }
    char *path = find_mesh(p, name);
    if (path == NULL)
        return;
    Error err;
    FileId id;
    FILE *f = input_open(path, "OBJ file", false, &id, &err);
    if (f == NULL) {
        ERROR(p, "mesh '%s' %s (%s)", name, err.text, path);
        free(path);
        return;
    }
    Mesh mesh;
    bool loaded = obj_load_stream(&mesh, f, path, p->diag);
    fclose(f);
    bool noted = note_file(p, id);
    if (!noted || !loaded) {
        if (loaded)
            obj_free(&mesh);
        else if (!stop_requested())
            ERROR(p, "mesh '%s' not loaded because of the errors above", name);
        free(path);
        return;
    }
    if (mesh.triangle_count == 0)
        diag_warn(p->diag, path, 0, "mesh has no triangles");
    Scene *s = p->scene;
    /* One message, not one per triangle, when the mesh does not fit. */
    if (!mesh_fits(p, name, mesh.triangle_count, s->triangle_count, "triangles") ||
        !mesh_fits(p, name, mesh.vertex_count, s->vertex_count, "vertices"))
        mesh.triangle_count = 0;
    /* The mesh's vertices follow the scene's, its corners' indices shifted by as many. */
    int first = s->vertex_count, material = current_material(p);
    for (int k = 0; k < mesh.vertex_count && mesh.triangle_count > 0; k++)
        if (!add_vertex(p, mesh.vertices[k]))
            mesh.triangle_count = 0;
    for (int k = 0; k < mesh.triangle_count; k++) {
        const int *t = mesh.triangles[k];
        if (!add_triangle(p, first + t[0], first + t[1], first + t[2], material))
            break;
    }
    s->mesh_count++;
    obj_free(&mesh);
    free(path);
}

/* o name value...: an option; "o convention NAME" is the only one. */
static void parse_option(Parser *p, char *const *words, int n)
{
    if (n == 0) {
        ERROR(p, "option (o) needs a name, e.g. 'o convention fall2016'");
        return;
    }
    if (strcmp(words[0], "convention") != 0) {
        diag_warn(p->diag, p->path, p->line, "unknown option '%s' ignored", words[0]);
        return;
    }
    Convention c;
    if (n != 2 || !convention_from_name(words[1], &c)) {
        ERROR(p, "option 'convention' takes one name: lecture or fall2016 (got '%s')",
              n > 1 ? words[1] : "nothing");
        return;
    }
    if (p->convention_line > 0 && c != p->convention)
        ERROR(p, "a second, different convention; the first is on line %d", p->convention_line);
    p->convention = c;
    p->convention_line = p->line;
}

/* Counts a v or f line. Before any camera, it tells that the file is an OBJ mesh, not a
 * scene: that one message ends the reading, and the warnings about its comments and
 * statements read so far are forgotten, as noise. */
static void note_obj_line(Parser *p)
{
    p->obj_lines++;
    if (p->camera_tried > 0)
        return;
    diag_forget_warnings(p->diag);
    diag_error(p->diag, p->path, 0,
               "this is an OBJ mesh (it has v and f lines), not a scene file; load it from a "
               "scene with the line 'w %s'",
               p->path);
    p->stopped = true;
}

/* Finds the command named by the first word (and, for lights, the second). */
static const Command *find_command(Parser *p, char *const *words, int count, int *used)
{
    *used = 1;
    char name[8];
    if (strcmp(words[0], "l") == 0) {
        if (count < 2) {
            ERROR(p, "light (l) needs a type: p, d, a or s");
            return NULL;
        }
        *used = 2;
        snprintf(name, sizeof name, "l %.4s", words[1]);
    } else {
        snprintf(name, sizeof name, "%.7s", words[0]);
    }
    for (size_t k = 0; k < sizeof commands / sizeof commands[0]; k++)
        if (strcmp(name, commands[k].name) == 0)
            return &commands[k];
    if (*used == 2)
        ERROR(p, "unknown light type '%s' (expected p, d, a or s)", words[1]);
    else if (strcmp(words[0], "v") == 0 || strcmp(words[0], "f") == 0)
        note_obj_line(p);
    else
        diag_warn(p->diag, p->path, p->line, "unknown command '%s' ignored", words[0]);
    return NULL;
}

/* Reads one line of the scene file. */
static void parse_line(Parser *p, char *line)
{
    while (isspace((unsigned char)*line))
        line++;
    if (*line == '\0' || *line == '/')
        return;
    if (line[0] == 'w' && (line[1] == '\0' || isspace((unsigned char)line[1]))) {
        char *name = line + 1, *end = line + strlen(line);
        while (isspace((unsigned char)*name))
            name++;
        while (end > name && isspace((unsigned char)end[-1]))
            *--end = '\0';
        parse_mesh(p, name);
        return;
    }
    Words w;
    lex_split(line, &w);
    if (strcmp(w.word[0], "o") == 0) {
        parse_option(p, w.word + 1, w.count - 1);
        return;
    }
    int used;
    const Command *c = find_command(p, w.word, w.count, &used);
    if (c != NULL)
        run_command(p, c, w.word + used, w.count - used);
}

/* Puts every plane in the lecture's form p.N + d = 0 with |N| = 1. */
static void finish_planes(Scene *s)
{
    for (int k = 0; k < s->plane_count; k++) {
        Plane *pl = &s->planes[k];
        double len = vec3_length(pl->normal);
        /* Slide 45 ("d is measured in direction of normal"): so d stays the distance
         * along the unit normal, whatever length N was given with; p.N = d is
         * p.N + (-d) = 0. */
        pl->normal = vec3_scale(pl->normal, 1.0 / len);
        if (s->convention == CONVENTION_FALL2016)
            pl->d = -pl->d;
    }
}

/* Checks what only the whole file can tell and settles the convention. */
static void finish(Parser *p, const SceneLoadOptions *opts)
{
    Scene *s = p->scene;
    if (p->camera_tried == 0) {
        diag_error(p->diag, p->path, 0,
                   "no camera: a scene needs the line 'c x y z vx vy vz d iw ih pw ph'");
    } else if (p->obj_lines > 0) {
        diag_warn(p->diag, p->path, 0,
                  "v and f lines ignored: they belong in an OBJ file loaded with w");
    }
    s->convention = opts->convention;
    if (p->convention_line > 0) {
        if (!opts->forced)
            s->convention = p->convention;
        else if (p->convention != opts->convention)
            diag_warn(p->diag, p->path, p->convention_line,
                      "'o convention %s' overridden by --convention %s on the command line",
                      convention_name(p->convention), convention_name(opts->convention));
    }
    finish_planes(s);
}

/* Says once when the scene's point or area lights are far too bright for its convention:
 * the fall2016 scenes' lights are in the thousands, made for 1/r^2 falloff, and their planes
 * are p.N = d. Under the lecture's convention the lit parts wash out to white, and a plane
 * stands on the other side of the origin, where it may hide the light: large parts black
 * (scene_light_too_bright tells such a light). */
static void note_convention(const Scene *s, FILE *messages)
{
    const Light *brightest = scene_light_too_bright(s);
    if (brightest == NULL)
        return;
    double most = fmax(brightest->color.r, fmax(brightest->color.g, brightest->color.b));
    /* Formatted by error_set, which makes a file name safe to print, as diagnostics are. */
    Error note;
    error_set(&note,
              "raytra: note: %s:%d: a light of %g is made for the fall2016 convention, which "
              "dims lights by 1/r^2 and reads planes as p.N = d; under the lecture convention "
              "the lit parts wash out to white and planes may stand where they hide the light: "
              "run with --convention fall2016 or add the line 'o convention fall2016' "
              "(docs/scene-format.md)",
              s->path, brightest->line, most);
    fprintf(messages, "%s\n", note.text);
}

/* Returns what kind of image a file starting with head is, or NULL: an image given
 * where the scene belongs, usually the output named first. */
static const char *image_kind(const char *head)
{
    if (strncmp(head, "\x89PNG", 4) == 0)
        return "a PNG image";
    if (strcmp(head, "PF") == 0 || strcmp(head, "Pf") == 0)
        return "a PFM image";
    if (strncmp(head, "v/1", 3) == 0)
        return "an OpenEXR image";
    return NULL;
}

/* Reports the binary byte that ended the reading, naming an image by its kind. */
static void report_binary(Parser *p, const LineReader *reader)
{
    const char *kind = image_kind(p->head);
    if (kind != NULL)
        diag_error(p->diag, p->path, 0,
                   "this is %s, not a scene file (the scene comes first: raytra SCENE "
                   "[OUTPUT])",
                   kind);
    else
        ERROR(p, "%s in the file: this is not a text scene file", lex_binary_byte_name(reader));
}

/* Reads a scene from the open file f, named path in messages and for finding meshes;
 * false after reporting every problem found, or silently when a stop was requested
 * (stop.h). The caller closes f. */
bool scene_load_stream(Scene *scene, FILE *f, const char *path, const SceneLoadOptions *opts)
{
    memset(scene, 0, sizeof *scene);
    Diag diag;
    diag_init(&diag, opts->messages);
    scene->path = strdup(path);
    LineReader *reader = malloc(sizeof *reader);
    Parser p = {.scene = scene, .diag = &diag, .path = path, .material = -1};
    if (reader != NULL && scene->path != NULL) {
        lex_start(reader, f);
        while (!diag_too_many(&diag) && !p.stopped) {
            LineStatus st = lex_next_line(reader);
            p.line = reader->line;
            if (st == LINE_END)
                break;
            if (p.line == 1 && (st == LINE_OK || st == LINE_BINARY))
                snprintf(p.head, sizeof p.head, "%.7s", reader->buf);
            if (stop_requested() || st == LINE_STOPPED) {
                p.stopped = true;
            } else if (st == LINE_IO_ERROR) {
                ERROR(&p, "read error: %s", strerror(errno));
                p.stopped = true;
            } else if (st == LINE_BINARY) {
                /* Whatever was read before is noise: one message says it all. */
                diag_forget_warnings(&diag);
                report_binary(&p, reader);
                p.stopped = true;
            } else if (st == LINE_TOO_LONG) {
                ERROR(&p, "line longer than %d characters", LEX_MAX_LINE);
            } else {
                parse_line(&p, reader->buf);
            }
        }
        if (diag_too_many(&diag))
            diag_give_up(&diag, path);
        else if (!p.stopped && !stop_requested())
            finish(&p, opts);
    } else {
        diag_error(&diag, path, 0, "out of memory");
    }
    free(reader);
    diag_flush(&diag);
    if (diag.errors > 0 || stop_requested()) {
        scene_free(scene);
        return false;
    }
    note_convention(scene, diag.stream);
    return true;
}

/* Reads the scene file at path; false after reporting every problem found. */
bool scene_load(Scene *scene, const char *path, const SceneLoadOptions *opts)
{
    memset(scene, 0, sizeof *scene);
    Diag diag;
    diag_init(&diag, opts->messages);
    Error err;
    FileId id;
    FILE *f = input_open(path, "scene file", true, &id, &err);
    if (f == NULL) {
        /* Ctrl-C while waiting for a pipe's writer is an interruption, not an error. */
        if (!stop_requested())
            diag_error(&diag, path, 0, "%s", err.text);
        return false;
    }
    bool ok = scene_load_stream(scene, f, path, opts);
    fclose(f);
    if (ok) {
        Parser p = {
            .scene = scene, .diag = &diag, .path = path, .file_capacity = scene->file_count};
        ok = note_file(&p, id);
        if (!ok)
            scene_free(scene);
    } else {
        free(id.path);
    }
    return ok;
}
