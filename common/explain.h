/* explain.h: the ray tree of one pixel in plain text, printed as it is traced (--trace-pixel). */
#ifndef RAYTRA_EXPLAIN_H
#define RAYTRA_EXPLAIN_H

#include <stdio.h>

#include "color.h"
#include "ray.h"
#include "scene.h"

/* Where the tree goes, and the scene whose file lines it names. NULL when not tracing. */
typedef struct Explain {
    FILE *out;
    const Scene *scene;
} Explain;

#if defined(__GNUC__)
#define EXPLAIN_PRINTF __attribute__((format(printf, 3, 4)))
#else
#define EXPLAIN_PRINTF
#endif

void explain_print(const Explain *e, int depth, const char *fmt, ...) EXPLAIN_PRINTF;
void explain_print_ray(const Explain *e, int depth, const char *kind, Ray r);
void explain_print_color(const Explain *e, int depth, const char *what, Color c);
const char *explain_vec3(Vec3 v, char *buf, size_t size);

/* The calls the tracing code makes: each does nothing when e is NULL, that is for
 * every pixel but the one --trace-pixel asks about. */
#define explain_line(e, ...) ((e) != NULL ? explain_print((e), __VA_ARGS__) : (void)0)

/* Prints a ray of the given kind ("camera", "shadow", "mirror"), when tracing. */
static inline void explain_ray(const Explain *e, int depth, const char *kind, Ray r)
{
    if (e != NULL)
        explain_print_ray(e, depth, kind, r);
}

/* Prints "what = (r, g, b)", when tracing. */
static inline void explain_color(const Explain *e, int depth, const char *what, Color c)
{
    if (e != NULL)
        explain_print_color(e, depth, what, c);
}
const char *explain_where(const Explain *e, int line, char *buf, size_t size);

#endif
