/* two-corners-ac.c: held out, like book/mistakes' bvh-loses-hits written otherwise: a
 * triangle's box of its first and last corners, padded, without the middle one. */
Box box_of_triangle(const Triangle *tri)
{
    return box_pad(box_union((Box){*tri->a, *tri->a}, (Box){*tri->c, *tri->c}));
}
