/* dielectric.c: where light goes at a glass surface and how much of it, and what glass absorbs. */
#include "dielectric.h"

#include <math.h>
#include <string.h>

/* Reads the --fresnel option's value, "schlick" or "exact", into model; false for any other. */
bool dielectric_fresnel_from_name(const char *name, FresnelModel *model)
{
    if (strcmp(name, "schlick") == 0)
        *model = FRESNEL_SCHLICK;
    else if (strcmp(name, "exact") == 0)
        *model = FRESNEL_EXACT;
    else
        return false;
    return true;
}

/* starter: todo */
/* Finds the direction t in which the unit direction d goes on through a surface of unit
 * normal n (facing d: d.n < 0), where eta = n_i / n_t is the ratio of the index of the
 * side d comes from to the index of the side it enters. False, with t untouched, when
 * there is no refracted ray: total internal reflection.
 *
 * Snell's law, n_i sin(theta_i) = n_t sin(theta_t), fixes the part of t along the
 * surface: it is eta times the part of d along the surface, d + cos_i n. The part along
 * -n then makes t unit: cos_t = sqrt(1 - sin_t^2), which exists only when sin_t <= 1. */
bool dielectric_refract(Vec3 d, Vec3 n, double eta, Vec3 *t)
{
    double cos_i = -vec3_dot(d, n);
    double sin2_t = eta * eta * fmax(0, 1 - cos_i * cos_i);
    if (sin2_t > 1)
        return false; /* beyond the critical angle: everything is reflected */
    double cos_t = sqrt(1 - sin2_t);
    *t = vec3_add_scaled(vec3_scale(d, eta), n, eta * cos_i - cos_t);
    return true;
}

/* starter: todo */
/* Returns Schlick's approximation of the reflected fraction at a surface between air and
 * a material of index ior, R = R0 + (1 - R0)(1 - cos)^5 with R0 = ((ior - 1)/(ior + 1))^2,
 * the reflectance head-on; cos_air is the cosine of the angle on the air side. */
double dielectric_schlick(double ior, double cos_air)
{
    double r0 = (ior - 1) / (ior + 1);
    r0 *= r0;
    double m = 1 - cos_air;
    return r0 + (1 - r0) * m * m * m * m * m;
}

/* starter: todo */
/* Returns the reflected fraction of unpolarised light at a surface from index n_i to n_t,
 * met at cos_i and left at cos_t (Snell's angles): the mean of the reflectances of the
 * two polarisations, perpendicular (s) and parallel (p) to the plane of incidence,
 *   r_s = (n_i cos_i - n_t cos_t) / (n_i cos_i + n_t cos_t),
 *   r_p = (n_t cos_i - n_i cos_t) / (n_t cos_i + n_i cos_t),   R = (r_s^2 + r_p^2) / 2.
 * Swapping the two sides (and their angles) gives the same R: light is reflected as much
 * on the way in as on the way out. */
double dielectric_fresnel_exact(double n_i, double n_t, double cos_i, double cos_t)
{
    double rs = (n_i * cos_i - n_t * cos_t) / (n_i * cos_i + n_t * cos_t);
    double rp = (n_t * cos_i - n_i * cos_t) / (n_t * cos_i + n_i * cos_t);
    return (rs * rs + rp * rp) / 2;
}

/* Returns the transmitted fraction of unpolarised light at the same surface, from the
 * Fresnel equations' amplitudes t_s = 2 n_i cos_i / (n_i cos_i + n_t cos_t) and
 * t_p = 2 n_i cos_i / (n_t cos_i + n_i cos_t), times the ratio of the power flows
 * across the surface, n_t cos_t / (n_i cos_i). It is worked out on its own, not as
 * 1 - R, so that the tests can check that the two add up to 1. */
double dielectric_transmittance_exact(double n_i, double n_t, double cos_i, double cos_t)
{
    double ts = 2 * n_i * cos_i / (n_i * cos_i + n_t * cos_t);
    double tp = 2 * n_i * cos_i / (n_t * cos_i + n_i * cos_t);
    return n_t * cos_t / (n_i * cos_i) * (ts * ts + tp * tp) / 2;
}

/* Returns the reflected fraction R at a surface between air and a material of index ior,
 * by model, from the cosine of the angle on the air side. R is the same whichever way the
 * light crosses, so the air-side angle says it all; inside, Snell gives the other. */
double dielectric_reflectance(FresnelModel model, double ior, double cos_air)
{
    if (model == FRESNEL_SCHLICK)
        return dielectric_schlick(ior, cos_air);
    double sin2_inside = (1 - cos_air * cos_air) / (ior * ior);
    /* Grazing, or beyond the critical angle (only for ior < 1, where air is the denser
     * side): everything is reflected, and the equations would divide 0 by 0. */
    if (cos_air <= 0 || sin2_inside >= 1)
        return 1;
    return dielectric_fresnel_exact(1, ior, cos_air, sqrt(1 - sin2_inside));
}

/* starter: todo */
/* Returns the fraction of light left after a distance s inside a material of attenuation a,
 * per channel: Beer's law, I(s) = I(0) e^(ln(a) s) = I(0) a^s. Each unit of distance keeps
 * the fraction a; as a <= 1, ln(a) <= 0 and the light can only fade. */
Color dielectric_beer(Color a, double s)
{
    return color(pow(a.r, s), pow(a.g, s), pow(a.b, s));
}
