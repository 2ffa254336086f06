/* unpadded.c: wrong: a triangle's box is its corners' least and greatest coordinates, not
 * grown by box_pad, so the slab test, which rounds otherwise than the triangle's own test,
 * may shave off a ray through an edge or a corner. */
Box box_of_triangle(const Triangle *tri)
{
    return box_add_point(box_add_point((Box){*tri->a, *tri->a}, *tri->b), *tri->c);
}
