/* solid.c: checking that glass triangles bound closed solids, by counting how often each edge is used. */
#include "solid.h"

#include <stdlib.h>

#include "refract.h"

/* Orders two points by x, then y, then z. */
static int point_compare(Vec3 a, Vec3 b)
{
    if (a.x != b.x)
        return a.x < b.x ? -1 : 1;
    if (a.y != b.y)
        return a.y < b.y ? -1 : 1;
    if (a.z != b.z)
        return a.z < b.z ? -1 : 1;
    return 0;
}

/* Orders edges (SolidEdge) by material, then corners, so that the uses of one edge come
 * together; a comparison function for qsort. */
int solid_edge_compare(const void *pa, const void *pb)
{
    const SolidEdge *a = pa, *b = pb;
    if (a->material != b->material)
        return a->material < b->material ? -1 : 1;
    int c = point_compare(a->lo, b->lo);
    return c != 0 ? c : point_compare(a->hi, b->hi);
}

/* Returns the edge of material from p to q. */
SolidEdge solid_edge(int material, Vec3 p, Vec3 q)
{
    bool forward = point_compare(p, q) < 0;
    return (SolidEdge){material, forward ? p : q, forward ? q : p, forward};
}

/* starter: todo */
/* Counts the edges of the scene's glass triangles that show they do not bound a closed,
 * consistently wound solid. In a closed mesh every edge is shared by exactly two
 * triangles of the same material, and when both are counterclockwise seen from outside
 * they run along it in opposite directions. The corners must coincide exactly, as they
 * do when both triangles come from the same OBJ vertex. */
SolidCheck solid_check(const Scene *scene)
{
    SolidCheck check = {0};
    long count = 0;
    for (int k = 0; k < scene->triangle_count; k++)
        count += refract_is_glass(&scene->materials[scene->triangles[k].material]) ? 3 : 0;
    if (count == 0)
        return check;
    SolidEdge *edges = malloc((size_t)count * sizeof *edges);
    if (edges == NULL) {
        check.incomplete = true;
        return check;
    }
    long n = 0;
    for (int k = 0; k < scene->triangle_count; k++) {
        int material = scene->triangles[k].material;
        if (!refract_is_glass(&scene->materials[material]))
            continue;
        Triangle t = scene_triangle(scene, k);
        edges[n++] = solid_edge(material, *t.a, *t.b);
        edges[n++] = solid_edge(material, *t.b, *t.c);
        edges[n++] = solid_edge(material, *t.c, *t.a);
    }
    qsort(edges, (size_t)n, sizeof *edges, solid_edge_compare);
    for (long first = 0, next; first < n; first = next) {
        int forward = 0;
        for (next = first; next < n && solid_edge_compare(&edges[first], &edges[next]) == 0; next++)
            forward += edges[next].forward;
        long uses = next - first;
        if (uses == 1)
            check.open++;
        else if (2 * forward != uses)
            check.miswound++;
    }
    free(edges);
    return check;
}

/* Warns on f, once each, when the scene's glass triangles visibly do not bound closed solids. */
void solid_warn(const Scene *scene, FILE *f)
{
    SolidCheck check = solid_check(scene);
    if (check.open > 0)
        fprintf(f,
                "raytra: warning: %s: glass triangles are not closed: %ld edge(s) belong to one "
                "triangle only, and inside and outside are guessed from the side each ray "
                "meets (docs/1.5-refraction.md)\n",
                scene->path, check.open);
    if (check.miswound > 0)
        fprintf(f,
                "raytra: warning: %s: glass triangles are not wound consistently: %ld edge(s) "
                "run the same way in both their triangles, so some faces point inwards "
                "(docs/1.5-refraction.md)\n",
                scene->path, check.miswound);
    if (check.incomplete)
        fprintf(f, "raytra: warning: not enough memory to check that glass meshes are closed\n");
}
