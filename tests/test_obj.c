/* test_obj.c: the OBJ loader: faces, fans, index forms, relative indices and every error. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "obj.h"
#include "testing.h"

/* What loading an OBJ file said and made. */
typedef struct {
    bool ok;
    Mesh mesh;
    char *messages;
    Diag diag;
} Loaded;

/* Loads the OBJ file at path, capturing the messages. */
static Loaded load_path(const char *path)
{
    Loaded l;
    size_t size;
    FILE *messages = open_memstream(&l.messages, &size);
    diag_init(&l.diag, messages);
    l.ok = obj_load(&l.mesh, path, &l.diag);
    diag_flush(&l.diag);
    fclose(messages);
    return l;
}

/* Writes text to m.obj and loads it. */
static Loaded load(const char *text)
{
    FILE *f = fopen("m.obj", "w");
    fputs(text, f);
    fclose(f);
    return load_path("m.obj");
}

/* Releases what load returned. */
static void done(Loaded *l)
{
    obj_free(&l->mesh);
    free(l->messages);
}

/* Asserts that loading text fails with a message containing expected. */
static void assert_error(const char *text, const char *expected)
{
    Loaded l = load(text);
    ck_assert_msg(!l.ok, "loaded, but expected: %s", expected);
    ck_assert_contains(l.messages, expected);
    done(&l);
}

/* Asserts that triangle k of the mesh has the given 0-based corners. */
static void assert_triangle(const Mesh *m, int k, int a, int b, int c)
{
    ck_assert_int_lt(k, m->triangle_count);
    ck_assert_int_eq(m->triangles[k][0], a);
    ck_assert_int_eq(m->triangles[k][1], b);
    ck_assert_int_eq(m->triangles[k][2], c);
}

#define SQUARE "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"

START_TEST(triangles)
{
    Loaded l = load("# comment\n" SQUARE "f 1 2 3\nf 1 3 4\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.mesh.vertex_count, 4);
    ck_assert_vec3_near(l.mesh.vertices[2], vec3(1, 1, 0), 0);
    ck_assert_int_eq(l.mesh.triangle_count, 2);
    assert_triangle(&l.mesh, 0, 0, 1, 2);
    assert_triangle(&l.mesh, 1, 0, 2, 3);
    ck_assert_str_eq(l.messages, "");
    done(&l);
}
END_TEST

START_TEST(polygons_become_fans)
{
    Loaded l = load(SQUARE "v 0.5 1.5 0\nf 1 2 3 5 4\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.mesh.triangle_count, 3);
    assert_triangle(&l.mesh, 0, 0, 1, 2);
    assert_triangle(&l.mesh, 1, 0, 2, 4);
    assert_triangle(&l.mesh, 2, 0, 4, 3);
    done(&l);
}
END_TEST

START_TEST(index_forms)
{
    Loaded l =
        load(SQUARE "vt 0 0\nvn 0 0 1\nf 1/1 2/1 3/1\nf 1//1 3//1 4//1\nf 1/1/1 2/1/1 4/1/1\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.mesh.triangle_count, 3);
    assert_triangle(&l.mesh, 1, 0, 2, 3);
    assert_triangle(&l.mesh, 2, 0, 1, 3);
    done(&l);
}
END_TEST

START_TEST(relative_indices)
{
    /* -1 is the latest vertex read: after four vertices, -4 -3 -2 is 1 2 3. */
    Loaded l = load(SQUARE "f -4 -3 -2\nv 2 2 0\nf -1 -2 -3\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    assert_triangle(&l.mesh, 0, 0, 1, 2);
    assert_triangle(&l.mesh, 1, 4, 3, 2);
    done(&l);
}
END_TEST

START_TEST(ignored_statements_and_extra_numbers)
{
    Loaded l = load("mtllib x.mtl\no thing\ng group\ns 1\nusemtl red\n"
                    "v 0 0 0 1 0 0\nv 1 0 0 0.5 0.5 0.5\nv 0 1 0 1.0\n"
                    "vn 0 0 1\nvt 0 0\nl 1 2\nf 1 2 3\r\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.mesh.vertex_count, 3);
    ck_assert_vec3_near(l.mesh.vertices[1], vec3(1, 0, 0), 0);
    ck_assert_int_eq(l.mesh.triangle_count, 1);
    ck_assert_str_eq(l.messages, "");
    done(&l);
}
END_TEST

START_TEST(faces_may_come_before_their_vertices)
{
    Loaded l = load("f 1 2 3\n"
                    "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.mesh.triangle_count, 1);
    done(&l);
}
END_TEST

START_TEST(errors)
{
    assert_error(SQUARE "f 1 2 0\n",
                 "m.obj:5: face vertex index 0 is out of range (OBJ indices start at 1)");
    assert_error(SQUARE "f 1 2 5\n",
                 "m.obj:5: face vertex index 5 is out of range (the mesh has 4 vertices)");
    assert_error(SQUARE "f 1 2 -5\n", "m.obj:5: face vertex index -5 is out of range "
                                      "(4 vertices so far)");
    assert_error(SQUARE "f 1 2\n", "m.obj:5: face (f) needs at least 3 vertices, got 2");
    assert_error(SQUARE "f 1 2 x\n", "m.obj:5: malformed face vertex 'x'");
    assert_error(SQUARE "f 1 2 3/a\n", "m.obj:5: malformed face vertex '3/a'");
    assert_error(SQUARE "f 1 2 3.5\n", "m.obj:5: malformed face vertex '3.5'");
    /* Indices too large for any mesh, or for a long, are out of range, not malformed. */
    assert_error(SQUARE "f 1 2 2147483648\n", "m.obj:5: face vertex index 2147483648 is out "
                                               "of range (a mesh has at most 50000000 vertices)");
    assert_error(SQUARE "f 1 2 99999999999999999999999/1\n",
                 "m.obj:5: face vertex index 99999999999999999999999/1 is out of range");
    assert_error(SQUARE "f 1 2 -99999999999999999999999\n",
                 "m.obj:5: face vertex index -99999999999999999999999 is out of range");
    assert_error("v 0 0\n", "m.obj:1: vertex (v) needs 3 numbers x y z, got 2");
    assert_error("v 0 nan 0\n", "m.obj:1: vertex coordinate 'nan' is not a finite number");
}
END_TEST

START_TEST(comments_after_statements)
{
    /* Exporters write "f 1 2 3 # quad half" and "v 1 2 3 #top": the comment is dropped. */
    Loaded l = load("v 0 0 0 # origin\nv 1 0 0#x\nv 0 1 0\t# y\nf 1 2 3 # the face\n"
                    "# f 3 2 1\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.mesh.vertex_count, 3);
    ck_assert_int_eq(l.mesh.triangle_count, 1);
    assert_triangle(&l.mesh, 0, 0, 1, 2);
    ck_assert_str_eq(l.messages, "");
    done(&l);
}
END_TEST

START_TEST(binary_file)
{
    static const char bytes[] = "v 0 0 0\n\0\1\2\nf 1 1 1\n";
    FILE *f = fopen("m.obj", "w");
    fwrite(bytes, 1, sizeof bytes - 1, f);
    fclose(f);
    Loaded l = load_path("m.obj");
    ck_assert(!l.ok);
    ck_assert_str_eq(l.messages, "m.obj:2: NUL byte in the file: this is not a text OBJ file\n");
    done(&l);
}
END_TEST

START_TEST(degenerate_faces_are_skipped)
{
    Loaded l = load(SQUARE "v 2 0 0\nf 1 2 5\nf 1 1 2\nf 1 2 3\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.mesh.triangle_count, 1);
    ck_assert_str_eq(l.messages,
                     "m.obj:6: warning: degenerate triangle (no area) skipped (2 times in all)\n");
    done(&l);
}
END_TEST

START_TEST(missing_file)
{
    Loaded l = load_path("absent.obj");
    ck_assert(!l.ok);
    ck_assert_str_eq(l.messages, "absent.obj: cannot open OBJ file: No such file or directory\n");
    done(&l);
}
END_TEST

START_TEST(mesh_from_a_stream)
{
    static const char text[] = SQUARE "f 1 2 3 4\nf 1 2 9\n";
    FILE *f = fmemopen((void *)text, sizeof text - 1, "r");
    char *messages;
    size_t size;
    Diag diag;
    diag_init(&diag, open_memstream(&messages, &size));
    Mesh mesh;
    ck_assert(!obj_load_stream(&mesh, f, "memory.obj", &diag));
    fclose(f);
    fclose(diag.stream);
    ck_assert_int_eq(mesh.triangle_count, 0);
    ck_assert_str_eq(
        messages, "memory.obj:6: face vertex index 9 is out of range (the mesh has 4 vertices)\n");
    free(messages);
}
END_TEST

START_TEST(faces_too_small_for_a_normal_are_skipped)
{
    Loaded l = load("v 0 0 0\nv 1e-13 0 0\nv 0 1e-13 0\nf 1 2 3\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.mesh.triangle_count, 0);
    ck_assert_contains(l.messages, "m.obj:4: warning: degenerate triangle (no area) skipped");
    done(&l);
}
END_TEST

/* The OBJ loader's tests. */
static Suite *obj_suite(void)
{
    Suite *s = suite_create("obj");
    TCase *tc = tcase_create("obj");
    tcase_add_test(tc, triangles);
    tcase_add_test(tc, polygons_become_fans);
    tcase_add_test(tc, index_forms);
    tcase_add_test(tc, relative_indices);
    tcase_add_test(tc, ignored_statements_and_extra_numbers);
    tcase_add_test(tc, faces_may_come_before_their_vertices);
    tcase_add_test(tc, errors);
    tcase_add_test(tc, comments_after_statements);
    tcase_add_test(tc, binary_file);
    tcase_add_test(tc, degenerate_faces_are_skipped);
    tcase_add_test(tc, missing_file);
    tcase_add_test(tc, mesh_from_a_stream);
    tcase_add_test(tc, faces_too_small_for_a_normal_are_skipped);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(obj_suite)
