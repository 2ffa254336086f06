/* obj.c: the OBJ subset meshes need: v and f lines; everything else is skipped. */
#include "obj.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "array.h"
#include "lex.h"
#include "input.h"
#include "scene.h"
#include "stop.h"

/* How often long loops look for a stop request (stop.h). */
#define POLL_EVERY 65536

/* A triangle as read, before its indices are checked against the vertex count. */
typedef struct {
    long index[3]; /* 1-based; relative (negative) indices already resolved */
    int line;
} RawFace;

typedef struct {
    const char *path;
    Diag *diag;
    Mesh *mesh;
    int vertex_capacity;
    RawFace *faces;
    int face_count, face_capacity;
} ObjReader;

/* Makes room for item count of *items, called what; false (reported, once, naming the real
 * cause) when memory runs out or the limit is reached. */
static bool room_for(ObjReader *r, int line, void *items, int *capacity, int count,
                     size_t size, const char *what)
{
    if (array_grow(items, capacity, count, size))
        return true;
    if (count >= ARRAY_MAX_ITEMS)
        diag_error(r->diag, r->path, line, "more than %d %s: the limit of a mesh",
                   ARRAY_MAX_ITEMS, what);
    else
        diag_error(r->diag, r->path, line, "out of memory for %d %s", count + 1, what);
    return false;
}

/* Handles "v x y z [more]": numbers after the third (w, or a vertex colour) are ignored. */
static bool read_vertex(ObjReader *r, int line, const Words *w)
{
    if (w->count < 4) {
        diag_error(r->diag, r->path, line, "vertex (v) needs 3 numbers x y z, got %d",
                   w->count - 1);
        return true;
    }
    double xyz[3];
    for (int k = 0; k < 3; k++) {
        NumberStatus s = lex_number(w->word[k + 1], &xyz[k]);
        if (s == NUMBER_DASH)
            diag_warn(r->diag, r->path, line, lex_dash_warning, w->word[k + 1], xyz[k]);
        else if (s != NUMBER_OK) {
            diag_error(r->diag, r->path, line, "vertex coordinate '%s' is %s", w->word[k + 1],
                       lex_number_problem(s));
            return true;
        }
    }
    Mesh *m = r->mesh;
    if (!room_for(r, line, &m->vertices, &r->vertex_capacity, m->vertex_count, sizeof(Vec3),
                  "vertices"))
        return false;
    m->vertices[m->vertex_count++] = vec3(xyz[0], xyz[1], xyz[2]);
    return true;
}

/* Skips an optional signed integer at *p. */
static void skip_integer(const char **p)
{
    if (**p == '-' || **p == '+')
        (*p)++;
    while (isdigit((unsigned char)**p))
        (*p)++;
}

typedef enum { CORNER_OK, CORNER_MALFORMED, CORNER_TOO_LARGE } CornerStatus;

/* Reads the vertex index of a face corner "v", "v/t", "v//n" or "v/t/n". */
static CornerStatus parse_corner(const char *word, long *vertex)
{
    char *end;
    errno = 0;
    *vertex = strtol(word, &end, 10);
    if (end == word)
        return CORNER_MALFORMED;
    /* Far beyond any mesh: no more than ARRAY_MAX_ITEMS vertices are ever read. */
    bool too_large = errno == ERANGE || *vertex > ARRAY_MAX_ITEMS || *vertex < -ARRAY_MAX_ITEMS;
    /* The texture and normal indices are not used, but must be well formed. */
    const char *p = end;
    if (*p == '/') {
        p++;
        skip_integer(&p);
        if (*p == '/') {
            p++;
            skip_integer(&p);
        }
    }
    if (*p != '\0')
        return CORNER_MALFORMED;
    return too_large ? CORNER_TOO_LARGE : CORNER_OK;
}

/* Handles "f c1 c2 c3 ...": a polygon, split into a fan of triangles from its first corner. */
static bool read_face(ObjReader *r, int line, const Words *w)
{
    int corners = w->count - 1;
    if (corners < 3) {
        diag_error(r->diag, r->path, line, "face (f) needs at least 3 vertices, got %d", corners);
        return true;
    }
    if (corners > LEX_MAX_WORDS - 1) {
        diag_error(r->diag, r->path, line, "face (f) has %d vertices; at most %d are supported",
                   corners, LEX_MAX_WORDS - 1);
        return true;
    }
    long index[LEX_MAX_WORDS];
    for (int k = 0; k < corners; k++) {
        const char *word = w->word[k + 1];
        long v;
        CornerStatus cs = parse_corner(word, &v);
        if (cs == CORNER_MALFORMED) {
            diag_error(r->diag, r->path, line, "malformed face vertex '%s'", word);
            return true;
        }
        if (cs == CORNER_TOO_LARGE) {
            diag_error(r->diag, r->path, line,
                       "face vertex index %s is out of range (a mesh has at most %d vertices)",
                       word, ARRAY_MAX_ITEMS);
            return true;
        }
        if (v == 0) {
            diag_error(r->diag, r->path, line,
                       "face vertex index 0 is out of range (OBJ indices start at 1)");
            return true;
        }
        /* A negative index counts back from the latest vertex: -1 is the last one read. */
        if (v < 0 && -v > r->mesh->vertex_count) {
            diag_error(r->diag, r->path, line,
                       "face vertex index %ld is out of range (%d vertices so far)", v,
                       r->mesh->vertex_count);
            return true;
        }
        index[k] = v < 0 ? r->mesh->vertex_count + 1 + v : v;
    }
    for (int k = 1; k + 1 < corners; k++) {
        if (!room_for(r, line, &r->faces, &r->face_capacity, r->face_count, sizeof(RawFace),
                      "triangles"))
            return false;
        r->faces[r->face_count++] = (RawFace){{index[0], index[k], index[k + 1]}, line};
    }
    return true;
}

/* Checks every face against the final vertex count and keeps the non-degenerate ones. */
static bool resolve_faces(ObjReader *r)
{
    Mesh *m = r->mesh;
    if (r->face_count > 0) {
        m->triangles = malloc((size_t)r->face_count * sizeof *m->triangles);
        if (m->triangles == NULL) {
            diag_error(r->diag, r->path, 0, "out of memory for %d triangles", r->face_count);
            return false;
        }
    }
    for (int f = 0; f < r->face_count && !diag_too_many(r->diag); f++) {
        if (f % POLL_EVERY == 0 && stop_requested())
            return false;
        const RawFace *face = &r->faces[f];
        bool in_range = true;
        for (int k = 0; k < 3; k++)
            if (face->index[k] > m->vertex_count) {
                diag_error(r->diag, r->path, face->line,
                           "face vertex index %ld is out of range (the mesh has %d vertices)",
                           face->index[k], m->vertex_count);
                in_range = false;
                break;
            }
        if (!in_range)
            continue;
        int *t = m->triangles[m->triangle_count];
        for (int k = 0; k < 3; k++)
            t[k] = (int)(face->index[k] - 1);
        if (scene_triangle_is_degenerate(m->vertices[t[0]], m->vertices[t[1]], m->vertices[t[2]])) {
            diag_warn(r->diag, r->path, face->line, "degenerate triangle (no area) skipped");
            continue;
        }
        m->triangle_count++;
    }
    return true;
}

/* Reads an OBJ mesh from the open file f into mesh; problems go to diag as path's,
 * with the OBJ's own line numbers. False when there were any, or (silently) when a stop
 * was requested (stop.h). The caller closes f. */
bool obj_load_stream(Mesh *mesh, FILE *f, const char *path, Diag *diag)
{
    memset(mesh, 0, sizeof *mesh);
    ObjReader r = {.path = path, .diag = diag, .mesh = mesh};
    LineReader *lr = malloc(sizeof *lr);
    bool ok = lr != NULL;
    int errors_before = diag->errors;
    if (ok)
        lex_start(lr, f);
    while (ok && !diag_too_many(diag)) {
        LineStatus st = lex_next_line(lr);
        if (st == LINE_END)
            break;
        if (st == LINE_STOPPED || (lr->line % POLL_EVERY == 0 && stop_requested())) {
            ok = false;
            break;
        }
        if (st == LINE_IO_ERROR) {
            diag_error(diag, path, lr->line + 1, "read error: %s", strerror(errno));
            break;
        }
        if (st == LINE_BINARY) {
            diag_error(diag, path, lr->line, "%s in the file: this is not a text OBJ file",
                       lex_binary_byte_name(lr));
            break;
        }
        if (st == LINE_TOO_LONG) {
            diag_error(diag, path, lr->line, "line longer than %d characters", LEX_MAX_LINE);
            continue;
        }
        /* A comment runs from # to the end of the line, after a statement too. */
        char *comment = strchr(lr->buf, '#');
        if (comment != NULL)
            *comment = '\0';
        Words w;
        lex_split(lr->buf, &w);
        if (w.count == 0)
            continue;
        if (strcmp(w.word[0], "v") == 0)
            ok = read_vertex(&r, lr->line, &w);
        else if (strcmp(w.word[0], "f") == 0)
            ok = read_face(&r, lr->line, &w);
        /* vn, vt, g, o, s, usemtl, mtllib and the rest carry nothing raytra draws. */
    }
    if (ok && diag->errors == errors_before)
        ok = resolve_faces(&r);
    free(r.faces);
    free(lr);
    if (!ok || diag->errors != errors_before) {
        obj_free(mesh);
        return false;
    }
    return true;
}

/* Reads the OBJ file at path into mesh; problems go to diag with the OBJ's own line numbers. */
bool obj_load(Mesh *mesh, const char *path, Diag *diag)
{
    memset(mesh, 0, sizeof *mesh);
    Error err;
    FileId id;
    FILE *f = input_open(path, "OBJ file", false, &id, &err);
    if (f == NULL) {
        diag_error(diag, path, 0, "%s", err.text);
        return false;
    }
    free(id.path);
    bool ok = obj_load_stream(mesh, f, path, diag);
    fclose(f);
    return ok;
}

/* Releases the mesh's arrays. */
void obj_free(Mesh *mesh)
{
    free(mesh->vertices);
    free(mesh->triangles);
    memset(mesh, 0, sizeof *mesh);
}
