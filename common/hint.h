/* hint.h: what to try when a scene or its render looks wrong (hint.c). */
#ifndef HINT_H
#define HINT_H

#include <stdio.h>

#include "image.h"
#include "scene.h"

void hint_scene(const Scene *scene, unsigned features, const char *part, FILE *out);
void hint_image(const Scene *scene, unsigned features, const Image *img, FILE *out);

#endif
