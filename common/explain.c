/* explain.c: printing the steps of one pixel's rays, indented by their depth in the ray tree. */
#include "explain.h"

#include <stdarg.h>

/* Prints one line of the tree, indented two blanks per level of depth. */
void explain_print(const Explain *e, int depth, const char *fmt, ...)
{
    fprintf(e->out, "%*s", 2 * depth, "");
    va_list ap;
    va_start(ap, fmt);
    vfprintf(e->out, fmt, ap);
    va_end(ap);
    fputc('\n', e->out);
}

/* Writes v as "(x, y, z)" into buf, with the shortest form that reads back exactly. */
const char *explain_vec3(Vec3 v, char *buf, size_t size)
{
    snprintf(buf, size, "(%.6g, %.6g, %.6g)", v.x, v.y, v.z);
    return buf;
}

/* Prints a ray: its kind, origin and unit direction. */
void explain_print_ray(const Explain *e, int depth, const char *kind, Ray r)
{
    char o[96], d[96];
    explain_print(e, depth, "%s ray from %s along %s", kind, explain_vec3(r.origin, o, sizeof o),
                  explain_vec3(r.dir, d, sizeof d));
}

/* Prints a named colour, "what = (r, g, b)". */
void explain_print_color(const Explain *e, int depth, const char *what, Color c)
{
    explain_print(e, depth, "%s = (%.6g, %.6g, %.6g)", what, c.r, c.g, c.b);
}

/* Writes "file:line" for a line of the scene file into buf, or "" when unknown. */
const char *explain_where(const Explain *e, int line, char *buf, size_t size)
{
    if (line > 0)
        snprintf(buf, size, " (%s:%d)", e->scene->path, line);
    else
        buf[0] = '\0';
    return buf;
}
