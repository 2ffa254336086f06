/* minmax-unpadded.c: held out, like unpadded written otherwise: a triangle's box from the
 * least and greatest of its corners, axis by axis, never grown. */
Box box_of_triangle(const Triangle *tri)
{
    Vec3 lo = vec3_min(vec3_min(*tri->a, *tri->b), *tri->c);
    Vec3 hi = vec3_max(vec3_max(*tri->a, *tri->b), *tri->c);
    return (Box){lo, hi};
}
