/* color.h: linear RGB radiance and reflectance triples, passed by value. */
#ifndef RAYTRA_COLOR_H
#define RAYTRA_COLOR_H

#include <math.h>
#include <stdbool.h>

typedef struct {
    double r, g, b;
} Color;

/* Returns the colour (r, g, b). */
static inline Color color(double r, double g, double b)
{
    return (Color){r, g, b};
}

/* Returns a + b: light from two sources adds up. */
static inline Color color_add(Color a, Color b)
{
    return color(a.r + b.r, a.g + b.g, a.b + b.b);
}

/* Returns the component-wise product a (.) b: a reflectance filtering light. */
static inline Color color_mul(Color a, Color b)
{
    return color(a.r * b.r, a.g * b.g, a.b * b.b);
}

/* Returns the colour c scaled by s. */
static inline Color color_scale(Color c, double s)
{
    return color(c.r * s, c.g * s, c.b * s);
}

/* Tells whether all three components are zero (nothing to add or reflect). */
static inline bool color_is_black(Color c)
{
    return c.r == 0.0 && c.g == 0.0 && c.b == 0.0;
}

/* Tells whether every component is a finite number. */
static inline bool color_is_finite(Color c)
{
    return isfinite(c.r) && isfinite(c.g) && isfinite(c.b);
}

#endif
