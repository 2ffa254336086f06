/* grade_metadata.c: grade metadata: the times of Gradescope's submission_metadata.json (when it was handed in, when it was due, a student's extension), for run_autograder. */
#include "grade_metadata.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grade_base.h"
#include "grade_time.h"

/* The most of the file read: its earlier submissions' results make it grow. */
#define METADATA_MAX_BYTES (256L << 20)

/* The deepest nesting of objects and arrays followed. */
#define METADATA_MAX_DEPTH 64

/* One time found: the moment, and its text as the file has it (time_parse took it whole). */
typedef struct {
    bool set;
    double when;
    const char *text;
} Found;

/* The times found; a date of the users' (their assignment: an extension) wins over the
 * assignment's, the latest of a group's. */
typedef struct {
    const char *p; /* where the parser is */
    bool bad;
    Found created, due, late, user_due, user_late;
    bool user_late_seen; /* a user's late_due_date, a time or null, is there */
} Metadata;

static void parse_value(Metadata *m, const char *path, int depth);

/* Skips white space. */
static void skip_space(Metadata *m)
{
    m->p += strspn(m->p, " \t\r\n");
}

/* Reads a JSON string at m->p (its opening quote) and returns its text: escapes other than
 * \" and \\ are kept as they are (no time holds one). */
static char *parse_string(Metadata *m)
{
    const char *start = ++m->p;
    while (*m->p != '"' && *m->p != '\0')
        m->p += *m->p == '\\' && m->p[1] != '\0' ? 2 : 1;
    if (*m->p != '"') {
        m->bad = true;
        return "";
    }
    return grade_format("%.*s", (int)(m->p++ - start), start);
}

/* Keeps in *found the time `text`, the moment `when`, unless it holds a later one. */
static void keep_latest(Found *found, const char *text, double when)
{
    if (!found->set || when > found->when)
        *found = (Found){true, when, text};
}

/* Keeps the time `text` (or a null, when text is NULL) found at `path` if it is one of the
 * times wanted: created_at; the assignment's due_date and late_due_date; each user's. */
static void keep(Metadata *m, const char *path, const char *text)
{
    double when = 0;
    int zone;
    bool is_time = text != NULL && time_parse(text, &when, &zone);
    if (strcmp(path, "/users/*/assignment/late_due_date") == 0)
        m->user_late_seen = true;
    if (!is_time)
        return;
    if (strcmp(path, "/created_at") == 0)
        m->created = (Found){true, when, text};
    else if (strcmp(path, "/assignment/due_date") == 0)
        m->due = (Found){true, when, text};
    else if (strcmp(path, "/assignment/late_due_date") == 0)
        m->late = (Found){true, when, text};
    else if (strcmp(path, "/users/*/assignment/due_date") == 0)
        keep_latest(&m->user_due, text, when);
    else if (strcmp(path, "/users/*/assignment/late_due_date") == 0)
        keep_latest(&m->user_late, text, when);
}

/* Reads an object or an array at m->p, its members' paths below `path`: an object's
 * members by name, an array's as "*". */
static void parse_container(Metadata *m, const char *path, int depth)
{
    bool object = *m->p++ == '{';
    char close = object ? '}' : ']';
    skip_space(m);
    if (*m->p == close) {
        m->p++;
        return;
    }
    while (!m->bad) {
        char *name = "*";
        skip_space(m);
        if (object) {
            if (*m->p != '"') {
                m->bad = true;
                return;
            }
            name = parse_string(m);
            skip_space(m);
            if (*m->p++ != ':') {
                m->bad = true;
                return;
            }
        }
        parse_value(m, grade_format("%s/%s", path, name), depth + 1);
        skip_space(m);
        if (*m->p == ',')
            m->p++;
        else {
            m->bad |= *m->p++ != close;
            return;
        }
    }
}

/* Reads the JSON value at m->p, found at `path`, keeping the times wanted. */
static void parse_value(Metadata *m, const char *path, int depth)
{
    skip_space(m);
    if (depth > METADATA_MAX_DEPTH)
        m->bad = true;
    else if (*m->p == '"')
        keep(m, path, parse_string(m));
    else if (*m->p == '{' || *m->p == '[')
        parse_container(m, path, depth);
    else if (strncmp(m->p, "null", 4) == 0)
        keep(m, path, NULL), m->p += 4;
    else if (strncmp(m->p, "true", 4) == 0 || strncmp(m->p, "false", 5) == 0)
        m->p += *m->p == 't' ? 4 : 5;
    else {
        size_t len = strspn(m->p, "+-0123456789.eE");
        m->bad |= len == 0;
        m->p += len;
    }
}

/* Runs grade metadata FILE ("-": standard input): reads Gradescope's
 * submission_metadata.json and prints a line a time, "submitted TIME", "due TIME" and
 * "late_until TIME", each when the file has it, as it has it (ISO 8601, which grade's
 * --submitted-at, --due and --late-until take; checked by time_parse, so no other
 * character than a time's is printed): created_at, and the assignment's due_date and
 * late_due_date, for which the users' own dates (a student's extension; a group's latest)
 * stand when the file has them. Exit status 0, or 2 when the file cannot be read or is no
 * JSON object. */
int metadata_main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: grade metadata FILE   (FILE: Gradescope's "
                        "submission_metadata.json, or - for standard input)\n");
        return EXIT_TROUBLE;
    }
    FILE *f = strcmp(argv[1], "-") == 0 ? stdin : fopen(argv[1], "rb");
    char *text = grade_alloc(METADATA_MAX_BYTES + 1);
    size_t size = f != NULL ? fread(text, 1, METADATA_MAX_BYTES + 1, f) : 0;
    if (f == NULL || ferror(f) || size > METADATA_MAX_BYTES) {
        grade_fail("cannot read %s%s", argv[1], f == NULL ? "" : " (or it is too large)");
        return EXIT_TROUBLE;
    }
    text[size] = '\0';
    Metadata m = {.p = text};
    skip_space(&m);
    if (*m.p != '{')
        m.bad = true;
    else
        parse_value(&m, "", 0);
    skip_space(&m);
    if (m.bad || *m.p != '\0') {
        grade_fail("%s: not a JSON object as Gradescope writes submission_metadata.json",
                   argv[1]);
        return EXIT_TROUBLE;
    }
    Found due = m.user_due.set ? m.user_due : m.due;
    Found late = m.user_late_seen ? m.user_late : m.late;
    if (m.created.set)
        printf("submitted %s\n", m.created.text);
    if (due.set)
        printf("due %s\n", due.text);
    if (late.set)
        printf("late_until %s\n", late.text);
    return EXIT_REPORTED;
}
