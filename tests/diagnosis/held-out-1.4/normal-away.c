/* normal-away.c: held out, a mistake the gallery does not have: box_hit_face is right but
 * gives the face's normal pointing away from the ray's origin. No known mistake is it. */
bool box_hit_face(Box b, Ray r, double tmin, double tmax, double *t, Vec3 *normal)
{
    double t0 = -INFINITY, t1 = INFINITY;
    int axis0 = 0, axis1 = 0;
    for (int a = 0; a < 3; a++) {
        double near = t0, far = t1;
        box_slab(vec3_axis(b.lo, a), vec3_axis(b.hi, a), vec3_axis(r.origin, a),
                 1 / vec3_axis(r.dir, a), &near, &far);
        if (near > t0)
            t0 = near, axis0 = a;
        if (far < t1)
            t1 = far, axis1 = a;
    }
    bool enters = t0 > tmin && t0 < tmax;
    int axis = enters ? axis0 : axis1;
    *t = enters ? t0 : t1;
    if (!(t0 <= t1 && *t > tmin && *t < tmax))
        return false;
    double side = vec3_axis(r.dir, axis) > 0 ? 1 : -1;
    *normal = vec3(axis == 0 ? side : 0, axis == 1 ? side : 0, axis == 2 ? side : 0);
    return true;
}
