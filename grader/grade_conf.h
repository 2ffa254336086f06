/* grade_conf.h: grading.conf read: the points and visibility of the scenes, the hidden scenes. */
#ifndef RAYTRA_GRADE_CONF_H
#define RAYTRA_GRADE_CONF_H

#include <stdbool.h>

#include "grading.h"

bool conf_read(Grading *g);

#endif
