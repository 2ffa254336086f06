/* camera.h: the lecture's perspective camera: a frame, an image plane, and a ray per pixel. */
#ifndef RAYTRA_CAMERA_H
#define RAYTRA_CAMERA_H

#include "ray.h"
#include "scene.h"

/* excerpt: camera-struct */
typedef struct {
    Vec3 eye;                        /* e */
    Vec3 u, v, w;                    /* the frame: right, up, and backwards (away from the view) */
    double focal;                    /* d: the image plane is the plane at -d along w */
    double left, right, bottom, top; /* l, r, b, t: the image plane's edges in u and v */
    int nx, ny;                      /* pixels across and down */
} Camera;
/* end excerpt: camera-struct */

Camera camera_make(const CameraSpec *spec);
Ray camera_ray(const Camera *cam, double x, double y);

#endif
