/* containment.h: the containment started and chosen (--sandbox): bubblewrap's namespaces where they work here, or the fallback. */
#ifndef RAYTRA_CONTAINMENT_H
#define RAYTRA_CONTAINMENT_H

const char *containment_start(const char *run_as, const char *grader_user, int jobs,
                              const char *asked);
void containment_finish(void);

#endif
