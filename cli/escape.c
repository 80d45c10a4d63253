/*
 * escape.c - text from outside shown on one line: every message the
 * command prints (an option's value, a file's name, a reader's quote of
 * a file's bytes) and the grade report's names and quotes.
 *
 * Control bytes are written as they would be typed, \n, \t, \r or \xHH;
 * a byte that is not valid UTF-8 as \xHH (so no stray byte can start a
 * terminal's control sequence); valid UTF-8 is kept, but for the
 * characters that change how the rest of a line reads: the bidirectional
 * controls (U+061C, U+200E, U+200F, U+202A-U+202E, U+2066-U+2069, which
 * can reorder a table's row) and the line and paragraph separators
 * (U+2028, U+2029), written \uHHHH.  A message is cut
 * at CLI_MESSAGE_MAX bytes with "...", so a 100,000-digit value cannot
 * make a 100,000-byte line.
 */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "cli.h"

size_t cli_utf8_sequence(const unsigned char *s)
{
    unsigned long cp;
    size_t n, i;
    if (s[0] >= 0xC2 && s[0] <= 0xDF) {
        n = 2;
        cp = s[0] & 0x1Fu;
    } else if (s[0] >= 0xE0 && s[0] <= 0xEF) {
        n = 3;
        cp = s[0] & 0x0Fu;
    } else if (s[0] >= 0xF0 && s[0] <= 0xF4) {
        n = 4;
        cp = s[0] & 0x07u;
    } else {
        return 0;
    }
    for (i = 1; i < n; i++) {
        if ((s[i] & 0xC0u) != 0x80u)
            return 0; /* also stops at the terminating NUL */
        cp = cp << 6 | (s[i] & 0x3Fu);
    }
    if ((n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000) ||
        cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
        return 0;
    return n;
}

/* The code point of the n-byte UTF-8 sequence at p when it is one that
   reorders or breaks the line it is in (shown as \uHHHH), else 0. */
static unsigned long line_control(const unsigned char *p, size_t n)
{
    unsigned long cp;
    if (n == 2)
        cp = (p[0] & 0x1Fu) << 6 | (p[1] & 0x3Fu);
    else if (n == 3)
        cp = (unsigned long)(p[0] & 0x0Fu) << 12 |
             (unsigned long)(p[1] & 0x3Fu) << 6 | (p[2] & 0x3Fu);
    else
        return 0;
    if (cp == 0x061C || cp == 0x200E || cp == 0x200F ||
        (cp >= 0x2028 && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069))
        return cp;
    return 0;
}

size_t cli_escape_unit(const char *s, int names, char text[8],
                       size_t *columns)
{
    unsigned long control;
    const unsigned char *p = (const unsigned char *)s;
    size_t n = p[0] >= 0x80 ? cli_utf8_sequence(p) : 0;
    /* The C1 controls (U+0080-U+009F) are shown byte by byte: some
       terminals obey them. */
    if (n == 2 && p[0] == 0xC2 && p[1] <= 0x9F)
        n = 0;
    control = n > 0 ? line_control(p, n) : 0;
    if (control != 0) {
        snprintf(text, 8, "\\u%04lx", control);
        *columns = strlen(text);
        return n;
    }
    if (n > 0) {
        memcpy(text, s, n);
        text[n] = '\0';
        *columns = 1;
        return n;
    }
    if (p[0] == '\n')
        strcpy(text, "\\n");
    else if (p[0] == '\t')
        strcpy(text, "\\t");
    else if (p[0] == '\r')
        strcpy(text, "\\r");
    else if (p[0] == '\\' && names)
        strcpy(text, "\\\\");
    else if (p[0] < 0x20 || p[0] >= 0x7f)
        snprintf(text, 8, "\\x%02x", p[0]);
    else {
        text[0] = s[0];
        text[1] = '\0';
    }
    *columns = strlen(text);
    return 1;
}

void cli_put_escaped(FILE *stream, const char *s, int names, size_t max)
{
    size_t written = 0;
    while (*s != '\0') {
        char text[8];
        size_t columns, n = cli_escape_unit(s, names, text, &columns);
        size_t length = strlen(text);
        if (max > 0 && written + length > max) {
            fputs("...", stream);
            return;
        }
        fputs(text, stream);
        written += length;
        s += n;
    }
}

void cli_say(const char *text)
{
    fputs("rayo: ", stderr);
    cli_put_escaped(stderr, text, 0, CLI_MESSAGE_MAX);
    fputc('\n', stderr);
}

void cli_vsayf(const char *format, va_list args)
{
    char text[CLI_MESSAGE_MAX + 64];
    int n = vsnprintf(text, sizeof text, format, args);
    if (n < 0)
        text[0] = '\0';
    else if ((size_t)n >= sizeof text)
        memcpy(text + sizeof text - 4, "...", 4);
    cli_say(text);
}

void cli_sayf(const char *format, ...)
{
    va_list args;
    va_start(args, format);
    cli_vsayf(format, args);
    va_end(args);
}
