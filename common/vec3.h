/* vec3.h: three-component vectors for points and directions, passed by value. */
#ifndef RAYTRA_VEC3_H
#define RAYTRA_VEC3_H

#include <math.h>
#include <stdbool.h>

typedef struct {
    double x, y, z;
} Vec3;

/* Returns the vector (x, y, z). */
static inline Vec3 vec3(double x, double y, double z)
{
    return (Vec3){x, y, z};
}

/* Returns a + b. */
static inline Vec3 vec3_add(Vec3 a, Vec3 b)
{
    return vec3(a.x + b.x, a.y + b.y, a.z + b.z);
}

/* Returns a - b. */
static inline Vec3 vec3_sub(Vec3 a, Vec3 b)
{
    return vec3(a.x - b.x, a.y - b.y, a.z - b.z);
}

/* Returns the vector a scaled by s. */
static inline Vec3 vec3_scale(Vec3 a, double s)
{
    return vec3(a.x * s, a.y * s, a.z * s);
}

/* Returns a + s b, the step along b that rays and offsets take. */
static inline Vec3 vec3_add_scaled(Vec3 a, Vec3 b, double s)
{
    return vec3(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z);
}

/* Returns -a. */
static inline Vec3 vec3_neg(Vec3 a)
{
    return vec3(-a.x, -a.y, -a.z);
}

/* Returns the dot product a . b. */
static inline double vec3_dot(Vec3 a, Vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/* Returns the cross product a x b (right-handed). */
static inline Vec3 vec3_cross(Vec3 a, Vec3 b)
{
    return vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

/* Returns |a|^2. */
static inline double vec3_length_squared(Vec3 a)
{
    return vec3_dot(a, a);
}

/* Returns the Euclidean length |a|. */
static inline double vec3_length(Vec3 a)
{
    return sqrt(vec3_dot(a, a));
}

/* Returns a / |a|; the caller makes sure a is not the zero vector. */
static inline Vec3 vec3_normalize(Vec3 a)
{
    return vec3_scale(a, 1.0 / vec3_length(a));
}

/* Returns the largest absolute component, max(|x|, |y|, |z|). */
static inline double vec3_max_abs(Vec3 a)
{
    return fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
}

/* Returns the smaller of each component of a and b (b's where they do not compare). */
static inline Vec3 vec3_min(Vec3 a, Vec3 b)
{
    return vec3(a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z);
}

/* Returns the larger of each component of a and b (b's where they do not compare). */
static inline Vec3 vec3_max(Vec3 a, Vec3 b)
{
    return vec3(a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z);
}

/* Returns component axis of a: x, y, z for 0, 1, 2. */
static inline double vec3_axis(Vec3 a, int axis)
{
    return axis == 0 ? a.x : axis == 1 ? a.y : a.z;
}

/* Tells whether every component is a finite number (no NaN, no infinity). */
static inline bool vec3_is_finite(Vec3 a)
{
    return isfinite(a.x) && isfinite(a.y) && isfinite(a.z);
}

#endif
