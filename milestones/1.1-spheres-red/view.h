/* view.h: what every pixel function reads: the scene and the camera built from it. */
#ifndef RAYTRA_VIEW_H
#define RAYTRA_VIEW_H

#include <stdbool.h>

#include "camera.h"
#include "cli.h"
#include "scene.h"

typedef struct {
    Camera camera;
    const Scene *scene;
    const Options *opts; /* the command line, read by later parts */
} View;

bool view_setup(const Scene *scene, const Options *opts, void **ctx);

#endif
