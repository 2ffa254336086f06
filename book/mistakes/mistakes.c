/* mistakes.c: the usual mistakes of the course, each a wrapper around one of part 1.3's
 * functions, compiled alone (-DWRAP_name) and linked in its place with the linker's --wrap,
 * only for docs/mistakes.md. */
#include <math.h>

#include "box.h"
#include "camera.h"
#include "image.h"
#include "secondary.h"
#include "shade.h"
#include "sphere.h"
#include "world.h"

#ifdef WRAP_camera_ray
Ray __real_camera_ray(const Camera *cam, double x, double y);
Ray __wrap_camera_ray(const Camera *cam, double x, double y);

/* Upside down: row j taken from the top, where the lecture counts it from the bottom. */
Ray __wrap_camera_ray(const Camera *cam, double x, double y)
{
    return __real_camera_ray(cam, x, cam->ny - y);
}
#endif

#ifdef WRAP_sphere_intersect
bool __real_sphere_intersect(const Sphere *s, Ray r, double tmin, double tmax, double *t);
bool __wrap_sphere_intersect(const Sphere *s, Ray r, double tmin, double tmax, double *t);

/* No closest hit: every sphere test looks as far as infinity, so the last sphere hit
 * in the file's order wins, not the nearest. */
bool __wrap_sphere_intersect(const Sphere *s, Ray r, double tmin, double tmax, double *t)
{
    (void)tmax;
    return __real_sphere_intersect(s, r, tmin, INFINITY, t);
}
#endif

#ifdef WRAP_world_hit
bool __real_world_hit(const Scene *scene, Ray r, double tmin, double tmax, Hit *hit);
bool __wrap_world_hit(const Scene *scene, Ray r, double tmin, double tmax, Hit *hit);

/* Unnormalised normals: a sphere's normal taken as p - O, not divided by the radius. */
bool __wrap_world_hit(const Scene *scene, Ray r, double tmin, double tmax, Hit *hit)
{
    if (!__real_world_hit(scene, r, tmin, tmax, hit))
        return false;
    if (hit->kind == SURFACE_SPHERE)
        hit->normal = vec3_scale(hit->normal, scene->spheres[hit->index].radius);
    return true;
}
#endif

#ifdef WRAP_shade_direct_radiance
Color __wrap_shade_direct_radiance(const Scene *scene, const Hit *hit, Ray r, bool two_sided);

/* Specular behind the surface: the highlight added even for a light behind it, where
 * n.l < 0 but n.h may still be positive. Part 1.2's sum, with that mistake. */
Color __wrap_shade_direct_radiance(const Scene *scene, const Hit *hit, Ray r, bool two_sided)
{
    const Material *m = shade_material(scene, hit, two_sided);
    Vec3 n = shade_normal(hit), v = vec3_neg(r.dir);
    Color sum = color(0, 0, 0);
    for (int k = 0; k < scene->light_count; k++) {
        Incident in = light_incident(&scene->lights[k], hit->point, scene_light_falls_off(scene));
        BlinnPhong terms = shade_blinn_phong_terms(m, n, v, &in);
        if (vec3_dot(n, in.dir) <= 0) {
            double n_dot_h = fmax(0, vec3_dot(n, vec3_normalize(vec3_add(in.dir, v))));
            terms.specular =
                color_mul(in.radiance, color_scale(m->specular, pow(n_dot_h, m->phong)));
        }
        sum = color_add(sum, color_add(terms.diffuse, terms.specular));
    }
    return sum;
}
#endif

#ifdef WRAP_image_encode_8bit
int __wrap_image_encode_8bit(double linear, PngEncoding encoding);

/* No clamp before encoding: a value above 1 wraps round the 8 bits, bright turns dark. */
int __wrap_image_encode_8bit(double linear, PngEncoding encoding)
{
    double v = fmax(linear, 0);
    if (encoding == PNG_ENCODING_SRGB)
        v = image_srgb_encode(v);
    return (int)(v * 255 + 0.5) & 255;
}
#endif

#ifdef WRAP_secondary_reflect
Vec3 __real_secondary_reflect(Vec3 d, Vec3 n);
Vec3 __wrap_secondary_reflect(Vec3 d, Vec3 n);

/* The mirror direction turned round: r = 2 (d.n) n - d points into the surface. */
Vec3 __wrap_secondary_reflect(Vec3 d, Vec3 n)
{
    return vec3_neg(__real_secondary_reflect(d, n));
}

#endif

#ifdef WRAP_box_of_triangle
Box __wrap_box_of_triangle(const Triangle *tri);

/* A BVH that loses hits: a triangle's box made of two of its corners, not all three, so
 * the traversal never reaches the part of the triangle that sticks out of it. */
Box __wrap_box_of_triangle(const Triangle *tri)
{
    return box_add_point(box_add_point(box_empty(), *tri->a), *tri->b);
}
#endif
