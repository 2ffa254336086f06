/* grade_containment.h: --sandbox's choice: bubblewrap's namespaces where they work here, or the fallback. */
#ifndef RAYTRA_GRADE_CONTAINMENT_H
#define RAYTRA_GRADE_CONTAINMENT_H

#include <stdbool.h>

#include "grading.h"

bool containment_choose(Grading *g);

#endif
