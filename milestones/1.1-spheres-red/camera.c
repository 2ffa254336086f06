/* camera.c: the camera frame and the ray through a point of the image plane. */
#include "camera.h"

/* starter: todo */
/* Builds the camera of a scene's c line: its frame and its image plane. */
Camera camera_make(const CameraSpec *spec)
{
    Camera cam = {.eye = spec->eye, .focal = spec->focal, .nx = spec->nx, .ny = spec->ny};
    Vec3 view = vec3_normalize(spec->view);

    /* u = D x up, v = u x D, w = -D, with up = [0 1 0]:
     * slide 41 ("constructing a camera frame"). */
    Vec3 up = vec3(0, 1, 0);
    Vec3 u = vec3_cross(view, up);
    /* When D is parallel to up, D x up is zero and the recipe fails:
     * slide 41 ("this won't work when D is"). Then the image's up is taken where it
     * would be had the camera tilted straight up or down from looking along -z: +z
     * when looking up, -z when looking down. */
    if (!(vec3_length(u) > 1e-12)) {
        up = vec3(0, 0, view.y > 0 ? 1 : -1);
        u = vec3_cross(view, up);
    }
    cam.u = vec3_normalize(u);
    cam.v = vec3_normalize(vec3_cross(cam.u, view));
    cam.w = vec3_neg(view);

    /* The image plane is centred on the view axis, l = -r and b = -t:
     * slide 38 ("usually, an image is centered"). */
    cam.right = spec->width / 2;
    cam.left = -cam.right;
    cam.top = spec->height / 2;
    cam.bottom = -cam.top;
    return cam;
}

/* starter: todo */
/* Returns the unit ray from the eye through image point (x, y), measured in pixels
 * from the bottom-left corner: pixel (i, j) has its centre at (i + 0.5, j + 0.5). */
Ray camera_ray(const Camera *cam, double x, double y)
{
    /* u = l + (r - l)(i + 0.5)/nx and v = b + (t - b)(j + 0.5)/ny:
     * slide 38 ("relationship of (i, j) th pixel in image plane to u, v"). */
    double u = cam->left + (cam->right - cam->left) * x / cam->nx;
    double v = cam->bottom + (cam->top - cam->bottom) * y / cam->ny;

    /* The direction -d w + u u + v v, normalised:
     * slide 37 ("generating rays for a perspective camera"). */
    Vec3 dir = vec3_scale(cam->w, -cam->focal);
    dir = vec3_add_scaled(dir, cam->u, u);
    dir = vec3_add_scaled(dir, cam->v, v);
    return ray(cam->eye, vec3_normalize(dir));
}
