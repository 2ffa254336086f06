/* test_hint.c: the warnings for a scene with no light a part uses and for a render of one colour. */
#include "hint.h"
#include "testing.h"

/* A part that shades with point and directional lights, as parts 1.2 to 1.5 do. */
#define SHADING (FEATURE_SPHERES | FEATURE_SHADING | FEATURE_POINT_LIGHTS | FEATURE_DIRECTIONAL_LIGHTS)

/* The scene file text loads into s (a camera of 4 x 2 pixels and one sphere, then text). */
static void load(Scene *s, const char *text)
{
    FILE *f = fopen("t.scn", "w");
    ck_assert(f != NULL);
    fprintf(f, "c 0 0 0 0 0 -1 1 2 1 4 2\nm 1 1 1 0 0 0 1 0 0 0\ns 0 0 -5 1\n%s", text);
    fclose(f);
    FILE *quiet = fopen("/dev/null", "w");
    bool loaded = scene_load(s, "t.scn", &(SceneLoadOptions){.messages = quiet});
    fclose(quiet);
    ck_assert_msg(loaded, "the test's scene does not load");
}

/* What hint_image says of an image of 4 x 2 pixels all (v, v, v) but pixel 0, (first, v, v). */
static char *said_of(const Scene *s, unsigned features, float v, float first)
{
    static char text[512];
    Image img;
    ck_assert(image_init(&img, 4, 2));
    for (int k = 0; k < 8 * 3; k++)
        img.pixels[k] = v;
    img.pixels[0] = first;
    text[0] = '\0';
    FILE *out = fmemopen(text, sizeof text, "w");
    hint_image(s, features, &img, out);
    fclose(out);
    image_free(&img);
    return text;
}

START_TEST(test_no_light_told_before)
{
    Scene s;
    load(&s, "l s 0 5 0 0 -1 0 1 0 0 1 1 1 1\n");
    char text[512] = "";
    FILE *out = fmemopen(text, sizeof text, "w");
    hint_scene(&s, SHADING, "1.4-bvh", out);
    fclose(out);
    ck_assert_str_eq(text, "raytra: warning: t.scn: no light that part 1.4-bvh uses (its area "
                           "lights come in part 1.6): the render will be black\n");
    text[0] = '\0';
    out = fmemopen(text, sizeof text, "w");
    hint_scene(&s, SHADING | FEATURE_AREA_LIGHTS, "1.6-monte-carlo", out);
    fclose(out);
    ck_assert_msg(text[0] == '\0', "part 1.6 uses area lights, yet: %s", text);
    scene_free(&s);
}
END_TEST

START_TEST(test_black_images)
{
    Scene s;
    load(&s, "l s 0 5 0 0 -1 0 1 0 0 1 1 1 1\n");
    ck_assert_str_eq(said_of(&s, SHADING, 0, 0), "raytra: warning: all 8 pixels are black: this "
                                                  "scene has no light that this part uses\n");
    ck_assert_str_eq(said_of(&s, SHADING, 0, 0.5f), "");
    scene_free(&s);
    load(&s, "l p 0 5 0 8000 8000 8000\n");
    ck_assert_msg(strstr(said_of(&s, SHADING, 0, 0), "brighter than 100, as in the Fall 2016 "
                                                     "term, whose planes are p.N = d; try "
                                                     "--convention fall2016") != NULL,
                  "%s", said_of(&s, SHADING, 0, 0));
    scene_free(&s);
    load(&s, "l p 0 5 0 1 1 1\n");
    ck_assert_msg(strstr(said_of(&s, SHADING, 0, 0), "the camera sees nothing lit") != NULL,
                  "%s", said_of(&s, SHADING, 0, 0));
    ck_assert_msg(strstr(said_of(&s, FEATURE_SPHERES, 0, 0), "meet no surface") != NULL, "%s",
                  said_of(&s, FEATURE_SPHERES, 0, 0));
    scene_free(&s);
}
END_TEST

START_TEST(test_one_colour)
{
    Scene s;
    load(&s, "l p 0 5 0 1 1 1\n");
    ck_assert_str_eq(said_of(&s, SHADING, 0.25f, 0.25f),
                     "raytra: warning: all 8 pixels are one colour (0.25, 0.25, 0.25): the "
                     "camera's rays meet nothing, or one surface fills the view; check the "
                     "camera's direction and image plane (c line)\n");
    scene_free(&s);
}
END_TEST

/* The suite of the hints. */
static Suite *hint_suite(void)
{
    Suite *s = suite_create("hint");
    TCase *tc = tcase_create("hint");
    tcase_add_test(tc, test_no_light_told_before);
    tcase_add_test(tc, test_black_images);
    tcase_add_test(tc, test_one_colour);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(hint_suite)
