/* fuzz_obj.c: the libFuzzer harness of the OBJ reader: any bytes, then the mesh's invariants. */
#include <math.h>

#include "fuzz.h"
#include "lex.h"
#include "obj.h"
#include "scene.h"

/* Where diagnostics go: they are formatted (and so tested) but not kept. */
static FILE *messages;

/* Closes the sink for diagnostics at exit: valgrind then finds nothing left behind. */
static void close_messages(void)
{
    fclose(messages);
}

/* Opens the sink for diagnostics once, before the first input. */
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc, (void)argv;
    messages = fopen("/dev/null", "w");
    FUZZ_CHECK(messages != NULL);
    atexit(close_messages);
    return 0;
}

/* Checks what every user of a loaded mesh relies on: indices in range, finite vertices
 * within the number limit, and only triangles with an area. */
static void check_mesh(const Mesh *m)
{
    FUZZ_CHECK(m->vertex_count >= 0 && m->triangle_count >= 0);
    FUZZ_CHECK(m->vertex_count == 0 || m->vertices != NULL);
    FUZZ_CHECK(m->triangle_count == 0 || m->triangles != NULL);
    for (int k = 0; k < m->vertex_count; k++) {
        FUZZ_CHECK(vec3_is_finite(m->vertices[k]));
        FUZZ_CHECK(vec3_max_abs(m->vertices[k]) <= LEX_MAX_NUMBER);
    }
    for (int k = 0; k < m->triangle_count; k++) {
        const int *t = m->triangles[k];
        for (int c = 0; c < 3; c++)
            FUZZ_CHECK(t[c] >= 0 && t[c] < m->vertex_count);
        Vec3 a = m->vertices[t[0]], b = m->vertices[t[1]], c = m->vertices[t[2]];
        FUZZ_CHECK(!scene_triangle_is_degenerate(a, b, c));
        /* Shading normalises the normal: that must give a unit vector. */
        Vec3 n = vec3_normalize(vec3_cross(vec3_sub(b, a), vec3_sub(c, a)));
        FUZZ_CHECK(fabs(vec3_length(n) - 1) < 1e-9);
    }
}

/* Reads data as an OBJ file from memory and checks the mesh it makes, if any. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const char empty[1];
    FILE *f = fmemopen(size > 0 ? (void *)data : (void *)empty, size, "r");
    FUZZ_CHECK(f != NULL);
    Diag diag;
    diag_init(&diag, messages);
    Mesh mesh;
    bool ok = obj_load_stream(&mesh, f, "fuzz.obj", &diag);
    diag_flush(&diag);
    fclose(f);
    FUZZ_CHECK(ok == (diag.errors == 0));
    if (ok) {
        check_mesh(&mesh);
        obj_free(&mesh);
    }
    return 0;
}
