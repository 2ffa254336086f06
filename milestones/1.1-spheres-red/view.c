/* view.c: the per-render state of the parts: the scene and its camera, shared by every thread. */
#include "view.h"

#include <stdlib.h>

/* Builds the View of a scene for a Program's setup; false when out of memory. */
bool view_setup(const Scene *scene, const Options *opts, void **ctx)
{
    View *view = malloc(sizeof *view);
    if (view == NULL)
        return false;
    view->camera = camera_make(&scene->camera);
    view->scene = scene;
    view->opts = opts;
    *ctx = view;
    return true;
}
