/* view.h: what every pixel function reads: the scene and the camera built from it. */
#ifndef RAYTRA_VIEW_H
#define RAYTRA_VIEW_H

#include <stdbool.h>

#include "camera.h"
#include "scene.h"

typedef struct {
    Camera camera;
    const Scene *scene;
} View;

bool view_setup(const Scene *scene, void **ctx);

#endif
