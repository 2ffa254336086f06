/* surfaces.c: the brute-force Surfaces of part 1.3: every ray is tested against every surface. */
#include "surfaces.h"

#include "world.h"

/* Finds the closest hit with part 1.2's world_hit. */
static bool brute_force_hit(const void *data, Ray r, double tmin, double tmax, Hit *hit)
{
    return world_hit(data, r, tmin, tmax, hit);
}

/* Tells whether anything lies on the ray: any hit will do, so the closest one does too. */
static bool brute_force_blocked(const void *data, Ray r, double tmin, double tmax)
{
    Hit hit;
    return world_hit(data, r, tmin, tmax, &hit);
}

/* Returns how many surfaces the search for the closest hit tests: every one. */
static long brute_force_tests(const void *data, Ray r)
{
    const Scene *scene = data;
    (void)r;
    return scene->sphere_count + scene->plane_count + scene->triangle_count;
}

/* Returns the Surfaces that answer by testing every surface of scene. */
Surfaces surfaces_brute_force(const Scene *scene)
{
    return (Surfaces){.hit = brute_force_hit,
                      .blocked = brute_force_blocked,
                      .tests = brute_force_tests,
                      .data = scene};
}
