/* dielectric.h: the optics of a glass surface: Snell's law, Fresnel's reflectance, Beer's law. */
#ifndef RAYTRA_DIELECTRIC_H
#define RAYTRA_DIELECTRIC_H

#include <stdbool.h>

#include "color.h"
#include "vec3.h"

/* How the reflected fraction R of a glass surface is computed (--fresnel). */
typedef enum {
    FRESNEL_SCHLICK, /* Schlick's approximation, as the textbook gives it (the default) */
    FRESNEL_EXACT    /* the Fresnel equations for unpolarised light */
} FresnelModel;

bool dielectric_fresnel_from_name(const char *name, FresnelModel *model);
bool dielectric_refract(Vec3 d, Vec3 n, double eta, Vec3 *t);
double dielectric_schlick(double ior, double cos_air);
double dielectric_fresnel_exact(double n_i, double n_t, double cos_i, double cos_t);
double dielectric_transmittance_exact(double n_i, double n_t, double cos_i, double cos_t);
double dielectric_reflectance(FresnelModel model, double ior, double cos_air);
Color dielectric_beer(Color a, double s);

#endif
