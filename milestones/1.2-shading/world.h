/* world.h: the closest hit of a ray among all the surfaces of a scene. */
#ifndef RAYTRA_WORLD_H
#define RAYTRA_WORLD_H

#include <stdbool.h>

#include "explain.h"
#include "hit.h"
#include "ray.h"
#include "scene.h"

bool world_intersect(const Scene *scene, int s, Ray r, double tmin, double tmax, Hit *hit);
bool world_hit(const Scene *scene, Ray r, double tmin, double tmax, Hit *hit);
void world_complete_hit(const Scene *scene, Ray r, Hit *hit);
void world_explain_hit(const Explain *e, int depth, const Hit *hit);
int world_surface_id(const Scene *scene, const Hit *hit);

#endif
