/* grade_html.c: what the report's parts share: text made safe for HTML, badges, embedded pictures. */
#include "grade_html.h"

#include <string.h>
#include <sys/stat.h>

#include "grade_base.h"
#include "grade_verdict.h"
#include "imgfile.h"

/* The largest picture embedded: thumbnails are far smaller; a larger file is a mistake. */
#define EMBED_MAX_BYTES (8L << 20)

const char *const html_tally_class[TALLY_COUNT] = {"pass", "fail", "missing", "error"};

/* Returns text with the characters HTML gives a meaning written as entities: everything a
 * student named or printed goes through here. */
char *html_escape(const char *text)
{
    static const char specials[] = "&<>\"'", *const entities[] = {"&amp;", "&lt;", "&gt;",
                                                                  "&quot;", "&#39;"};
    char *out = grade_alloc(6 * strlen(text) + 1), *o = out;
    for (const char *t = text; *t != '\0'; t++) {
        const char *special = strchr(specials, *t);
        if (special != NULL)
            o = stpcpy(o, entities[special - specials]);
        else
            *o++ = *t;
    }
    return out;
}

/* Returns "s" for a count other than 1, the plural's ending. */
const char *html_plural(int n)
{
    return n == 1 ? "" : "s";
}

/* Returns the badge of a submission's overall verdict, in its column's colour: PASS when
 * every scene passes, BUILD FAILED, or FAIL; or with k >= 0 that of scene k. */
char *html_badge(const Grading *g, const Submission *s, int k)
{
    Verdict overall = s->build_message != NULL                ? VERDICT_BUILD_FAILED
                      : s->tally[TALLY_PASS] == g->render_count ? VERDICT_PASS
                                                                : VERDICT_FAIL;
    const VerdictInfo *v = &verdict_info[k >= 0 ? s->results[k].verdict : overall];
    return grade_format("<span class=\"badge %s\">%s</span>", html_tally_class[v->tally],
                        v->name);
}

/* Returns the flag of a file handed in or written that is byte for byte the reference's, for
 * the instructor to look at (the verdict stays what imgdiff says): for `count` such scenes of
 * a submission, or none when count is 0. */
char *html_copy_flag(int count)
{
    return count == 0 ? ""
                      : grade_format(" <span class=\"badge flag\" title=\"%d image%s byte for byte "
                                     "the reference file%s: look at how it was made\">COPY</span>",
                                     count, html_plural(count), html_plural(count));
}

/* Tells whether the thumbnail at path, made by imgdiff, can be embedded (a PNG of a sane
 * size, in pixels and in bytes), and sets its size in pixels. */
bool html_picture_size(const char *path, int *width, int *height)
{
    ImgFileKind kind;
    Error err;
    struct stat st;
    return path != NULL && imgfile_header(path, &kind, width, height, &err) &&
           kind == IMGFILE_PNG && lstat(path, &st) == 0 && st.st_size <= EMBED_MAX_BYTES;
}

/* Writes the PNG at path as a data: URI, in base64. */
void html_put_picture(FILE *f, const char *path)
{
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    FILE *in = imgfile_fopen(path);
    unsigned char d[3];
    size_t n;
    fputs("data:image/png;base64,", f);
    while (in != NULL && (n = fread(memset(d, 0, sizeof d), 1, sizeof d, in)) > 0) {
        /* Three bytes make four digits; a '=' stands for each digit of a missing byte. */
        unsigned long bits = (unsigned long)d[0] << 16 | (unsigned long)d[1] << 8 | d[2];
        for (size_t j = 0; j < 4; j++)
            fputc(j <= n ? digits[(bits >> (18 - 6 * j)) & 63] : '=', f);
    }
    if (in != NULL)
        fclose(in);
}
