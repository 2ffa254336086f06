/* grade_self.c: --self's lines for a student checking their own work, every byte safe for a terminal. */
#include "grade_self.h"

#include <string.h>
#include <unistd.h>

#include "grade_base.h"
#include "grade_late.h"
#include "grade_run.h"
#include "grade_verdict.h"

/* Returns text with every byte a terminal could take for a control written \xNN: C0
 * controls and DEL, C1 controls (U+0080 to U+009F in UTF-8) and bytes of no well-formed
 * UTF-8 character (a lone 0x9B is CSI to an 8-bit terminal); what a student named, linked
 * to or printed goes through here on its way to a terminal. */
static char *plain(const char *text)
{
    char *out = grade_alloc(4 * strlen(text) + 1), *o = out;
    for (const unsigned char *t = (const unsigned char *)text; *t != '\0';) {
        int len = *t < 0x80                 ? 1
                  : *t >= 0xC2 && *t <= 0xDF ? 2
                  : *t >= 0xE0 && *t <= 0xEF ? 3
                  : *t >= 0xF0 && *t <= 0xF4 ? 4
                                             : 0;
        int n = 1;
        while (n < len && (t[n] & 0xC0) == 0x80)
            n++;
        bool control = *t < 0x20 || *t == 0x7F || (t[0] == 0xC2 && t[1] < 0xA0);
        if (len == 0 || n < len || control)
            o += sprintf(o, "\\x%02x", *t++);
        else
            for (int k = 0; k < len; k++)
                *o++ = (char)*t++;
    }
    *o = '\0';
    return out;
}

/* Prints, for a student checking their own work, each scene's verdict and reason, the heat
 * map to look at when it did not pass, and the command line to run again when the program
 * failed (crashed, timed out...), and with a due date when it was handed in and what
 * lateness costs; returns the exit status: 0 when every scene passes, 1
 * otherwise. */
int self_print(const Grading *g)
{
    const Submission *s = &g->subs[0];
    for (int k = 0; k < g->render_count; k++) {
        const SceneResult *res = &s->results[k];
        char *heat = grade_format("%s/%s.heat.png", s->work, g->renders[k].name);
        printf("%-12s %s: %s\n", verdict_info[res->verdict].name, plain(g->renders[k].name),
               plain(res->message));
        if (res->verdict != VERDICT_PASS && access(heat, F_OK) == 0)
            printf("%12s heat map: %s\n", "", plain(heat));
        if (res->command != NULL && verdict_info[res->verdict].tally == TALLY_ERROR)
            printf("%12s command: %s\n", "",
                   plain(grade_format("cd %s && %s", run_quote(grade_format("%s/run", s->work)),
                                      res->command)));
    }
    printf("%d of %d scenes pass; the report: %s/report.html\n", s->tally[TALLY_PASS],
           g->render_count, plain(g->out));
    if (late_describe(g, s) != NULL)
        printf("%s\n", late_describe(g, s));
    return s->tally[TALLY_PASS] == g->render_count ? 0 : 1;
}
