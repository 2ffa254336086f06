/* grade_time.h: times in ISO 8601 with their time zone, and durations, read and written. */
#ifndef RAYTRA_GRADE_TIME_H
#define RAYTRA_GRADE_TIME_H

#include <stdbool.h>

/* What time_parse says a time must look like. */
#define TIME_FORMAT_TEXT "a time in ISO 8601 with its time zone (2026-03-01T23:59:00-05:00, or Z for UTC)"

bool time_parse(const char *text, double *when, int *zone);
char *time_format(double when, int zone);
bool time_parse_duration(const char *text, double *seconds);
char *time_duration_text(double seconds);

#endif
