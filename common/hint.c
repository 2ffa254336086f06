/* hint.c: what to try when a scene or its render looks wrong: no light to shade with, or an image of one colour. */
#include "hint.h"

#include <string.h>

/* The kinds of light a part may shade with. */
#define LIGHTS (FEATURE_POINT_LIGHTS | FEATURE_DIRECTIONAL_LIGHTS | FEATURE_AREA_LIGHTS)

/* Tells whether a part with these features shades, and the scene has no light it uses. */
static bool unlit(const Scene *scene, unsigned features)
{
    return (features & FEATURE_SHADING) && (scene_features(scene) & features & LIGHTS) == 0;
}

/* Warns, before a long render, when part (of these features) shades but the scene has no
 * light it uses: everything but the ambient light will be black. */
void hint_scene(const Scene *scene, unsigned features, const char *part, FILE *out)
{
    if (!unlit(scene, features))
        return;
    fprintf(out, "raytra: warning: %s: no light that part %s uses (%s): the render will be "
                 "black%s\n",
            scene->path, part,
            scene_features(scene) & FEATURE_AREA_LIGHTS ? "its area lights come in part 1.6"
            : features & FEATURE_AREA_LIGHTS            ? "no 'l p', 'l d' or 'l s' line"
                                                        : "no 'l p' or 'l d' line",
            scene_features(scene) & FEATURE_AMBIENT_LIGHT ? " but for the ambient light" : "");
}

/* Warns when every pixel of the render is the same colour, with what most likely made it
 * so and what to try: no light the part uses, the Fall 2016 term's lights under the
 * lecture's convention, or a camera that meets nothing lit. */
void hint_image(const Scene *scene, unsigned features, const Image *img, FILE *out)
{
    long count = (long)img->width * img->height;
    const float *p = img->pixels;
    for (long k = 1; k < count; k++)
        if (memcmp(&p[3 * k], p, 3 * sizeof *p) != 0)
            return;
    if (count == 0)
        return;
    if (p[0] != 0 || p[1] != 0 || p[2] != 0) {
        fprintf(out, "raytra: warning: all %ld pixels are one colour (%g, %g, %g): the camera's "
                     "rays meet nothing, or one surface fills the view; check the camera's "
                     "direction and image plane (c line)\n",
                count, p[0], p[1], p[2]);
        return;
    }
    const char *why =
        unlit(scene, features) ? "this scene has no light that this part uses"
        : scene_light_too_bright(scene) != NULL
            ? "this scene's lights are brighter than 100, as in the Fall 2016 term, whose "
              "planes are p.N = d; try --convention fall2016"
        : (features & FEATURE_SHADING)
            ? "the camera sees nothing lit; check its direction (c line), and that the "
              "lights are on the side of the surfaces that it sees"
            : "the camera's rays meet no surface; check its direction and image plane (c line)";
    fprintf(out, "raytra: warning: all %ld pixels are black: %s\n", count, why);
}
