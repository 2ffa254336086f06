/* grade_html.h: what the report's parts share: text made safe for HTML, badges, embedded pictures. */
#ifndef RAYTRA_GRADE_HTML_H
#define RAYTRA_GRADE_HTML_H

#include <stdbool.h>
#include <stdio.h>

#include "grading.h"

/* The report's class (and colour) for each tally. */
extern const char *const html_tally_class[TALLY_COUNT];

char *html_escape(const char *text);
const char *html_plural(int n);
char *html_badge(const Grading *g, const Submission *s, int k);
char *html_copy_flag(int count);
bool html_picture_size(const char *path, int *width, int *height);
void html_put_picture(FILE *f, const char *path);

#endif
