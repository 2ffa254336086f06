/* grade_utf8.h: UTF-8 read a character at a time. */
#ifndef RAYTRA_GRADE_UTF8_H
#define RAYTRA_GRADE_UTF8_H

int utf8_read(const char *text, unsigned long *code);

#endif
