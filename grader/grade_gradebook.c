/* grade_gradebook.c: gradebook.csv: a line a student, with its points, lateness and final points, for Canvas, Moodle or a spreadsheet. */
#include "grade_gradebook.h"

#include "grade_base.h"
#include "grade_csv.h"
#include "grade_late.h"
#include "grade_time.h"

/* Returns the flags of submission s, words for the instructor to look at, separated by
 * spaces: copy (a file byte for byte the reference's), build-failed, link (its folder is a
 * link: not graded), late, too-late (it gets 0), no-time (a due date is set but when it was
 * handed in is not known); empty when none. */
static char *flags(const Grading *g, const Submission *s, const Lateness *l)
{
    bool copy = false;
    for (int k = 0; k < g->render_count; k++)
        copy |= s->results[k].copy;
    char *text = grade_format("%s%s%s%s%s%s", copy ? " copy" : "",
                              s->build_message != NULL ? " build-failed" : "",
                              s->link != NULL ? " link" : "", l->days > 0 ? " late" : "",
                              l->zero ? " too-late" : "",
                              g->late.due_set && !l->known ? " no-time" : "");
    return text[0] == ' ' ? text + 1 : text;
}

/* Writes gradebook.csv: a header, then a line a submission in the report's order. The
 * student's folder name stands under the headers Canvas matches students by (Student and
 * SIS Login ID; ID, SIS User ID and Section, which the grader does not know, are empty), so
 * that Canvas imports the file as it is; the numbers have two decimals and a dot;
 * final_points is what the course's gradebook takes (grader/docs/class.md). */
void gradebook_write(FILE *f, const Grading *g)
{
    fputs("Student,ID,SIS User ID,SIS Login ID,Section,points,maximum,percent,submitted,"
          "time_source,late_days,penalty_percent,final_points,flags\n", f);
    for (int i = 0; i < g->sub_count; i++) {
        const Submission *s = &g->subs[i];
        Lateness l = late_of(g, s);
        char *name = csv_field(s->name);
        fprintf(f, "%s,,,%s,,%.2f,%.2f,%.2f,%s,%s,%d,%.2f,%.2f,%s\n", name, name, l.points, l.max,
                l.max > 0 ? 100 * l.points / l.max : 0,
                s->time_source != NULL ? time_format(s->submitted, g->late.zone) : "",
                s->time_source != NULL ? s->time_source : "", l.days, l.penalty, l.final,
                csv_field(flags(g, s, &l)));
    }
}
