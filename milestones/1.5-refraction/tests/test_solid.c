/* test_solid.c: telling closed, consistently wound glass meshes from open or miswound ones. */
#include <stdio.h>
#include <stdlib.h>

#include "solid.h"
#include "testing.h"

/* Loads the scene text (meshes are looked for from the top of the repository). */
static void load(Scene *scene, const char *text)
{
    char path[512];
    snprintf(path, sizeof path, "%s/scenes/solid-test.scn", TOP_DIR);
    FILE *f = fmemopen((void *)text, strlen(text), "r");
    SceneLoadOptions opts = {.messages = stderr};
    ck_assert(scene_load_stream(scene, f, path, &opts));
    fclose(f);
}

#define CAMERA "c 0 0 10  0 0 -1  1  1 1  4 4\n"
#define GLASS "m 0 0 0  0 0 0  1  0 0 0  1.5\n"
#define MATTE "m 1 1 1  0 0 0  1  0 0 0\n"

START_TEST(closed_meshes_pass)
{
    Scene scene;
    load(&scene, CAMERA GLASS "w meshes/icosphere.obj\nw meshes/prism.obj\n");
    ck_assert_int_eq(scene.triangle_count, 88);
    SolidCheck check = solid_check(&scene);
    ck_assert_int_eq(check.open, 0);
    ck_assert_int_eq(check.miswound, 0);
    scene_free(&scene);
}
END_TEST

START_TEST(a_hole_is_found)
{
    Scene scene;
    load(&scene, CAMERA GLASS "w meshes/icosphere.obj\n");
    /* Taking one triangle out leaves its three edges with one triangle each. */
    scene.triangle_count--;
    SolidCheck check = solid_check(&scene);
    ck_assert_int_eq(check.open, 3);
    ck_assert_int_eq(check.miswound, 0);
    /* A lone glass triangle: three open edges. */
    scene_free(&scene);
    load(&scene, CAMERA GLASS "t 0 0 0  1 0 0  0 1 0\n");
    ck_assert_int_eq(solid_check(&scene).open, 3);
    /* The message names the scene and the count. */
    char *text = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&text, &size);
    solid_warn(&scene, f);
    fclose(f);
    ck_assert_contains(text, "solid-test.scn: glass triangles are not closed: 3 edge(s)");
    free(text);
    scene_free(&scene);
}
END_TEST

START_TEST(a_flipped_face_is_found)
{
    Scene scene;
    load(&scene, CAMERA GLASS "w meshes/icosphere.obj\n");
    /* Turning one triangle round makes each of its edges run the same way as its
     * neighbour's. */
    int *corner = scene.triangles[5].corner, b = corner[1];
    corner[1] = corner[2];
    corner[2] = b;
    SolidCheck check = solid_check(&scene);
    ck_assert_int_eq(check.open, 0);
    ck_assert_int_eq(check.miswound, 3);
    scene_free(&scene);
}
END_TEST

START_TEST(opaque_triangles_are_not_checked)
{
    Scene scene;
    load(&scene, CAMERA MATTE "t 0 0 0  1 0 0  0 1 0\n" GLASS "s 0 0 0 1\n");
    SolidCheck check = solid_check(&scene);
    ck_assert_int_eq(check.open + check.miswound, 0);
    char *text = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&text, &size);
    solid_warn(&scene, f);
    fclose(f);
    ck_assert_str_eq(text, "");
    free(text);
    scene_free(&scene);
}
END_TEST

/* The closed-mesh check's tests. */
static Suite *solid_suite(void)
{
    Suite *s = suite_create("solid");
    TCase *tc = tcase_create("edges");
    tcase_add_test(tc, closed_meshes_pass);
    tcase_add_test(tc, a_hole_is_found);
    tcase_add_test(tc, a_flipped_face_is_found);
    tcase_add_test(tc, opaque_triangles_are_not_checked);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(solid_suite)
