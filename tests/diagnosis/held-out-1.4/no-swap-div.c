/* no-swap-div.c: held out, like no-swap written otherwise: each slab's planes divided by the
 * direction, taken as entry and exit in the order lo, hi whatever the direction's sign. */
bool box_hit_face(Box b, Ray r, double tmin, double tmax, double *t, Vec3 *normal)
{
    double enter[3], leave[3];
    for (int a = 0; a < 3; a++) {
        enter[a] = (vec3_axis(b.lo, a) - vec3_axis(r.origin, a)) / vec3_axis(r.dir, a);
        leave[a] = (vec3_axis(b.hi, a) - vec3_axis(r.origin, a)) / vec3_axis(r.dir, a);
    }
    int axis0 = 0, axis1 = 0;
    for (int a = 1; a < 3; a++) {
        if (enter[a] > enter[axis0])
            axis0 = a;
        if (leave[a] < leave[axis1])
            axis1 = a;
    }
    double t0 = enter[axis0], t1 = leave[axis1];
    int axis = t0 > tmin && t0 < tmax ? axis0 : axis1;
    *t = axis == axis0 && t0 > tmin && t0 < tmax ? t0 : t1;
    if (!(t0 <= t1 && *t > tmin && *t < tmax))
        return false;
    double side = vec3_axis(r.dir, axis) > 0 ? -1 : 1;
    *normal = vec3(axis == 0 ? side : 0, axis == 1 ? side : 0, axis == 2 ? side : 0);
    return true;
}
