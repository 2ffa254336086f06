/* grade_utf8.c: UTF-8 read a character at a time, every byte of no valid character told apart. */
#include "grade_utf8.h"

/* Reads the UTF-8 character that starts at s: returns its length in bytes and sets *code,
 * or returns 0 for a byte that starts no valid character (a stray continuation byte, a
 * sequence cut short, an overlong form, a surrogate, a code point past U+10FFFF). */
int utf8_read(const char *text, unsigned long *code)
{
    static const unsigned long least[] = {0, 0, 0x80, 0x800, 0x10000};
    const unsigned char *s = (const unsigned char *)text;
    int n = s[0] < 0x80   ? 1
            : s[0] < 0xC2 ? 0
            : s[0] < 0xE0 ? 2
            : s[0] < 0xF0 ? 3
            : s[0] < 0xF5 ? 4
                          : 0;
    unsigned long c = s[0] & (0x7Fu >> (n > 0 ? n - 1 : 0)); /* the lead byte's bits */
    /* A continuation byte is 10xxxxxx; the string's NUL ends a cut sequence here too. */
    for (int k = 1; k < n; k++) {
        if ((s[k] & 0xC0) != 0x80)
            return 0;
        c = c << 6 | (s[k] & 0x3F);
    }
    if (n == 0 || c < least[n] || (c >= 0xD800 && c <= 0xDFFF) || c > 0x10FFFF)
        return 0;
    *code = c;
    return n;
}
