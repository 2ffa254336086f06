/* docsnip.c: keeps the code excerpts in the docs identical to the source they quote. */
#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Longer names are refused, so that every message can print a name whole. */
#define MAX_NAME 64

/* Longer source paths in a doc are refused, for the same reason. */
#define MAX_PATH 1024

#if defined(__GNUC__)
#define PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define PRINTF_LIKE(f, a)
#endif

/* What --help prints: all the syntax an author needs, on one screen. */
static const char help_text[] =
    "Usage: docsnip [--root DIR] --check DOC.md...\n"
    "       docsnip [--root DIR] --update DOC.md...\n"
    "       docsnip --list SOURCE...\n"
    "Keeps the code excerpts in Markdown docs identical to the source they quote.\n"
    "\n"
    "  --check      report each excerpt region that is stale or cannot be resolved\n"
    "  --update     rewrite the stale regions (each doc is replaced whole, atomically)\n"
    "  --list       print FILE:LINE: NAME for each excerpt a source file defines\n"
    "  --root DIR   the folder the paths inside the docs are relative to (default: .)\n"
    "  -h, --help   show this help and exit\n"
    "\n"
    "A source file marks an excerpt with two lines that hold nothing but a comment:\n"
    "    /* excerpt: NAME */   ...   /* end excerpt: NAME */\n"
    "or, in Makefiles and shell scripts,  # excerpt: NAME  ...  # end excerpt: NAME\n"
    "NAME is made of a-z, 0-9 and '-'. Excerpts may nest or overlap; marker lines\n"
    "are left out, and the common indentation is removed.\n"
    "\n"
    "A doc quotes an excerpt with a region, whose inside belongs to docsnip:\n"
    "    <!-- excerpt: PATH NAME -->\n"
    "    <!-- end excerpt -->\n"
    "PATH is relative to --root. docsnip fills the region with a fenced code block\n"
    "(```c, ```make or ```sh, by the file name; longer fences when the code holds\n"
    "backticks), then the caption line *From PATH*. New lines end like the opening\n"
    "marker line (LF or CRLF). Markers inside fenced code blocks are plain text.\n"
    "\n"
    "Exit status: 0 when all is well, 1 when a problem was found, 2 for bad usage.\n";

/* What the command line asks for. */
typedef enum { MODE_NONE, MODE_CHECK, MODE_UPDATE, MODE_LIST } Mode;

/* A stretch of text inside a bigger buffer, not NUL-terminated. */
typedef struct {
    const char *s;
    size_t n;
} Span;

/* Bytes that grow as they are appended to. */
typedef struct {
    char *data;
    size_t size, cap;
} Buffer;

/* One line of a file: its text, then 0, 1 ("\n") or 2 ("\r\n") bytes of line ending. */
typedef struct {
    Span text;
    size_t eol;
} Line;

/* A whole file in memory, cut into lines that point into it. */
typedef struct {
    Buffer bytes;
    Line *lines;
    size_t count;
} LineFile;

/* Which kind of marker a line is, if any. */
typedef enum { MARK_NONE, MARK_OPEN, MARK_CLOSE, MARK_MALFORMED } MarkKind;

/* A marker line as read, its words pointing into the line. */
typedef struct {
    MarkKind kind;
    Span path; /* the source a doc region quotes; unused in source files */
    Span name;
} Marker;

/* One named excerpt of a source file; open and close index its marker lines. */
typedef struct {
    Span name;
    size_t open, close;
    bool closed;
} Excerpt;

/* A source file quoted by the docs, read once however many regions quote it. */
typedef struct {
    char *path;  /* as messages name it: relative to the root for the docs' sources */
    int error;   /* errno when it could not be read, else 0 */
    bool broken; /* its markers have errors, reported when it was read */
    LineFile file;
    bool *is_marker; /* for each line: marker lines are left out of every excerpt */
    Excerpt *excerpts;
    size_t count;
} Source;

/* The sources read so far, shared by all the docs of one run. */
typedef struct {
    const char *root;
    Source **items;
    size_t count;
} SourceSet;

/* The fenced code block a doc is inside of, if any: markers there are only text. */
typedef struct {
    char mark;     /* '`' or '~'; 0 when outside any fence */
    size_t length; /* a closing fence needs at least this many marks */
    size_t line;   /* where it opened, for messages */
} Fence;

/* One doc being checked, and the text that --update would give it. */
typedef struct {
    const char *path;
    Mode mode;
    SourceSet *sources;
    LineFile file;
    Buffer out;
    size_t copied; /* lines of file already accounted for in out */
    bool changed;
    int problems;
} Doc;

/* The command line, once understood. */
typedef struct {
    Mode mode;
    const char *root;
    char **files;
    int count;
    bool help;
} Args;

static int report(const char *path, size_t line, const char *fmt, ...) PRINTF_LIKE(3, 4);

/* Prints "path:line: message" on stderr, a form editors jump to; returns 1 to count it. */
static int report(const char *path, size_t line, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (line > 0)
        fprintf(stderr, "%s:%zu: ", path, line);
    else
        fprintf(stderr, "%s: ", path);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    return 1;
}

/* Resizes p like realloc, but ends the run when memory runs out: no doc is half-written. */
static void *xrealloc(void *p, size_t size)
{
    void *q = realloc(p, size > 0 ? size : 1);
    if (q == NULL) {
        fputs("docsnip: out of memory\n", stderr);
        exit(1);
    }
    return q;
}

/* Appends n bytes from s to b, doubling its room when it is full. */
static void buffer_add(Buffer *b, const char *s, size_t n)
{
    if (n == 0)
        return;
    if (b->cap - b->size < n) {
        size_t cap = b->cap > 0 ? b->cap : 256;
        while (cap - b->size < n)
            cap *= 2;
        b->data = xrealloc(b->data, cap);
        b->cap = cap;
    }
    memcpy(b->data + b->size, s, n);
    b->size += n;
}

/* Appends the C string s to b. */
static void buffer_puts(Buffer *b, const char *s)
{
    buffer_add(b, s, strlen(s));
}

/* Appends c to b, count times. */
static void buffer_repeat(Buffer *b, char c, size_t count)
{
    for (size_t k = 0; k < count; k++)
        buffer_add(b, &c, 1);
}

/* Appends text, a series of "\n"-ended lines, to b with eol in place of each "\n". */
static void buffer_add_lines(Buffer *b, Span text, const char *eol)
{
    const char *p = text.s, *end = text.s + text.n;
    while (p < end) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        size_t n = nl != NULL ? (size_t)(nl - p) : (size_t)(end - p);
        buffer_add(b, p, n);
        buffer_puts(b, eol);
        p += n + 1;
    }
}

/* Returns a new NUL-terminated copy of s, for the caller to free. */
static char *span_dup(Span s)
{
    Buffer b = {0};
    buffer_add(&b, s.s, s.n);
    buffer_add(&b, "", 1);
    return b.data;
}

/* Tells whether a and b hold the same text. */
static bool span_equal(Span a, Span b)
{
    return a.n == b.n && (a.n == 0 || memcmp(a.s, b.s, a.n) == 0);
}

/* Tells whether s holds exactly the C string word. */
static bool span_is(Span s, const char *word)
{
    return span_equal(s, (Span){word, strlen(word)});
}

/* Tells whether c is blank; '\r' counts, for a stray carriage return at a line's end. */
static bool is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/* Returns s without its leading and trailing blanks. */
static Span span_trim(Span s)
{
    while (s.n > 0 && is_blank(s.s[0])) {
        s.s++;
        s.n--;
    }
    while (s.n > 0 && is_blank(s.s[s.n - 1]))
        s.n--;
    return s;
}

/* Removes prefix from the start of s, telling whether it was there. */
static bool span_eat(Span *s, const char *prefix)
{
    size_t n = strlen(prefix);
    if (s->n < n || memcmp(s->s, prefix, n) != 0)
        return false;
    s->s += n;
    s->n -= n;
    return true;
}

/* Removes suffix from the end of s, telling whether it was there. */
static bool span_eat_end(Span *s, const char *suffix)
{
    size_t n = strlen(suffix);
    if (s->n < n || memcmp(s->s + s->n - n, suffix, n) != 0)
        return false;
    s->n -= n;
    return true;
}

/* Cuts s into blank-separated words, keeping max; returns their number (max + 1: more). */
static int span_words(Span s, Span *words, int max)
{
    int count = 0;
    size_t i = 0;
    for (;;) {
        while (i < s.n && is_blank(s.s[i]))
            i++;
        if (i == s.n)
            return count;
        if (count == max)
            return max + 1;
        size_t start = i;
        while (i < s.n && !is_blank(s.s[i]))
            i++;
        words[count++] = (Span){s.s + start, i - start};
    }
}

/* Counts the bytes that a and b share at their start. */
static size_t common_start(Span a, Span b)
{
    size_t n = 0;
    while (n < a.n && n < b.n && a.s[n] == b.s[n])
        n++;
    return n;
}

/* Cuts f->bytes into lines; a last line without "\n" still counts. */
static void file_split(LineFile *f)
{
    size_t n = 0;
    for (size_t i = 0; i < f->bytes.size; i++)
        n += f->bytes.data[i] == '\n';
    f->lines = xrealloc(NULL, (n + 1) * sizeof *f->lines);
    const char *p = f->bytes.data, *end = f->bytes.data + f->bytes.size;
    while (p < end) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        size_t len = nl != NULL ? (size_t)(nl - p) : (size_t)(end - p);
        size_t eol = nl != NULL;
        if (nl != NULL && len > 0 && p[len - 1] == '\r') {
            len--;
            eol = 2;
        }
        f->lines[f->count++] = (Line){{p, len}, eol};
        p += len + eol;
    }
}

/* Reads all of the file at path into f; false with errno set when it cannot. */
static bool file_read(LineFile *f, const char *path)
{
    memset(f, 0, sizeof *f);
    FILE *in = fopen(path, "rb");
    if (in == NULL)
        return false;
    char chunk[65536];
    size_t got;
    while ((got = fread(chunk, 1, sizeof chunk, in)) > 0)
        buffer_add(&f->bytes, chunk, got);
    int error = ferror(in) ? (errno != 0 ? errno : EIO) : 0;
    fclose(in);
    if (error != 0) {
        free(f->bytes.data);
        errno = error;
        return false;
    }
    file_split(f);
    return true;
}

/* Frees what file_read allocated. */
static void file_free(LineFile *f)
{
    free(f->bytes.data);
    free(f->lines);
}

/* Writes all of data to fd, however many calls write needs. */
static bool write_all(int fd, const Buffer *data)
{
    const char *p = data->data;
    size_t left = data->size;
    while (left > 0) {
        ssize_t n = write(fd, p, left);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0)
            return false;
        p += n;
        left -= (size_t)n;
    }
    return true;
}

/* Replaces the file at path by data through a temporary file beside it and a rename, so
 * that no reader ever sees half a doc; false with errno set when it cannot. */
static bool file_replace(const char *path, const Buffer *data)
{
    char *real = realpath(path, NULL); /* a symbolic link then stays a link */
    if (real == NULL)
        return false;
    Buffer temp = {0};
    buffer_puts(&temp, real);
    buffer_puts(&temp, ".docsnip-XXXXXX");
    buffer_add(&temp, "", 1);
    struct stat st;
    int error = 0, fd = -1;
    if (stat(real, &st) != 0 || (fd = mkstemp(temp.data)) < 0)
        error = errno;
    else if (fchmod(fd, st.st_mode & 07777) != 0 || !write_all(fd, data) || fsync(fd) != 0)
        error = errno;
    if (fd >= 0 && close(fd) != 0 && error == 0)
        error = errno;
    if (fd >= 0 && error == 0 && rename(temp.data, real) != 0)
        error = errno;
    if (fd >= 0 && error != 0)
        unlink(temp.data);
    free(temp.data);
    free(real);
    errno = error;
    return error == 0;
}

/* Tells whether s is a good excerpt name: 1 to MAX_NAME of a-z, 0-9 and '-'. */
static bool name_valid(Span s)
{
    if (s.n == 0 || s.n > MAX_NAME)
        return false;
    for (size_t i = 0; i < s.n; i++) {
        char c = s.s[i];
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'))
            return false;
    }
    return true;
}

/* Tells whether a doc's source path stays under the root and prints safely in Markdown. */
static bool path_valid(Span p)
{
    if (p.n == 0 || p.n > MAX_PATH || p.s[0] == '/')
        return false;
    size_t part = 0;
    for (size_t i = 0; i <= p.n; i++) {
        if (i == p.n || p.s[i] == '/') {
            if (span_is((Span){p.s + part, i - part}, ".."))
                return false;
            part = i + 1;
        } else if (!isalnum((unsigned char)p.s[i]) && p.s[i] != '.' && p.s[i] != '_' &&
                   p.s[i] != '-') {
            return false;
        }
    }
    return true;
}

/* Reads the words of a marker comment, "[end] excerpt[:] ARGS", into args (room for 3);
 * returns MARK_NONE for any other comment. */
static MarkKind marker_words(Span body, bool *colon, Span *args, int *nargs)
{
    Span w[4];
    int n = span_words(body, w, 4);
    int k = n > 0 && span_is(w[0], "end");
    if (n <= k)
        return MARK_NONE;
    Span word = w[k];
    *colon = span_is(word, "excerpt:");
    if (!span_is(word, "excerpt") && !span_eat(&word, "excerpt:"))
        return MARK_NONE;
    *nargs = n - k - 1;
    for (int i = 0; i < *nargs && k + 1 + i < 4; i++)
        args[i] = w[k + 1 + i];
    return k > 0 ? MARK_CLOSE : MARK_OPEN;
}

/* Recognises a source line that is only a marker comment, in slash-star or hash style. */
static Marker source_marker(Span line)
{
    Marker m = {.kind = MARK_NONE};
    Span body = span_trim(line), args[3];
    bool colon;
    int n;
    if (!span_eat(&body, "#") && !(span_eat(&body, "/*") && span_eat_end(&body, "*/")))
        return m;
    m.kind = marker_words(body, &colon, args, &n);
    if (m.kind == MARK_NONE)
        return m;
    if (colon && n == 1 && name_valid(args[0]))
        m.name = args[0];
    else
        m.kind = MARK_MALFORMED;
    return m;
}

/* Recognises a doc line that is only a region marker, "<!-- excerpt: PATH NAME -->" or
 * "<!-- end excerpt -->"; other HTML comments are not markers. */
static Marker doc_marker(Span line)
{
    Marker m = {.kind = MARK_NONE};
    Span body = span_trim(line), args[3];
    bool colon;
    int n;
    if (!span_eat(&body, "<!--") || !span_eat_end(&body, "-->"))
        return m;
    m.kind = marker_words(body, &colon, args, &n);
    if (m.kind == MARK_OPEN && colon && n == 2 && name_valid(args[1])) {
        m.path = args[0];
        m.name = args[1];
    } else if (m.kind != MARK_NONE && !(m.kind == MARK_CLOSE && !colon && n == 0)) {
        m.kind = MARK_MALFORMED;
    }
    return m;
}

/* Finds the latest excerpt called name in src, skipping closed ones when open_only. */
static Excerpt *source_find(const Source *src, Span name, bool open_only)
{
    for (size_t k = src->count; k-- > 0;) {
        Excerpt *e = &src->excerpts[k];
        if (span_equal(e->name, name) && !(open_only && e->closed))
            return e;
    }
    return NULL;
}

/* Records the marker on line i of src, reporting those that do not pair up; returns the
 * number of problems. */
static int source_mark(Source *src, Marker m, size_t i)
{
    if (m.kind == MARK_MALFORMED)
        return report(src->path, i + 1,
                      "malformed excerpt marker: the comment must hold 'excerpt: NAME' or "
                      "'end excerpt: NAME', NAME made of a-z, 0-9 and '-'");
    int shown = (int)m.name.n;
    if (m.kind == MARK_CLOSE) {
        Excerpt *e = source_find(src, m.name, true);
        if (e == NULL)
            return report(src->path, i + 1, "end of excerpt '%.*s', which was never opened", shown,
                          m.name.s);
        e->close = i;
        e->closed = true;
        return 0;
    }
    const Excerpt *twin = source_find(src, m.name, false);
    size_t first = twin != NULL ? twin->open + 1 : 0;
    src->excerpts = xrealloc(src->excerpts, (src->count + 1) * sizeof *src->excerpts);
    src->excerpts[src->count++] = (Excerpt){m.name, i, 0, false};
    if (first > 0)
        return report(src->path, i + 1, "excerpt '%.*s' is defined twice (first on line %zu)",
                      shown, m.name.s, first);
    return 0;
}

/* Finds the excerpts of src, reporting marker problems; returns how many there were. */
static int source_scan(Source *src)
{
    const LineFile *f = &src->file;
    int problems = 0;
    src->is_marker = xrealloc(NULL, (f->count + 1) * sizeof *src->is_marker);
    for (size_t i = 0; i < f->count; i++) {
        Marker m = source_marker(f->lines[i].text);
        src->is_marker[i] = m.kind == MARK_OPEN || m.kind == MARK_CLOSE;
        if (m.kind != MARK_NONE)
            problems += source_mark(src, m, i);
    }
    for (size_t k = 0; k < src->count; k++) {
        const Excerpt *e = &src->excerpts[k];
        if (!e->closed)
            problems += report(src->path, e->open + 1, "excerpt '%.*s' is never closed",
                               (int)e->name.n, e->name.s);
    }
    return problems;
}

/* Reads the source at file and finds its excerpts; src->path names it in messages. */
static void source_load(Source *src, const char *file)
{
    if (!file_read(&src->file, file))
        src->error = errno;
    else
        src->broken = source_scan(src) > 0;
}

/* Frees src and what it holds. */
static void source_free(Source *src)
{
    file_free(&src->file);
    free(src->is_marker);
    free(src->excerpts);
    free(src->path);
}

/* Appends excerpt e of src to out as "\n"-ended lines, without the marker lines and without
 * the indentation that all its non-blank lines share. */
static void excerpt_text(const Source *src, const Excerpt *e, Buffer *out)
{
    const Line *lines = src->file.lines;
    Span indent = {NULL, 0};
    bool seen = false;
    for (size_t i = e->open + 1; i < e->close; i++) {
        Span t = lines[i].text;
        size_t lead = 0;
        while (lead < t.n && is_blank(t.s[lead]))
            lead++;
        if (src->is_marker[i] || lead == t.n)
            continue;
        Span own = {t.s, lead};
        indent = seen ? (Span){indent.s, common_start(indent, own)} : own;
        seen = true;
    }
    for (size_t i = e->open + 1; i < e->close; i++) {
        if (src->is_marker[i])
            continue;
        Span t = lines[i].text;
        size_t cut = common_start(t, indent); /* blank lines lose what they have of it */
        buffer_add(out, t.s + cut, t.n - cut);
        buffer_puts(out, "\n");
    }
}

/* Returns a backtick fence length that no run of backticks in code can close. */
static size_t fence_length(Span code)
{
    size_t longest = 0, run = 0;
    for (size_t i = 0; i < code.n; i++) {
        run = code.s[i] == '`' ? run + 1 : 0;
        if (run > longest)
            longest = run;
    }
    return longest < 3 ? 3 : longest + 1;
}

/* Names the language of the file at path for a fence's info string ("" when unknown). */
static const char *language_of(const char *path)
{
    static const struct {
        const char *ending; /* a whole file name, or an extension when it starts with '.' */
        const char *language;
    } table[] = {
        {".c", "c"},          {".h", "c"},          {".sh", "sh"},
        {".mk", "make"},      {"Makefile", "make"}, {"GNUmakefile", "make"},
        {"makefile", "make"},
    };
    const char *base = strrchr(path, '/');
    base = base != NULL ? base + 1 : path;
    const char *dot = strrchr(base, '.');
    const char *extension = dot != NULL ? dot : "";
    for (size_t k = 0; k < sizeof table / sizeof table[0]; k++) {
        const char *ending = table[k].ending;
        if (strcmp(ending[0] == '.' ? extension : base, ending) == 0)
            return table[k].language;
    }
    return "";
}

/* Appends what a region quoting excerpt e of src must hold: the fenced code, then a caption
 * in italics naming the source. */
static void region_block(const Source *src, const Excerpt *e, Buffer *out)
{
    Buffer code = {0};
    excerpt_text(src, e, &code);
    size_t fence = fence_length((Span){code.data, code.size});
    buffer_repeat(out, '`', fence);
    buffer_puts(out, language_of(src->path));
    buffer_puts(out, "\n");
    buffer_add(out, code.data, code.size);
    buffer_repeat(out, '`', fence);
    buffer_puts(out, "\n*From ");
    buffer_puts(out, src->path);
    buffer_puts(out, "*\n");
    free(code.data);
}

/* Tells whether lines [first, end) of f hold the text of want, a series of "\n"-ended
 * lines; line endings are not compared, so a CRLF doc can be up to date. */
static bool lines_match(const LineFile *f, size_t first, size_t end, Span want)
{
    size_t at = 0;
    for (size_t i = first; i < end; i++) {
        Span t = f->lines[i].text;
        if (want.n - at < t.n + 1 || memcmp(want.s + at, t.s, t.n) != 0 || want.s[at + t.n] != '\n')
            return false;
        at += t.n + 1;
    }
    return at == want.n;
}

/* Returns the source at path, relative to the root, reading it on first use. */
static Source *sources_get(SourceSet *set, Span path)
{
    for (size_t k = 0; k < set->count; k++)
        if (span_is(path, set->items[k]->path))
            return set->items[k];
    Source *src = xrealloc(NULL, sizeof *src);
    *src = (Source){.path = span_dup(path)};
    Buffer file = {0};
    buffer_puts(&file, set->root);
    buffer_puts(&file, "/");
    buffer_puts(&file, src->path);
    buffer_add(&file, "", 1);
    source_load(src, file.data);
    free(file.data);
    set->items = xrealloc(set->items, (set->count + 1) * sizeof *set->items);
    set->items[set->count++] = src;
    return src;
}

/* Frees every source of set. */
static void sources_free(SourceSet *set)
{
    for (size_t k = 0; k < set->count; k++) {
        source_free(set->items[k]);
        free(set->items[k]);
    }
    free(set->items);
}

/* Follows the doc's fenced code blocks through the line text (number line); tells whether
 * the line belongs to one, where a marker would only be an example. */
static bool fence_follow(Fence *fence, Span text, size_t line)
{
    size_t i = 0;
    while (i < text.n && i < 3 && text.s[i] == ' ')
        i++;
    char mark = i < text.n && (text.s[i] == '`' || text.s[i] == '~') ? text.s[i] : 0;
    size_t run = 0;
    while (mark != 0 && i + run < text.n && text.s[i + run] == mark)
        run++;
    Span rest = {text.s + i + run, text.n - i - run};
    if (fence->mark != 0) {
        if (mark == fence->mark && run >= fence->length && span_trim(rest).n == 0)
            fence->mark = 0;
        return true;
    }
    if (run < 3 || (mark == '`' && memchr(rest.s, '`', rest.n) != NULL))
        return false;
    *fence = (Fence){mark, run, line};
    return true;
}

/* Copies lines [d->copied, end) of the doc to its new text unchanged. */
static void doc_copy(Doc *d, size_t end)
{
    if (end > d->copied) {
        const Line *first = &d->file.lines[d->copied], *last = &d->file.lines[end - 1];
        const char *stop = last->text.s + last->text.n + last->eol;
        buffer_add(&d->out, first->text.s, (size_t)(stop - first->text.s));
        d->copied = end;
    }
}

/* Checks the region between the markers on lines open and close (indexes), and puts its
 * new text in place for --update. */
static void doc_region(Doc *d, size_t open, size_t close, Marker m)
{
    size_t line = open + 1;
    int name = (int)m.name.n;
    if (!path_valid(m.path)) {
        d->problems += report(d->path, line,
                              "excerpt path '%.*s' must be relative to the root, without "
                              "'..', made of letters, digits, '.', '_', '-' and '/'",
                              (int)(m.path.n < MAX_PATH ? m.path.n : MAX_PATH), m.path.s);
        return;
    }
    Source *src = sources_get(d->sources, m.path);
    const Excerpt *e = src->error != 0 ? NULL : source_find(src, m.name, false);
    if (src->error != 0)
        d->problems += report(d->path, line, "cannot read %s: %s", src->path, strerror(src->error));
    else if (e == NULL)
        d->problems += report(d->path, line, "no excerpt '%.*s' in %s", name, m.name.s, src->path);
    else if (src->broken)
        d->problems +=
            report(d->path, line, "excerpt '%.*s' cannot be used: %s has marker errors (above)",
                   name, m.name.s, src->path);
    if (e == NULL || src->broken)
        return;
    Buffer block = {0};
    region_block(src, e, &block);
    Span want = {block.data, block.size};
    if (!lines_match(&d->file, open + 1, close, want)) {
        if (d->mode == MODE_CHECK)
            d->problems += report(d->path, line, "excerpt '%.*s' from %s is stale; run 'make docs'",
                                  name, m.name.s, src->path);
        doc_copy(d, open + 1);
        buffer_add_lines(&d->out, want, d->file.lines[open].eol == 2 ? "\r\n" : "\n");
        d->copied = close;
        d->changed = true;
    }
    free(block.data);
}

/* Walks the doc line by line, pairing the region markers and checking each region. */
static void doc_walk(Doc *d)
{
    Fence fence = {.mark = 0};
    Marker opener = {.kind = MARK_NONE};
    size_t open = 0;
    for (size_t i = 0; i < d->file.count; i++) {
        if (fence_follow(&fence, d->file.lines[i].text, i + 1))
            continue;
        Marker m = doc_marker(d->file.lines[i].text);
        if (m.kind == MARK_MALFORMED) {
            d->problems += report(d->path, i + 1,
                                  "malformed excerpt marker: write "
                                  "'<!-- excerpt: PATH NAME -->' and '<!-- end excerpt -->', "
                                  "NAME made of a-z, 0-9 and '-'");
        } else if (m.kind == MARK_OPEN) {
            if (opener.kind == MARK_OPEN)
                d->problems += report(d->path, open + 1, "excerpt region not closed");
            opener = m;
            open = i;
        } else if (m.kind == MARK_CLOSE && opener.kind != MARK_OPEN) {
            d->problems += report(d->path, i + 1, "end of an excerpt region never opened");
        } else if (m.kind == MARK_CLOSE) {
            doc_region(d, open, i, opener);
            opener.kind = MARK_NONE;
        }
    }
    if (opener.kind == MARK_OPEN && fence.mark != 0)
        d->problems += report(d->path, open + 1,
                              "excerpt region not closed (its code fence on line %zu is "
                              "not closed either)",
                              fence.line);
    else if (opener.kind == MARK_OPEN)
        d->problems += report(d->path, open + 1, "excerpt region not closed");
    else if (fence.mark != 0)
        d->problems += report(d->path, fence.line,
                              "code fence not closed: any excerpt marker after it is unseen");
    doc_copy(d, d->file.count);
}

/* Checks or updates the doc at path; returns the number of problems found. */
static int doc_process(SourceSet *sources, const char *path, Mode mode)
{
    Doc d = {.path = path, .mode = mode, .sources = sources};
    if (!file_read(&d.file, path))
        return report("docsnip", 0, "cannot read %s: %s", path, strerror(errno));
    doc_walk(&d);
    if (mode == MODE_UPDATE && d.problems > 0) {
        report(path, 0, "not updated because of the problems above");
    } else if (mode == MODE_UPDATE && d.changed) {
        if (file_replace(path, &d.out))
            printf("updated %s\n", path);
        else
            d.problems += report("docsnip", 0, "cannot write %s: %s", path, strerror(errno));
    }
    file_free(&d.file);
    free(d.out.data);
    return d.problems;
}

/* Prints "FILE:LINE: NAME" for each excerpt of the source file at path; returns the number
 * of problems found in it. */
static int list_excerpts(const char *path)
{
    Source src = {.path = span_dup((Span){path, strlen(path)})};
    source_load(&src, path);
    int problems = src.error != 0 || src.broken;
    if (src.error != 0)
        report("docsnip", 0, "cannot read %s: %s", path, strerror(src.error));
    for (size_t k = 0; k < src.count; k++) {
        const Excerpt *e = &src.excerpts[k];
        printf("%s:%zu: %.*s\n", path, e->open + 1, (int)e->name.n, e->name.s);
    }
    source_free(&src);
    return problems;
}

/* Says what is wrong with the command line; returns false for args_parse to pass on. */
static bool usage_error(const char *what, const char *arg)
{
    report("docsnip", 0, "%s%s", what, arg);
    fputs("Try 'docsnip --help'.\n", stderr);
    return false;
}

/* Understands argv into a (whose files has room for argc); false, reported, when it
 * makes no sense. */
static bool args_parse(int argc, char **argv, Args *a)
{
    static const struct {
        const char *option;
        Mode mode;
    } modes[] = {{"--check", MODE_CHECK}, {"--update", MODE_UPDATE}, {"--list", MODE_LIST}};
    bool options = true;
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        Mode mode = MODE_NONE;
        for (size_t k = 0; k < sizeof modes / sizeof modes[0]; k++)
            if (strcmp(arg, modes[k].option) == 0)
                mode = modes[k].mode;
        if (!options || arg[0] != '-' || arg[1] == '\0')
            a->files[a->count++] = argv[i];
        else if (strcmp(arg, "--") == 0)
            options = false;
        else if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0)
            a->help = true;
        else if (strncmp(arg, "--root=", 7) == 0)
            a->root = arg + 7;
        else if (strcmp(arg, "--root") == 0 && i + 1 < argc)
            a->root = argv[++i];
        else if (strcmp(arg, "--root") == 0)
            return usage_error("--root needs a folder", "");
        else if (mode != MODE_NONE && a->mode != MODE_NONE && a->mode != mode)
            return usage_error("choose one of --check, --update and --list", "");
        else if (mode != MODE_NONE)
            a->mode = mode;
        else
            return usage_error("unknown option ", arg);
    }
    if (a->help)
        return true;
    if (a->mode == MODE_NONE)
        return usage_error("say what to do: --check, --update or --list", "");
    if (a->count == 0)
        return usage_error("no files given", "");
    if (a->root[0] == '\0')
        return usage_error("--root needs a folder", "");
    return true;
}

/* Runs docsnip: 0 when all is well, 1 when a problem was found, 2 for bad usage. */
int main(int argc, char **argv)
{
    Args a = {MODE_NONE, ".", NULL, 0, false};
    a.files = xrealloc(NULL, (size_t)argc * sizeof *a.files);
    bool ok = args_parse(argc, argv, &a);
    int status = 2;
    if (ok && a.help) {
        fputs(help_text, stdout);
        status = 0;
    } else if (ok && a.mode == MODE_LIST) {
        int problems = 0;
        for (int k = 0; k < a.count; k++)
            problems += list_excerpts(a.files[k]);
        status = problems > 0;
    } else if (ok) {
        SourceSet sources = {a.root, NULL, 0};
        int problems = 0;
        for (int k = 0; k < a.count; k++)
            problems += doc_process(&sources, a.files[k], a.mode);
        sources_free(&sources);
        status = problems > 0;
    }
    free(a.files);
    return status;
}
