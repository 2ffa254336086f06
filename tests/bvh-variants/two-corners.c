/* two-corners.c: wrong: a triangle's box is made of two of its corners, not all three, so
 * the traversal never reaches the part of the triangle that sticks out of it: holes. */
Box box_of_triangle(const Triangle *tri)
{
    return box_pad(box_add_point((Box){*tri->a, *tri->a}, *tri->b));
}
