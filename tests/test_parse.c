/* test_parse.c: the scene parser: every command, both conventions, every diagnostic. */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "scene.h"
#include "stop.h"
#include "testing.h"

/* A camera line that every scene below can start with. */
#define CAMERA "c 0 0 0  0 0 -1  35 35 25  32 24\n"

/* What loading a scene file said and made. */
typedef struct {
    bool ok;
    Scene scene;
    char *messages;
} Loaded;

/* Writes text to the file at path (in the test's scratch folder). */
static void write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    fclose(f);
}

/* Loads the scene file at path with the given load options, capturing the messages. */
static Loaded load_path_with(const char *path, SceneLoadOptions opts)
{
    Loaded l;
    size_t size;
    FILE *messages = open_memstream(&l.messages, &size);
    opts.messages = messages;
    l.ok = scene_load(&l.scene, path, &opts);
    fclose(messages);
    return l;
}

/* Writes text to t.scn and loads it in the lecture convention. */
static Loaded load(const char *text)
{
    write_file("t.scn", text);
    return load_path_with("t.scn", (SceneLoadOptions){0});
}

/* Releases what load returned. */
static void done(Loaded *l)
{
    if (l->ok)
        scene_free(&l->scene);
    free(l->messages);
}

/* Asserts that loading text fails with a message containing expected. */
static void assert_error(const char *text, const char *expected)
{
    Loaded l = load(text);
    ck_assert_msg(!l.ok, "loaded, but expected the error: %s", expected);
    ck_assert_contains(l.messages, expected);
    done(&l);
}

/* Asserts that text loads, with a message containing expected (a warning). */
static void assert_warning(const char *text, const char *expected)
{
    Loaded l = load(text);
    ck_assert_msg(l.ok, "did not load:\n%s", l.messages);
    ck_assert_contains(l.messages, expected);
    done(&l);
}

START_TEST(camera_line)
{
    Loaded l = load("c 1 2 3  0 0 -2  35 36 25  320 240\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    const CameraSpec *c = &l.scene.camera;
    ck_assert_vec3_near(c->eye, vec3(1, 2, 3), 0);
    ck_assert_vec3_near(c->view, vec3(0, 0, -1), 0);
    ck_assert_double_eq(c->focal, 35);
    ck_assert_double_eq(c->width, 36);
    ck_assert_double_eq(c->height, 25);
    ck_assert_int_eq(c->nx, 320);
    ck_assert_int_eq(c->ny, 240);
    ck_assert_str_eq(l.messages, "");
    done(&l);
}
END_TEST

START_TEST(sphere_triangle_and_material)
{
    Loaded l = load(CAMERA "m 0.1 0.2 0.3  0.4 0.5 0.6  70  0.7 0.8 0.9\n"
                           "s 1 2 3 4\n"
                           "t 0 0 0  1 0 0  0 1 0\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.scene.sphere_count, 1);
    ck_assert_vec3_near(l.scene.spheres[0].center, vec3(1, 2, 3), 0);
    ck_assert_double_eq(l.scene.spheres[0].radius, 4);
    ck_assert_int_eq(l.scene.triangle_count, 1);
    ck_assert_int_eq(l.scene.vertex_count, 3);
    Triangle tri = scene_triangle(&l.scene, 0);
    ck_assert_vec3_near(*tri.a, vec3(0, 0, 0), 0);
    ck_assert_vec3_near(*tri.b, vec3(1, 0, 0), 0);
    ck_assert_vec3_near(*tri.c, vec3(0, 1, 0), 0);
    ck_assert_int_eq(l.scene.material_count, 1);
    const Material *m = &l.scene.materials[l.scene.spheres[0].material];
    ck_assert_color_near(m->diffuse, color(0.1, 0.2, 0.3), 0);
    ck_assert_color_near(m->specular, color(0.4, 0.5, 0.6), 0);
    ck_assert_double_eq(m->phong, 70);
    ck_assert_color_near(m->mirror, color(0.7, 0.8, 0.9), 0);
    ck_assert_double_eq(m->ior, 0);
    ck_assert_color_near(m->attenuation, color(1, 1, 1), 0);
    ck_assert_int_eq(l.scene.triangles[0].material, l.scene.spheres[0].material);
    done(&l);
}
END_TEST

START_TEST(material_applies_to_what_follows)
{
    Loaded l = load(CAMERA "m 1 0 0  0 0 0  1  0 0 0\n"
                           "s 0 0 -5 1\n"
                           "m 0 1 0  0 0 0  1  0 0 0\n"
                           "s 0 0 -9 1\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.scene.material_count, 2);
    ck_assert_double_eq(l.scene.materials[l.scene.spheres[0].material].diffuse.r, 1);
    ck_assert_double_eq(l.scene.materials[l.scene.spheres[1].material].diffuse.g, 1);
    done(&l);
}
END_TEST

START_TEST(refraction_numbers)
{
    Loaded l = load(CAMERA "m 0 0 0  0 0 0  1  0 0 0  1.5\n"
                           "s 0 0 -5 1\n"
                           "m 0 0 0  0 0 0  1  0 0 0  1.33  0.9 0.8 0.7\n"
                           "s 0 0 -9 1\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_double_eq(l.scene.materials[0].ior, 1.5);
    ck_assert_color_near(l.scene.materials[0].attenuation, color(1, 1, 1), 0);
    ck_assert_double_eq(l.scene.materials[1].ior, 1.33);
    ck_assert_color_near(l.scene.materials[1].attenuation, color(0.9, 0.8, 0.7), 0);
    done(&l);
    assert_error(CAMERA "m 0 0 0  0 0 0  1  0 0 0  1.5 1\n",
                 "t.scn:2: material (m) takes 10 numbers, 11 with an index of refraction, "
                 "or 14 with an rgb attenuation too; got 12");
    assert_error(CAMERA "m 0 0 0  0 0 0  1  0 0 0  1.5 1 0 1\n",
                 "t.scn:2: attenuation must be in (0, 1], got 0");
    assert_error(CAMERA "m 0 0 0  0 0 0  1  0 0 0  -1\n",
                 "t.scn:2: index of refraction must be positive, got -1");
}
END_TEST

START_TEST(default_material_warns_once)
{
    Loaded l = load(CAMERA "s 0 0 -5 1\ns 0 0 -9 1\nt 0 0 0 1 0 0 0 1 0\n"
                           "m 1 1 1 0 0 0 1 0 0 0\ns 0 0 -3 1\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_contains(l.messages, "t.scn:2: warning: geometry before the first "
                                   "material (m) gets the default material");
    ck_assert_ptr_null(strstr(l.messages, "t.scn:3"));
    ck_assert_int_eq(l.scene.material_count, 2);
    ck_assert_int_eq(l.scene.spheres[0].material, l.scene.spheres[1].material);
    ck_assert_int_eq(l.scene.triangles[0].material, l.scene.spheres[0].material);
    const Material *m = &l.scene.materials[l.scene.spheres[0].material];
    ck_assert_color_near(m->diffuse, scene_default_material.diffuse, 0);
    ck_assert_int_ne(l.scene.spheres[2].material, l.scene.spheres[0].material);
    done(&l);
}
END_TEST

START_TEST(lights_and_their_intensity)
{
    Loaded l = load(CAMERA "l p 1 2 3  0.5 0.25 1\n"
                           "l p 1 2 3  0.5 0.25 1  4\n"
                           "l d 0 -2 0  1 1 1\n"
                           "l a 0.1 0.2 0.3\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.scene.light_count, 3);
    ck_assert_int_eq(l.scene.lights[0].kind, LIGHT_POINT);
    ck_assert_vec3_near(l.scene.lights[0].position, vec3(1, 2, 3), 0);
    ck_assert_color_near(l.scene.lights[0].color, color(0.5, 0.25, 1), 0);
    ck_assert_color_near(l.scene.lights[1].color, color(2, 1, 4), 0);
    ck_assert_int_eq(l.scene.lights[2].kind, LIGHT_DIRECTIONAL);
    ck_assert_vec3_near(l.scene.lights[2].direction, vec3(0, -1, 0), 0);
    ck_assert_color_near(l.scene.ambient, color(0.1, 0.2, 0.3), 0);
    done(&l);
}
END_TEST

START_TEST(two_ambient_lights_add_up)
{
    Loaded l = load(CAMERA "l a 0.1 0.2 0.3\nl a 0.1 0.1 0.1 2\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_color_near(l.scene.ambient, color(0.3, 0.4, 0.5), 1e-15);
    ck_assert_contains(l.messages, "t.scn:3: warning: more than one ambient light");
    done(&l);
}
END_TEST

START_TEST(area_light)
{
    /* u is given slightly tilted towards n; it is made perpendicular, and v = u x n. */
    Loaded l = load(CAMERA "l s 0 10 0  0 -2 0  1 0.5 0  2  0.5 0.5 1\n"
                           "l s 0 10 0  0 -1 0  1 0 0  2  1 1 1 3\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    const Light *a = &l.scene.lights[0];
    ck_assert_int_eq(a->kind, LIGHT_AREA);
    ck_assert_vec3_near(a->position, vec3(0, 10, 0), 0);
    ck_assert_vec3_near(a->direction, vec3(0, -1, 0), 0);
    ck_assert_vec3_near(a->u, vec3(1, 0, 0), 1e-15);
    /* (1,0,0) x (0,-1,0) = (0,0,-1) */
    ck_assert_vec3_near(a->v, vec3(0, 0, -1), 1e-15);
    ck_assert_double_eq(a->size, 2);
    ck_assert_color_near(a->color, color(0.5, 0.5, 1), 0);
    ck_assert_color_near(l.scene.lights[1].color, color(3, 3, 3), 0);
    done(&l);
    assert_error(CAMERA "l s 0 10 0  0 -1 0  0 2 0  2  1 1 1\n",
                 "t.scn:2: area light u direction must not be parallel to its normal");
    assert_error(CAMERA "l s 0 10 0  0 -1 0  1 0 0  0  1 1 1\n",
                 "t.scn:2: area light side length must be positive, got 0");
}
END_TEST

START_TEST(plane_lecture_convention)
{
    /* p.N + d = 0 with N = (0,2,0), d = 4: d is the distance along the unit normal
     * (slide 45 ("d is measured in direction of normal")), so the plane is y = -4
     * (not 2y + 4 = 0), stored as N = (0,1,0), d = 4. */
    Loaded l = load(CAMERA "p 0 2 0 4\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.scene.convention, CONVENTION_LECTURE);
    ck_assert_vec3_near(l.scene.planes[0].normal, vec3(0, 1, 0), 0);
    ck_assert_double_eq(l.scene.planes[0].d, 4);
    ck_assert(!scene_light_falls_off(&l.scene));
    done(&l);
}
END_TEST

START_TEST(plane_fall2016_convention_from_an_o_line)
{
    /* p.N = d with N = (0,2,0) normalised, d = 4: the plane y = 4, which in the
     * lecture's form p.N + d = 0 has N = (0,1,0), d = -4. The o line may come after
     * the plane. */
    Loaded l = load(CAMERA "p 0 2 0 4\no convention fall2016\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.scene.convention, CONVENTION_FALL2016);
    ck_assert_vec3_near(l.scene.planes[0].normal, vec3(0, 1, 0), 0);
    ck_assert_double_eq(l.scene.planes[0].d, -4);
    ck_assert(scene_light_falls_off(&l.scene));
    done(&l);
}
END_TEST

START_TEST(plane_fall2016_convention_from_the_command_line)
{
    write_file("t.scn", CAMERA "p 0 0 -3 6\n");
    Loaded l = load_path_with("t.scn", (SceneLoadOptions){CONVENTION_FALL2016, true, NULL});
    ck_assert_msg(l.ok, "%s", l.messages);
    /* Unit normal (0,0,-1) at distance 6 along it: -z = 6, z = -6; p.N + d = 0 needs
     * d = -6. */
    ck_assert_vec3_near(l.scene.planes[0].normal, vec3(0, 0, -1), 0);
    ck_assert_double_eq(l.scene.planes[0].d, -6);
    done(&l);
}
END_TEST

START_TEST(command_line_convention_wins_over_the_file)
{
    write_file("t.scn", CAMERA "o convention fall2016\n");
    Loaded l = load_path_with("t.scn", (SceneLoadOptions){CONVENTION_LECTURE, true, NULL});
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.scene.convention, CONVENTION_LECTURE);
    ck_assert_contains(l.messages, "t.scn:2: warning: 'o convention fall2016' "
                                   "overridden by --convention lecture");
    done(&l);
    /* Not forced: the default gives way to the file. */
    Loaded m = load_path_with("t.scn", (SceneLoadOptions){CONVENTION_LECTURE, false, NULL});
    ck_assert_int_eq(m.scene.convention, CONVENTION_FALL2016);
    done(&m);
}
END_TEST

START_TEST(options)
{
    assert_warning(CAMERA "o shadows off\n", "t.scn:2: warning: unknown option 'shadows' ignored");
    assert_error(CAMERA "o convention spring\n",
                 "t.scn:2: option 'convention' takes one name: lecture or fall2016");
    assert_error(CAMERA "o\n", "t.scn:2: option (o) needs a name");
    assert_error(CAMERA "o convention lecture\no convention fall2016\n",
                 "t.scn:3: a second, different convention; the first is on line 2");
}
END_TEST

START_TEST(comments_blanks_tabs_and_crlf)
{
    Loaded l = load("/ a comment\r\n"
                    "\r\n"
                    "   \t\r\n"
                    "// another\r\n"
                    "  \tc\t0 0 0 0 0 -1 35 35 25 32 24\r\n"
                    "\ts 0\t0 -5   1.5\r\n"
                    "   / indented comment\n"
                    "s 0 0 -9 2");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.scene.sphere_count, 2);
    ck_assert_double_eq(l.scene.spheres[0].radius, 1.5);
    ck_assert_double_eq(l.scene.spheres[1].radius, 2);
    done(&l);
}
END_TEST

START_TEST(number_spellings)
{
    Loaded l = load(CAMERA "s .5 5. -0.25 1e1\ns +1 1E-1 -2.5e+1 100.\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_vec3_near(l.scene.spheres[0].center, vec3(0.5, 5, -0.25), 0);
    ck_assert_double_eq(l.scene.spheres[0].radius, 10);
    ck_assert_vec3_near(l.scene.spheres[1].center, vec3(1, 0.1, -25), 0);
    done(&l);
}
END_TEST

START_TEST(wrong_number_of_arguments)
{
    assert_error(CAMERA "s 1 2 3\n", "t.scn:2: sphere (s) takes 4 numbers (x y z r), got 3");
    assert_error(CAMERA "s 1 2 3 4 5\n", "t.scn:2: sphere (s) takes 4 numbers (x y z r), got 5");
    assert_error(CAMERA "t 1 2 3 4 5 6 7 8\n", "t.scn:2: triangle (t) takes 9 numbers");
    assert_error(CAMERA "p 0 1 0\n", "t.scn:2: plane (p) takes 4 numbers (nx ny nz d), got 3");
    assert_error("c 0 0 0 0 0 -1 35 35 25 32\n", "t.scn:1: camera (c) takes 11 numbers");
    assert_error(CAMERA "l p 1 2 3 1 1\n",
                 "t.scn:2: point light (l p) takes 6 to 7 numbers (x y z r g b [i]), got 5");
    assert_error(CAMERA "l d 1 2 3 1 1 1 1 1\n", "t.scn:2: directional light (l d) takes 6 to 7");
    assert_error(CAMERA "l a 1 1\n", "t.scn:2: ambient light (l a) takes 3 to 4 numbers");
    assert_error(CAMERA "l s 0 10 0 0 -1 0 1 0 0 2 1 1\n",
                 "t.scn:2: area light (l s) takes 13 to 14");
    assert_error(CAMERA "m 1 1 1 0 0 0 1 0 0\n", "t.scn:2: material (m) takes 10 to 14 numbers");
    assert_error(CAMERA "l\n", "t.scn:2: light (l) needs a type: p, d, a or s");
    assert_error(CAMERA "l q 1 2 3\n", "t.scn:2: unknown light type 'q' (expected p, d, a or s)");
}
END_TEST

START_TEST(bad_numbers)
{
    assert_error(CAMERA "s 0 0 -5 abc\n", "t.scn:2: sphere (s): r is 'abc', not a number");
    assert_error(CAMERA "s 0 1.2.3 -5 1\n", "t.scn:2: sphere (s): y is '1.2.3', not a number");
    assert_error(CAMERA "s 0 0x10 -5 1\n", "t.scn:2: sphere (s): y is '0x10', not a number");
    assert_error(CAMERA "s nan 0 -5 1\n", "t.scn:2: sphere (s): x is 'nan', not a finite number");
    assert_error(CAMERA "s 0 0 -inf 1\n", "t.scn:2: sphere (s): z is '-inf', not a finite number");
    assert_error(CAMERA "s 0 0 1e400 1\n",
                 "t.scn:2: sphere (s): z is '1e400', not a finite number");
    assert_error(CAMERA "s 0 0 -5 1e308\n",
                 "t.scn:2: sphere (s): r is '1e308', too large (the limit is 1e12)");
    assert_error(CAMERA "m 1 1 1 0 0 0 1 0 0 x 1.5\n", "t.scn:2: material (m): ib is 'x'");
    assert_error(CAMERA "m 1 1 1 0 0 0 1 0 0 0 1.5 1 1 y\n", "t.scn:2: material (m): ab is 'y'");
}
END_TEST

START_TEST(bad_values)
{
    assert_error(CAMERA "s 0 0 -5 -1\n", "t.scn:2: sphere radius must be positive, got -1");
    assert_error(CAMERA "s 0 0 -5 0\n", "t.scn:2: sphere radius must be positive, got 0");
    assert_error("c 0 0 0 0 0 -1 0 35 25 32 24\n",
                 "t.scn:1: camera focal length must be positive, got 0");
    assert_error("c 0 0 0 0 0 -1 35 -35 25 32 24\n",
                 "t.scn:1: camera image-plane width must be positive, got -35");
    assert_error("c 0 0 0 0 0 -1 35 35 0 32 24\n",
                 "t.scn:1: camera image-plane height must be positive, got 0");
    assert_error("c 0 0 0 0 0 -1 35 35 25 0 24\n",
                 "t.scn:1: camera pixel width must be a positive whole number, got 0");
    assert_error("c 0 0 0 0 0 -1 35 35 25 32 2.5\n",
                 "t.scn:1: camera pixel height must be a positive whole number, got 2.5");
    assert_error("c 0 0 0 0 0 -1 35 35 25 -32 24\n",
                 "t.scn:1: camera pixel width must be a positive whole number, got -32");
    assert_error("c 0 0 0 0 0 0 35 35 25 32 24\n",
                 "t.scn:1: camera view direction must not be the zero vector");
    assert_error(CAMERA "p 0 0 0 1\n", "t.scn:2: plane normal must not be the zero vector");
    assert_error(CAMERA "l d 0 0 0 1 1 1\n",
                 "t.scn:2: directional light direction must not be the zero vector");
    assert_error(CAMERA "l s 0 10 0  0 0 0  1 0 0  2  1 1 1\n",
                 "t.scn:2: area light normal must not be the zero vector");
    assert_error(CAMERA "l p 0 0 0 1 -1 1\n", "t.scn:2: light colour must not be negative, got -1");
    assert_error(CAMERA "l p 0 0 0 1 1 1 -2\n",
                 "t.scn:2: light intensity must not be negative, got -2");
    assert_error(CAMERA "m 1 1 -1 0 0 0 1 0 0 0\n",
                 "t.scn:2: diffuse colour must not be negative, got -1");
    assert_error(CAMERA "m 1 1 1 0 0 0 -1 0 0 0\n",
                 "t.scn:2: phong exponent must not be negative, got -1");
}
END_TEST

START_TEST(image_too_large_is_refused_before_allocating)
{
    assert_error("c 0 0 0 0 0 -1 35 35 25 100000 100000\n",
                 "t.scn:1: an image of 100000 x 100000 pixels is too large");
    assert_error("c 0 0 0 0 0 -1 35 35 25 1e12 1\n", "t.scn:1: an image of 1e12 x 1 pixels");
    assert_error("c 0 0 0 0 0 -1 35 35 25 20000 20000\n", "is too large");
}
END_TEST

START_TEST(camera_missing_or_twice)
{
    assert_error("s 0 0 -5 1\n", "t.scn: no camera: a scene needs the line 'c x y z vx vy vz "
                                 "d iw ih pw ph'");
    assert_error("/ x\n" CAMERA "/ y\n" CAMERA,
                 "t.scn:4: a second camera (c); the first is on line 2");
    assert_error("", "t.scn: no camera");
}
END_TEST

START_TEST(unknown_commands_warn_once_with_a_count)
{
    Loaded l = load(CAMERA "q 1 2\nsphere 1 2 3 4\nq\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_str_eq(l.messages,
                     "t.scn:2: warning: unknown command 'q' ignored (3 times in all)\n");
    done(&l);
}
END_TEST

START_TEST(degenerate_triangles_warn)
{
    Loaded l = load(CAMERA "t 0 0 0  1 1 1  2 2 2\nt 0 0 0  0 0 0  0 1 0\nt 0 0 0 1 0 0 0 1 0\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.scene.triangle_count, 1);
    ck_assert_contains(l.messages, "t.scn:2: warning: degenerate triangle (no area) "
                                   "skipped (2 times in all)");
    done(&l);
}
END_TEST

START_TEST(several_errors_are_all_reported)
{
    Loaded l = load(CAMERA "s 0 0 -5 -1\ns 0 0\nl p\n");
    ck_assert(!l.ok);
    ck_assert_contains(l.messages, "t.scn:2:");
    ck_assert_contains(l.messages, "t.scn:3:");
    ck_assert_contains(l.messages, "t.scn:4:");
    done(&l);
}
END_TEST

START_TEST(nul_byte_and_long_lines)
{
    FILE *f = fopen("t.scn", "w");
    fputs(CAMERA "s 0 0 -5 1\n", f);
    fputc('\0', f);
    fputs("s 0 0 0 1\n", f);
    fclose(f);
    Loaded l = load_path_with("t.scn", (SceneLoadOptions){0});
    ck_assert(!l.ok);
    ck_assert_contains(l.messages, "t.scn:3: NUL byte in the file");
    done(&l);

    f = fopen("t.scn", "w");
    fputs(CAMERA "/", f);
    for (int k = 0; k < 100000; k++)
        fputc('x', f);
    fputs("\ns 0 0 -5 1\n", f);
    fclose(f);
    l = load_path_with("t.scn", (SceneLoadOptions){0});
    ck_assert(!l.ok);
    ck_assert_contains(l.messages, "t.scn:2: line longer than 65536 characters");
    /* Reading goes on, and the lines after it keep their numbers. */
    ck_assert_contains(l.messages, "t.scn:3: warning: geometry before the first");
    done(&l);
}
END_TEST

START_TEST(a_binary_scene_gives_one_message)
{
    /* Unknown commands before the binary part would be warnings printed after the error;
     * "no camera" would follow it too. One message says it all. */
    FILE *f = fopen("t.scn", "w");
    fputs("GIF89a\r\nIHDR x\n\x01\x02 garbage\nc 0 0 0\n", f);
    fclose(f);
    Loaded l = load_path_with("t.scn", (SceneLoadOptions){0});
    ck_assert(!l.ok);
    ck_assert_str_eq(l.messages,
                     "t.scn:3: control character in the file: this is not a text scene file\n");
    done(&l);
}
END_TEST

START_TEST(an_image_given_as_the_scene_is_named)
{
    /* The first bytes of a PNG, a PFM and an OpenEXR file, each followed by binary data:
     * the usual slip is the output named before the scene. */
    static const struct {
        const char *bytes;
        size_t size;
        const char *kind;
    } images[] = {
        {"\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16, "a PNG image"},
        {"PF\n4 2\n-1.0\n\0\0\x80?", 16, "a PFM image"},
        {"Pf\n4 2\n-1.0\n\0\0\x80?", 16, "a PFM image"},
        {"v/1\x01\x02\0\0\0channels", 16, "an OpenEXR image"},
    };
    for (size_t k = 0; k < sizeof images / sizeof images[0]; k++) {
        FILE *f = fopen("t.scn", "wb");
        fwrite(images[k].bytes, 1, images[k].size, f);
        fclose(f);
        Loaded l = load_path_with("t.scn", (SceneLoadOptions){0});
        ck_assert(!l.ok);
        char expected[256];
        snprintf(expected, sizeof expected,
                 "t.scn: this is %s, not a scene file (the scene comes first: raytra SCENE "
                 "[OUTPUT])\n",
                 images[k].kind);
        ck_assert_str_eq(l.messages, expected);
        done(&l);
    }
}
END_TEST

START_TEST(material_colours_are_reflectances)
{
    assert_error(CAMERA "m 1.5 0 0  0 0 0  1  0 0 0\n",
                 "t.scn:2: diffuse colour must be in [0, 1] (a material reflects at most the "
                 "light it gets), got 1.5; a percentage? write it as a fraction");
    assert_error(CAMERA "m 0 0 0  0 0 200  1  0 0 0\n",
                 "t.scn:2: specular colour must be in [0, 1] (a material reflects at most the "
                 "light it gets), got 200\n");
    assert_error(CAMERA "m 0 0 0  0 0 0  1  0 85 0\n", "t.scn:2: mirror colour must be in [0, 1]");
    /* Exactly 1 is fine, and so are light colours above 1 (slide 66 ("these may be > 1")). */
    Loaded l = load(CAMERA "m 1 1 1  1 1 1  1  1 1 1\nl p 0 0 0  5 5 5\nl a 2 2 2\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    done(&l);
}
END_TEST

START_TEST(errors_beyond_twenty_are_counted_not_shown)
{
    char text[4096] = CAMERA;
    for (int k = 0; k < 40; k++)
        strcat(text, "s 0 0 -5 -1\n");
    Loaded l = load(text);
    ck_assert(!l.ok);
    int lines = 0;
    for (const char *c = l.messages; *c != '\0'; c++)
        lines += *c == '\n';
    /* 20 errors and the line that says reading stopped. */
    ck_assert_int_eq(lines, 21);
    ck_assert_contains(l.messages, "t.scn: too many errors; stopped reading\n");
    done(&l);

    /* The cap holds for any caller of diag_error, not only the loops that check it. */
    Diag d;
    char *buf;
    size_t size;
    FILE *out = open_memstream(&buf, &size);
    diag_init(&d, out);
    for (int k = 0; k < 1000; k++)
        diag_error(&d, "x", k + 1, "error %d", k);
    fclose(out);
    ck_assert_int_eq(d.errors, 1000);
    ck_assert_contains(buf, "x:20: error 19\n");
    ck_assert_msg(strstr(buf, "x:21:") == NULL, "error 21 was shown:\n%s", buf);
    free(buf);
}
END_TEST

START_TEST(a_stop_request_ends_loading_silently)
{
    /* The request arrives while loading (Ctrl-C): the loader stops, says nothing, and
     * returns false; the program then says it was interrupted. */
    write_file("m.obj", "v 0 0 -5\nv 1 0 -5\nv 0 1 -5\nf 1 2 3\n");
    stop_request(SIGINT);
    Loaded l = load(CAMERA "s 0 0 -5 1\nw m.obj\n");
    ck_assert(!l.ok);
    ck_assert_str_eq(l.messages, "");
    done(&l);
    /* An endless line, as from a pipe that never sends a newline, is read until the stop. */
    size_t big = 4 << 20;
    char *endless = malloc(big);
    memset(endless, 'x', big);
    FILE *f = fmemopen(endless, big, "r");
    size_t size;
    char *messages;
    FILE *out = open_memstream(&messages, &size);
    Scene scene;
    ck_assert(!scene_load_stream(&scene, f, "pipe", &(SceneLoadOptions){.messages = out}));
    fclose(out);
    /* It stopped within 64 KiB of the request, not at the end of the 4 MB. */
    ck_assert_int_le(ftell(f), 65536);
    ck_assert_str_eq(messages, "");
    fclose(f);
    free(messages);
    free(endless);
    stop_reset();
}
END_TEST

/* Tells whether this test program runs under AddressSanitizer, which reserves terabytes of
 * address space and so cannot run under a limit of it. */
static bool under_asan(void)
{
#if defined(__SANITIZE_ADDRESS__)
    return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return true;
#endif
#endif
    return false;
}

START_TEST(running_out_of_memory_gives_one_message)
{
    if (under_asan()) {
        fprintf(stderr, "test_parse: AddressSanitizer cannot run under a memory limit: "
                        "out-of-memory test skipped\n");
        return;
    }
    /* A mesh of 2 million vertices (a 2000 x 1000 grid, one triangle) and an address
     * space that holds only part of it (a loop test: two limits): whichever array fails
     * to grow first, one message says so, not one per vertex. */
    FILE *f = fopen("big.obj", "w");
    for (int i = 0; i < 2000; i++)
        for (int j = 0; j < 1000; j++)
            fprintf(f, "v %d %d -50\n", i, j);
    fprintf(f, "f 1 2 1001\n");
    fclose(f);
    write_file("t.scn", CAMERA "w big.obj\n");
    /* The process's address space now, from /proc, plus 40 MB. */
    long pages = 0;
    f = fopen("/proc/self/statm", "r");
    ck_assert_ptr_nonnull(f);
    ck_assert_int_eq(fscanf(f, "%ld", &pages), 1);
    fclose(f);
    rlim_t extra = _i == 0 ? 40u << 20 : 85u << 20;
    rlim_t limit = (rlim_t)pages * (rlim_t)sysconf(_SC_PAGESIZE) + extra;
    struct rlimit rl = {limit, limit};
    ck_assert_int_eq(setrlimit(RLIMIT_AS, &rl), 0);
    Loaded l = load_path_with("t.scn", (SceneLoadOptions){0});
    ck_assert(!l.ok);
    ck_assert_contains(l.messages, "out of memory for ");
    int lines = 0;
    for (const char *c = l.messages; *c != '\0'; c++)
        lines += *c == '\n';
    ck_assert_msg(lines <= 2, "%d lines:\n%s", lines, l.messages);
    /* The vertex arrays double from 2^20 vertices (25 MB) to 2^21 (50 MB). With 40 MB more
     * the OBJ reader's fails; with 85 MB the mesh loads and the scene's copy fails, at
     * the first of a million vertices left to add. */
    ck_assert_contains(l.messages, _i == 0 ? "big.obj:" : "t.scn:2: out of memory for ");
    done(&l);
}
END_TEST

START_TEST(files_read_are_recorded)
{
    write_file("m.obj", "v 0 0 -5\nv 1 0 -5\nv 0 1 -5\nf 1 2 3\n");
    Loaded l = load(CAMERA "w m.obj\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.scene.file_count, 2);
    ck_assert(input_same_file(&l.scene.files[0], "m.obj"));
    ck_assert(input_same_file(&l.scene.files[1], "./t.scn"));
    ck_assert(!input_same_file(&l.scene.files[1], "m.obj"));
    done(&l);
}
END_TEST

START_TEST(devices_and_pipes_are_refused_as_meshes)
{
    assert_error(CAMERA "w /dev/zero\n",
                 "t.scn:2: mesh '/dev/zero' is a device, not an OBJ file (/dev/zero)");
    ck_assert_int_eq(mkfifo("p.obj", 0600), 0);
    assert_error(CAMERA "w p.obj\n", "mesh 'p.obj' is a named pipe, not an OBJ file");
    Loaded l = load_path_with("/dev/zero", (SceneLoadOptions){0});
    ck_assert(!l.ok);
    ck_assert_str_eq(l.messages, "/dev/zero: is a device, not a scene file\n");
    done(&l);
}
END_TEST

START_TEST(missing_scene_file_and_directory)
{
    Loaded l = load_path_with("no-such.scn", (SceneLoadOptions){0});
    ck_assert(!l.ok);
    ck_assert_str_eq(l.messages,
                     "no-such.scn: cannot open scene file: No such file or directory\n");
    done(&l);
    mkdir("folder.scn", 0777);
    l = load_path_with("folder.scn", (SceneLoadOptions){0});
    ck_assert(!l.ok);
    ck_assert_str_eq(l.messages, "folder.scn: is a directory, not a scene file\n");
    done(&l);
}
END_TEST

START_TEST(an_obj_file_given_as_a_scene)
{
    /* One message, and nothing else: neither the comments and statements before the first
     * v line, nor what follows it (an OBJ's s, l and o lines are no scene commands). */
    const char *objs[] = {"# an OBJ\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
                          ("# Blender\nmtllib m.mtl\no Cube\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                           "vn 0 0 1\nusemtl M\ns off\nf 1//1 2//1 3//1\nl 1 2\n# end\n"),
                          "f 1 2 3\nv 0 0 0\n"};
    for (size_t k = 0; k < sizeof objs / sizeof *objs; k++) {
        Loaded l = load(objs[k]);
        ck_assert(!l.ok);
        ck_assert_str_eq(l.messages,
                         "t.scn: this is an OBJ mesh (it has v and f lines), not a scene file; "
                         "load it from a scene with the line 'w t.scn'\n");
        done(&l);
    }
    /* After a camera, v and f lines are a scene's stray lines: a warning. */
    assert_warning(CAMERA "v 0 0 0\n", "t.scn: warning: v and f lines ignored");
}
END_TEST

START_TEST(lights_that_do_not_fit_the_convention_are_noted)
{
    /* Lights in the thousands without falloff: the fall2016 convention is named once,
     * with the brightest light's line, whichever light it is. */
    const char *bright = CAMERA "l p 0 10 0  8000 8000 8000\nl s 0 9 0  0 -1 0  1 0 0  2  "
                                "1 1 1 6000\nl p 0 5 0  0.5 0.5 0.5\n";
    Loaded l = load(bright);
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_str_eq(l.messages,
                     "raytra: note: t.scn:2: a light of 8000 is made for the fall2016 "
                     "convention, which dims lights by 1/r^2 and reads planes as p.N = d; under "
                     "the lecture convention the lit parts wash out to white and planes may "
                     "stand where they hide the light: run with --convention fall2016 or add "
                     "the line 'o convention fall2016' (docs/scene-format.md)\n");
    done(&l);
    /* An area light alone, its intensity given as i: the same. */
    l = load(CAMERA "l s 0 9 0  0 -1 0  1 0 0  2  1 1 1 6000\n");
    ck_assert_contains(l.messages, "t.scn:2: a light of 6000 is made for the fall2016 convention");
    done(&l);
    /* The same lights with falloff, from the file or the command line: nothing to say. */
    l = load(CAMERA "o convention fall2016\nl p 0 10 0  8000 8000 8000\n");
    ck_assert_msg(l.ok && l.messages[0] == '\0', "%s", l.messages);
    done(&l);
    write_file("t.scn", bright);
    l = load_path_with("t.scn", (SceneLoadOptions){CONVENTION_FALL2016, true, NULL});
    ck_assert_msg(l.ok && l.messages[0] == '\0', "%s", l.messages);
    done(&l);
    /* Nothing to say: lights near 1, or of 99, without falloff; lights near 1 or of 100
     * with it; a directional light of any brightness (it never falls off); ambient light. */
    const char *fine[] = {CAMERA "l p 0 10 0  1 1 1\nl s 0 9 0  0 -1 0  1 0 0  2  1 1 1\n",
                          CAMERA "l p 0 10 0  99 99 99\n",
                          CAMERA "o convention fall2016\nl p 0 10 0  100 100 100\n",
                          CAMERA "o convention fall2016\nl p 0 10 0  1 1 1\nl p 0 9 0  50 1 1\n",
                          CAMERA "l d 0 -1 0  6000 6000 6000\n",
                          CAMERA "o convention fall2016\nl d 0 -1 0  1 1 1\nl a 0.1 0.1 0.1\n"};
    for (size_t k = 0; k < sizeof fine / sizeof *fine; k++) {
        l = load(fine[k]);
        ck_assert_msg(l.ok && l.messages[0] == '\0', "scene %zu: %s", k, l.messages);
        done(&l);
    }
    /* A scene that fails says what is wrong, and no more. */
    l = load(CAMERA "l p 0 10 0  8000 8000 8000\ns 0 0 0 -1\n");
    ck_assert(!l.ok);
    ck_assert_ptr_null(strstr(l.messages, "note"));
    done(&l);
}
END_TEST

START_TEST(mesh_beside_the_scene)
{
    mkdir("sub", 0777);
    write_file("sub/quad.obj", "# a unit square as one quad\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                               "vn 0 0 1\ng square\nusemtl none\nf 1 2 3 4\n");
    write_file("sub/s.scn", CAMERA "m 0 1 0 0 0 0 1 0 0 0\nw quad.obj\n");
    Loaded l = load_path_with("sub/s.scn", (SceneLoadOptions){0});
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.scene.triangle_count, 2);
    ck_assert_int_eq(l.scene.mesh_count, 1);
    /* The quad 1 2 3 4 becomes the fan 1 2 3, 1 3 4, whose triangles share the
     * quad's four vertices. */
    ck_assert_int_eq(l.scene.vertex_count, 4);
    const int *corner = l.scene.triangles[1].corner;
    ck_assert(corner[0] == 0 && corner[1] == 2 && corner[2] == 3);
    Triangle tri = scene_triangle(&l.scene, 1);
    ck_assert_vec3_near(*tri.b, vec3(1, 1, 0), 0);
    ck_assert_vec3_near(*tri.c, vec3(0, 1, 0), 0);
    ck_assert_double_eq(l.scene.materials[l.scene.triangles[0].material].diffuse.g, 1);
    ck_assert_str_eq(l.messages, "");
    done(&l);
}
END_TEST

START_TEST(mesh_in_a_parent_folder_or_the_working_directory)
{
    mkdir("a", 0777);
    mkdir("a/b", 0777);
    write_file("a/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    /* A path relative to a parent folder, as in "w legoScene/Lego_Head.obj". */
    write_file("a/b/s.scn", CAMERA "w tri.obj\nw b/../tri.obj\n");
    Loaded l = load_path_with("a/b/s.scn", (SceneLoadOptions){0});
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.scene.triangle_count, 2);
    /* Each mesh brings its own vertices: the second's corners are counted after the first's. */
    ck_assert_int_eq(l.scene.vertex_count, 6);
    ck_assert_int_eq(l.scene.triangles[1].corner[0], 3);
    ck_assert_int_eq(l.scene.triangles[1].corner[2], 5);
    done(&l);

    /* A scene elsewhere whose mesh is only in the working directory. */
    write_file("cwd.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\n");
    char dir[] = "/tmp/raytra-test-XXXXXX";
    ck_assert_ptr_nonnull(mkdtemp(dir));
    char scene[64];
    snprintf(scene, sizeof scene, "%s/s.scn", dir);
    write_file(scene, CAMERA "w cwd.obj\n");
    l = load_path_with(scene, (SceneLoadOptions){0});
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_int_eq(l.scene.triangle_count, 2);
    done(&l);
    unlink(scene);
    rmdir(dir);
}
END_TEST

START_TEST(missing_mesh_names_every_place_tried)
{
    char cwd[4096];
    ck_assert_ptr_nonnull(getcwd(cwd, sizeof cwd));
    mkdir("x", 0777);
    write_file("x/s.scn", CAMERA "w  pieces.obj  \n");
    Loaded l = load_path_with("x/s.scn", (SceneLoadOptions){0});
    ck_assert(!l.ok);
    char expected[2 * sizeof cwd + 256];
    snprintf(expected, sizeof expected,
             "x/s.scn:2: cannot find mesh 'pieces.obj'; looked for it at:\n    %s/x/pieces.obj\n"
             "    %s/pieces.obj\n",
             cwd, cwd);
    ck_assert_msg(strncmp(l.messages, expected, strlen(expected)) == 0, "got:\n%s", l.messages);
    ck_assert_contains(l.messages, "\n    /pieces.obj\n    pieces.obj\n");
    done(&l);
}
END_TEST

START_TEST(mesh_problems)
{
    mkdir("dir.obj", 0777);
    assert_error(CAMERA "w dir.obj\n", "t.scn:2: mesh 'dir.obj' is a directory");
    assert_error(CAMERA "w\n", "t.scn:2: mesh (w) needs the path of an OBJ file");
    write_file("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
    Loaded l = load(CAMERA "w bad.obj\n");
    ck_assert(!l.ok);
    ck_assert_contains(l.messages, "bad.obj:4: face vertex index 9 is out of range "
                                   "(the mesh has 3 vertices)");
    ck_assert_contains(l.messages, "t.scn:2: mesh 'bad.obj' not loaded");
    done(&l);
    write_file("empty.obj", "# nothing\n");
    assert_warning(CAMERA "w empty.obj\n", "empty.obj: warning: mesh has no triangles");
}
END_TEST

START_TEST(features)
{
    Loaded l = load(CAMERA "m 1 1 1 0 0 0 1 0.5 0 0\ns 0 0 -5 1\np 0 1 0 0\nl d 0 -1 0 1 1 1\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    unsigned f = scene_features(&l.scene);
    ck_assert_uint_eq(f, FEATURE_SPHERES | FEATURE_PLANES | FEATURE_DIRECTIONAL_LIGHTS |
                             FEATURE_SHADING | FEATURE_MIRRORS);
    done(&l);
}
END_TEST

START_TEST(sizes_and_directions_too_small_to_compute_with)
{
    assert_error(CAMERA "s 0 0 -5 1e-13\n",
                 "t.scn:2: sphere radius 1e-13 is too small (the limit is 1e-12)");
    assert_error("c 0 0 0 0 0 -1 35 35 6.2e-125 32 24\n",
                 "t.scn:1: camera image-plane height 6.2e-125 is too small");
    assert_error("c 0 0 0 0 0 -1 1e-200 35 25 32 24\n", "camera focal length 1e-200 is too small");
    assert_error("c 0 0 0 1e-160 0 0 35 35 25 32 24\n",
                 "t.scn:1: camera view direction is too short to have a direction");
    assert_error(CAMERA "p 1e-13 0 0 1\n", "t.scn:2: plane normal is too short");
    /* Smaller still, its length squared is 0: it is simply zero. */
    assert_error(CAMERA "p 1e-200 0 0 1\n", "t.scn:2: plane normal must not be the zero vector");
    Loaded l = load(CAMERA "s 0 0 -5 1e-12\np 1e-12 0 0 1\n");
    ck_assert_msg(l.ok, "%s", l.messages);
    ck_assert_double_eq(l.scene.planes[0].normal.x, 1);
    done(&l);
}
END_TEST

START_TEST(triangles_too_small_for_a_normal_are_degenerate)
{
    /* The first is skipped; the second, a million times larger, is kept: one warning. */
    assert_warning(CAMERA "t 0 0 0  1e-13 0 0  0 1e-13 0\nt 0 0 0  1e-6 0 0  0 1e-6 0\n",
                   "t.scn:2: warning: degenerate triangle (no area) skipped\n");
}
END_TEST

START_TEST(scene_from_a_stream)
{
    /* The stream is named "dir/x.scn": messages say so, and meshes are looked for in dir. */
    ck_assert_int_eq(mkdir("dir", 0700), 0);
    write_file("dir/m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    static const char text[] = CAMERA "w m.obj\nq\n";
    FILE *f = fmemopen((void *)text, sizeof text - 1, "r");
    char *messages;
    size_t size;
    SceneLoadOptions opts = {.messages = open_memstream(&messages, &size)};
    Scene scene;
    ck_assert(scene_load_stream(&scene, f, "dir/x.scn", &opts));
    fclose(f);
    fclose(opts.messages);
    ck_assert_int_eq(scene.triangle_count, 1);
    ck_assert_str_eq(scene.path, "dir/x.scn");
    ck_assert_contains(messages, "dir/x.scn:3: warning: unknown command 'q' ignored");
    scene_free(&scene);
    free(messages);
}
END_TEST

START_TEST(a_camera_line_in_error_is_not_also_missing)
{
    Loaded l = load("c 0 0 0  0 0 -1  35 35 25  32\nc 0 0 0  0 0 -1  35 abc 25  32 24\n");
    ck_assert(!l.ok);
    ck_assert_contains(l.messages, "t.scn:1: camera (c) takes 11 numbers");
    ck_assert_contains(l.messages, "t.scn:2: camera (c): iw is 'abc', not a number");
    ck_assert_msg(strstr(l.messages, "no camera") == NULL, "%s", l.messages);
    done(&l);
}
END_TEST

/* The parser's tests. */
static Suite *parse_suite(void)
{
    Suite *s = suite_create("parse");
    TCase *cmd = tcase_create("commands");
    tcase_add_test(cmd, camera_line);
    tcase_add_test(cmd, sphere_triangle_and_material);
    tcase_add_test(cmd, material_applies_to_what_follows);
    tcase_add_test(cmd, refraction_numbers);
    tcase_add_test(cmd, default_material_warns_once);
    tcase_add_test(cmd, lights_and_their_intensity);
    tcase_add_test(cmd, two_ambient_lights_add_up);
    tcase_add_test(cmd, area_light);
    tcase_add_test(cmd, comments_blanks_tabs_and_crlf);
    tcase_add_test(cmd, number_spellings);
    tcase_add_test(cmd, features);
    suite_add_tcase(s, cmd);
    TCase *conv = tcase_create("conventions");
    tcase_add_test(conv, plane_lecture_convention);
    tcase_add_test(conv, plane_fall2016_convention_from_an_o_line);
    tcase_add_test(conv, plane_fall2016_convention_from_the_command_line);
    tcase_add_test(conv, command_line_convention_wins_over_the_file);
    tcase_add_test(conv, options);
    tcase_add_test(conv, lights_that_do_not_fit_the_convention_are_noted);
    suite_add_tcase(s, conv);
    TCase *diag = tcase_create("diagnostics");
    tcase_add_test(diag, wrong_number_of_arguments);
    tcase_add_test(diag, bad_numbers);
    tcase_add_test(diag, bad_values);
    tcase_add_test(diag, image_too_large_is_refused_before_allocating);
    tcase_add_test(diag, camera_missing_or_twice);
    tcase_add_test(diag, unknown_commands_warn_once_with_a_count);
    tcase_add_test(diag, degenerate_triangles_warn);
    tcase_add_test(diag, several_errors_are_all_reported);
    tcase_add_test(diag, nul_byte_and_long_lines);
    tcase_add_test(diag, a_binary_scene_gives_one_message);
    tcase_add_test(diag, an_image_given_as_the_scene_is_named);
    tcase_add_test(diag, material_colours_are_reflectances);
    tcase_add_test(diag, errors_beyond_twenty_are_counted_not_shown);
    tcase_add_test(diag, a_stop_request_ends_loading_silently);
    tcase_add_loop_test(diag, running_out_of_memory_gives_one_message, 0, 2);
    tcase_add_test(diag, files_read_are_recorded);
    tcase_add_test(diag, devices_and_pipes_are_refused_as_meshes);
    tcase_add_test(diag, missing_scene_file_and_directory);
    tcase_add_test(diag, an_obj_file_given_as_a_scene);
    tcase_add_test(diag, sizes_and_directions_too_small_to_compute_with);
    tcase_add_test(diag, triangles_too_small_for_a_normal_are_degenerate);
    tcase_add_test(diag, scene_from_a_stream);
    tcase_add_test(diag, a_camera_line_in_error_is_not_also_missing);
    suite_add_tcase(s, diag);
    TCase *mesh = tcase_create("meshes");
    tcase_add_test(mesh, mesh_beside_the_scene);
    tcase_add_test(mesh, mesh_in_a_parent_folder_or_the_working_directory);
    tcase_add_test(mesh, missing_mesh_names_every_place_tried);
    tcase_add_test(mesh, mesh_problems);
    suite_add_tcase(s, mesh);
    return s;
}

TEST_MAIN(parse_suite)
