/* debugview.c: mapping what a camera ray finds first to a colour, view by view. */
#include "debugview.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Each view: its name, and what a part must have to draw it (none: every part with a
 * probe draws it). */
static const struct {
    const char *name;
    const char *needs;
} views[] = {
    [VIEW_NORMAL] = {"normal", NULL},
    [VIEW_DEPTH] = {"depth", NULL},
    [VIEW_ID] = {"id", NULL},
    [VIEW_MATERIAL] = {"material", NULL},
    [VIEW_LIGHT_COUNT] = {"light-count", "lights to count"},
    [VIEW_BOX_TESTS] = {"box-tests", "bounding boxes"},
};

/* Reads a view's name; false when there is no such view. */
bool debugview_from_name(const char *name, ViewKind *kind)
{
    for (int k = VIEW_NORMAL; k <= VIEW_BOX_TESTS; k++)
        if (strcmp(name, views[k].name) == 0) {
            *kind = (ViewKind)k;
            return true;
        }
    return false;
}

/* Tells whether a part that draws the views of the bits views (1 << VIEW_...) beyond
 * those every part draws can draw view kind; when not, *why says what it lacks. */
bool debugview_drawn_by(ViewKind kind, unsigned views_drawn, const char **why)
{
    if (views[kind].needs == NULL || (views_drawn & (1u << kind)))
        return true;
    *why = views[kind].needs;
    return false;
}

/* Returns the names of the views, for messages. */
const char *debugview_names(void)
{
    return "normal, depth, id, material, light-count, box-tests";
}

/* Returns a colour for surface number id, the same every run: the bits of a hash,
 * kept away from black so that every surface shows. */
static Color id_color(int id)
{
    unsigned h = (unsigned)id * 2654435761u;
    h ^= h >> 15;
    return color(0.2 + 0.8 * (h & 255) / 255.0, 0.2 + 0.8 * ((h >> 8) & 255) / 255.0,
                 0.2 + 0.8 * ((h >> 16) & 255) / 255.0);
}

/* Returns the colour of a pixel in view kind. Depth, light counts and box tests are
 * stored as numbers in red and scaled by debugview_finish, once the largest is known. */
Color debugview_color(ViewKind kind, const Probe *p)
{
    if (kind == VIEW_BOX_TESTS)
        return color((double)p->tests, 0, 0);
    if (!p->hit)
        return kind == VIEW_DEPTH ? color(-1, 0, 0) : color(0, 0, 0);
    switch (kind) {
    case VIEW_NORMAL: /* each component from [-1, 1] to [0, 1] */
        return color(0.5 * (p->normal.x + 1), 0.5 * (p->normal.y + 1), 0.5 * (p->normal.z + 1));
    case VIEW_DEPTH: return color(p->t, 0, 0);
    case VIEW_ID: return id_color(p->surface);
    case VIEW_MATERIAL: return p->kd;
    case VIEW_LIGHT_COUNT: return color(p->lights_visible, 0, 0);
    default: return color(0, 0, 0);
    }
}

/* Returns a heat colour for v in [0, 1]: black, red, yellow, white. */
static Color heat(double v)
{
    v = fmin(fmax(v, 0), 1);
    return color(fmin(3 * v, 1), fmin(fmax(3 * v - 1, 0), 1), fmin(fmax(3 * v - 2, 0), 1));
}

/* Orders two floats, for qsort. */
static int compare_floats(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* Returns the median of the depths of the pixels that hit something; 0 if none do. */
static double median_depth(const Image *img)
{
    long n = (long)img->width * img->height, hits = 0;
    float *t = malloc((size_t)n * sizeof *t);
    if (t == NULL)
        return 0;
    for (long k = 0; k < n; k++)
        if (img->pixels[3 * k] >= 0)
            t[hits++] = img->pixels[3 * k];
    qsort(t, (size_t)hits, sizeof *t, compare_floats);
    double median = hits > 0 ? t[hits / 2] : 0;
    free(t);
    return median;
}

/* Scales the views that store numbers into colours, and prints the scale. Depth is
 * grey t_half / (t_half + t), t_half the median depth: white at the eye, half grey at
 * the median, fading to black far away, so that a floor to the horizon does not
 * wash out everything nearer. */
void debugview_finish(ViewKind kind, Image *img, int light_count, FILE *messages)
{
    if (kind != VIEW_DEPTH && kind != VIEW_LIGHT_COUNT && kind != VIEW_BOX_TESTS)
        return;
    long n = (long)img->width * img->height;
    double scale = 0;
    if (kind == VIEW_DEPTH)
        scale = median_depth(img);
    else if (kind == VIEW_LIGHT_COUNT)
        scale = light_count;
    else
        for (long k = 0; k < n; k++)
            scale = fmax(scale, img->pixels[3 * k]);
    for (long k = 0; k < n; k++) {
        float *p = img->pixels + 3 * k;
        double v = p[0];
        Color c;
        if (kind == VIEW_DEPTH)
            c = v < 0 ? color(0, 0, 0) : color_scale(color(1, 1, 1), scale / (scale + v));
        else
            c = heat(scale > 0 ? v / scale : 0);
        p[0] = (float)c.r, p[1] = (float)c.g, p[2] = (float)c.b;
    }
    if (kind == VIEW_DEPTH)
        fprintf(messages,
                "raytra: view depth: white at t = 0, half grey at t = %g (the median), "
                "black where nothing is hit\n",
                scale);
    else if (scale == 0)
        fprintf(messages, "raytra: view %s: black everywhere: %s\n", views[kind].name,
                kind == VIEW_LIGHT_COUNT
                    ? "the scene has no point, directional or area light to count"
                    : "no camera ray was tested against a box or a primitive");
    else
        fprintf(messages, "raytra: view %s: black 0, then red, yellow, white %g %s\n",
                views[kind].name, scale,
                kind == VIEW_LIGHT_COUNT ? "lights (all the scene's)"
                                         : "tests of boxes and primitives (the most of any pixel)");
}
