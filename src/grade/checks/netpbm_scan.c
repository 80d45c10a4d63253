/*
 * netpbm_scan.c - the parts of the strict Netpbm checkers that do not
 * depend on the raster (netpbm_scan.h): positions, quotes, the magic
 * number, the dimensions, the count verdict and the line-length note.
 *
 * Messages name the format the exercise asks for (netpbm_kind), so the
 * P1 checker says exactly what it said before P2 and P3 joined it.
 */
#include <stdio.h>
#include <string.h>

#include "rayo/limits.h"

#include "netpbm_scan.h"
#include "rayo/lang.h"

#define NETPBM_LINE_LIMIT 70

static const netpbm_kind kinds[] = {
    {'1', "PBM", N_("digits"), "imagen.pbm", 1},
    {'2', "PGM", N_("numbers"), "imagen.pgm", 1},
    {'3', "PPM", N_("numbers"), "imagen.ppm", 3},
};

const netpbm_kind *netpbm_kind_of(char magic)
{
    size_t i;
    for (i = 0; i < sizeof kinds / sizeof kinds[0]; i++)
        if (kinds[i].magic == magic)
            return &kinds[i];
    return NULL;
}

void netpbm_where(const netpbm_scan *s, size_t offset, unsigned long *line,
                  unsigned long *column)
{
    size_t i;
    *line = 1;
    *column = 1;
    for (i = 0; i < offset && i < s->size; i++) {
        if (s->data[i] == '\n') {
            (*line)++;
            *column = 1;
        } else {
            (*column)++;
        }
    }
}

void netpbm_excerpt(const netpbm_scan *s, size_t offset, size_t length,
                    char *out, size_t room)
{
    size_t i, n = 0;
    if (length > 16)
        length = 16;
    for (i = offset; i < s->size && i < offset + length && n + 5 < room;
         i++) {
        unsigned char c = s->data[i];
        if (c == '\n')
            n += (size_t)snprintf(out + n, room - n, "\\n");
        else if (c == '\r')
            n += (size_t)snprintf(out + n, room - n, "\\r");
        else if (c == '\t')
            n += (size_t)snprintf(out + n, room - n, "\\t");
        else if (c >= 32 && c < 127)
            out[n++] = (char)c;
        else
            n += (size_t)snprintf(out + n, room - n, "\\x%02x", c);
    }
    out[n] = '\0';
}

void netpbm_skip_header_space(netpbm_scan *s)
{
    while (s->pos < s->size) {
        int c = netpbm_peek(s);
        if (c == '#') {
            while (s->pos < s->size && s->data[s->pos] != '\n')
                s->pos++;
        } else if (netpbm_is_space(c)) {
            s->pos++;
        } else {
            break;
        }
    }
}

int netpbm_read_number(netpbm_scan *s, unsigned long *value)
{
    size_t start = s->pos;
    *value = 0;
    while (netpbm_is_digit(netpbm_peek(s))) {
        if (*value < 100000000ul)
            *value = *value * 10 + (unsigned long)(netpbm_peek(s) - '0');
        s->pos++;
    }
    return s->pos > start;
}

const char *netpbm_format_name(const unsigned char *m)
{
    if (m[0] != 'P' && m[0] != 'p')
        return NULL;
    switch (m[1]) {
    case '1': return N_("plain PBM (black and white)");
    case '2': return N_("plain PGM (gray)");
    case '3': return N_("plain PPM (colour)");
    case '4': return N_("raw PBM (binary)");
    case '5': return N_("raw PGM (gray, binary)");
    case '6': return N_("raw PPM (colour, binary)");
    }
    return NULL;
}

void netpbm_refuse_other(netpbm_scan *s, const netpbm_kind *kind)
{
    const unsigned char *m = s->data + s->pos;
    NETPBM_FAIL(s, N_("the magic number is '%c%c', %s; the exercise asks for "
                   "plain %s, 'P%c'"),
                m[0], m[1],
                rayo_gettext(rayo_error_lang(s->err), netpbm_format_name(m)),
                kind->name, kind->magic);
}

netpbm_magic netpbm_check_magic(netpbm_scan *s, const netpbm_kind *kind)
{
    static const unsigned char png[4] = {0x89, 'P', 'N', 'G'};
    const unsigned char *m;
    char seen[80];
    size_t start = 0;
    while (start < s->size && netpbm_is_space(s->data[start]))
        start++;
    if (start > 0 && start + 1 < s->size &&
        (s->data[start] == 'P' || s->data[start] == 'p'))
        NETPBM_FAIL(s, rayo_ngettext(rayo_error_lang(s->err),
                                     "the output begins with %zu whitespace "
                                     "character before the magic number; a "
                                     "%s file must begin with 'P%c' itself",
                                     "the output begins with %zu whitespace "
                                     "characters before the magic number; a "
                                     "%s file must begin with 'P%c' itself",
                                     start),
                    start, kind->name, kind->magic);
    else
        start = 0;
    s->pos = start;
    m = s->data + start;
    if (s->size - start >= 4 && memcmp(m, png, 4) == 0) {
        NETPBM_FAIL(s, N_("the output is a PNG image; the exercise asks for "
                       "plain %s ('P%c' and %s) on standard output"),
                    kind->name, kind->magic,
                    rayo_gettext(rayo_error_lang(s->err), kind->samples));
        return NETPBM_MAGIC_REFUSED;
    }
    if (s->size - start >= 2 && m[1] != kind->magic &&
        netpbm_format_name(m) != NULL)
        return NETPBM_MAGIC_OTHER;
    if (s->size - start >= 2 && m[0] == 'p' && m[1] == kind->magic) {
        NETPBM_FAIL(s, N_("the magic number is 'p%c' in lowercase; Netpbm "
                       "needs a capital 'P%c', and viewers refuse the file"),
                    kind->magic, kind->magic);
    } else if (s->size - start < 2 || m[0] != 'P' || m[1] != kind->magic) {
        netpbm_excerpt(s, start, 16, seen, sizeof seen);
        NETPBM_FAIL(s, N_("the output does not begin with the magic number "
                       "'P%c'; it begins with '%s'"),
                    kind->magic, seen);
        return NETPBM_MAGIC_REFUSED;
    }
    s->pos = start + 2;
    if (s->pos < s->size && !netpbm_is_space(netpbm_peek(s)) &&
        netpbm_peek(s) != '#')
        NETPBM_FAIL(s, N_("there is no whitespace after the magic number "
                       "'P%c'"),
                    kind->magic);
    return NETPBM_MAGIC_WANTED;
}

/* What the header says when its number `field` is missing: the output
   ends (ended) or something else stands there. */
static void say_missing(netpbm_scan *s, netpbm_field field, int magic,
                        int ended, unsigned long line, unsigned long column,
                        const char *seen)
{
    switch (field) {
    case NETPBM_FIELD_WIDTH:
        if (ended)
            NETPBM_FAIL(s, N_("the output ends before the width (expected "
                           "after 'P%c')"),
                        magic);
        else
            NETPBM_FAIL(s, N_("expected the width after 'P%c' at line %lu, "
                           "column %lu; found '%s'"),
                        magic, line, column, seen);
        break;
    case NETPBM_FIELD_HEIGHT:
        if (ended)
            NETPBM_FAIL(s, N_("the output ends before the height (expected "
                           "after the width)"));
        else
            NETPBM_FAIL(s, N_("expected the height after the width at line "
                           "%lu, column %lu; found '%s'"),
                        line, column, seen);
        break;
    case NETPBM_FIELD_MAXVAL:
        if (ended)
            NETPBM_FAIL(s, N_("the output ends before the maximum value "
                           "(255) (expected after the height)"));
        else
            NETPBM_FAIL(s, N_("expected the maximum value (255) after the "
                           "height at line %lu, column %lu; found '%s'"),
                        line, column, seen);
        break;
    }
}

int netpbm_expect_number(netpbm_scan *s, netpbm_field field, int magic,
                         unsigned long *value)
{
    unsigned long line, column;
    char seen[80];
    netpbm_skip_header_space(s);
    if (netpbm_read_number(s, value))
        return 1;
    netpbm_where(s, s->pos, &line, &column);
    netpbm_excerpt(s, s->pos, 16, seen, sizeof seen);
    say_missing(s, field, magic, s->pos >= s->size, line, column, seen);
    return 0;
}

int netpbm_check_dimensions(netpbm_scan *s, const netpbm_kind *kind,
                            uint32_t want_w, uint32_t want_h,
                            unsigned long *w, unsigned long *h)
{
    if (!netpbm_expect_number(s, NETPBM_FIELD_WIDTH, kind->magic, w))
        return 0;
    if ((netpbm_peek(s) == 'x' || netpbm_peek(s) == 'X') &&
        s->pos + 1 < s->size && netpbm_is_digit(s->data[s->pos + 1])) {
        int separator = netpbm_peek(s);
        s->pos++;
        netpbm_read_number(s, h);
        NETPBM_FAIL(s, N_("the dimensions are written '%lu%c%lu'; Netpbm needs "
                       "two numbers separated by whitespace: '%lu %lu'"),
                    *w, separator, *h, *w, *h);
    } else if (!netpbm_expect_number(s, NETPBM_FIELD_HEIGHT, kind->magic, h)) {
        return 0;
    }
    if (*w == 0 || *h == 0 || *w > RAYO_MAX_DIMENSION ||
        *h > RAYO_MAX_DIMENSION ||
        (unsigned long long)*w * *h > RAYO_MAX_PIXELS) {
        NETPBM_FAIL(s, N_("the header promises a %lux%lu image, which no "
                       "reader accepts; the exercise asks for %ux%u"),
                    *w, *h, (unsigned)want_w, (unsigned)want_h);
        return 0;
    }
    if (*w == want_h && *h == want_w && want_w != want_h)
        NETPBM_FAIL(s, N_("the header says %lu %lu (width %lu, height %lu); "
                       "the exercise asks for %u %u: width and height are "
                       "swapped"),
                    *w, *h, *w, *h, (unsigned)want_w, (unsigned)want_h);
    else if (*w != want_w || *h != want_h)
        NETPBM_FAIL(s, N_("the header says %lux%lu; the exercise asks for "
                       "%ux%u"),
                    *w, *h, (unsigned)want_w, (unsigned)want_h);
    return 1;
}

/* "exactly 1 row missing", "2 rows and 3 pixels", "less than one row",
   in lang. */
static void describe_rows(rayo_lang lang, char *out, size_t room,
                          unsigned long long pixels, unsigned long w,
                          int more)
{
    unsigned long long rows = pixels / w, rest = pixels % w;
    char part[64];
    if (rows == 0)
        snprintf(out, room, "%s", rayo_gettext(lang, "less than one row"));
    else if (rest == 0 && more)
        snprintf(out, room,
                 rayo_ngettext(lang, "exactly %llu row too many",
                               "exactly %llu rows too many",
                               (unsigned long)rows),
                 rows);
    else if (rest == 0)
        snprintf(out, room,
                 rayo_ngettext(lang, "exactly %llu row missing",
                               "exactly %llu rows missing",
                               (unsigned long)rows),
                 rows);
    else {
        snprintf(part, sizeof part,
                 rayo_ngettext(lang, "%llu pixel", "%llu pixels",
                               (unsigned long)rest),
                 rest);
        snprintf(out, room,
                 rayo_ngettext(lang, "%llu row and %s", "%llu rows and %s",
                               (unsigned long)rows),
                 rows, part);
    }
}

void netpbm_say_count(netpbm_scan *s, const netpbm_kind *kind,
                      unsigned long w, unsigned long h,
                      unsigned long long samples)
{
    rayo_lang lang = rayo_error_lang(s->err);
    unsigned channels = kind->channels;
    unsigned long long pixels = (unsigned long long)w * h;
    unsigned long long want = pixels * channels;
    unsigned long long diff = samples > want ? samples - want
                                             : want - samples;
    unsigned long long whole = diff / channels, part = diff % channels;
    char rows_text[160], way[64], whole_text[64], part_text[64];
    if (diff == 0)
        return;
    describe_rows(lang, rows_text, sizeof rows_text, whole, w,
                  samples > want);
    if (samples > want)
        snprintf(way, sizeof way, rayo_gettext(lang, "%llu more"), diff);
    else
        snprintf(way, sizeof way, rayo_gettext(lang, "%llu fewer"), diff);
    snprintf(whole_text, sizeof whole_text,
             rayo_ngettext(lang, "%llu pixel", "%llu pixels",
                           (unsigned long)whole),
             whole);
    snprintf(part_text, sizeof part_text,
             rayo_ngettext(lang, "%llu number", "%llu numbers",
                           (unsigned long)part),
             part);
    if (kind->magic == '1')
        NETPBM_FAIL(s, N_("the header promises %lux%lu = %llu pixels but the "
                       "output has %llu: %s, %s"),
                    w, h, pixels, samples, way, rows_text);
    else if (channels == 1)
        NETPBM_FAIL(s, N_("the header promises %lux%lu = %llu pixels but the "
                       "output has %llu numbers: %s, %s"),
                    w, h, pixels, samples, way, rows_text);
    else if (part == 0)
        NETPBM_FAIL(s, N_("the header promises %lux%lu = %llu pixels of %u "
                       "numbers (R G B), %llu in all, but the output has "
                       "%llu: %s, %s, %s"),
                    w, h, pixels, channels, want, samples, way, whole_text,
                    rows_text);
    else if (whole == 0)
        NETPBM_FAIL(s, N_("the header promises %lux%lu = %llu pixels of %u "
                       "numbers (R G B), %llu in all, but the output has "
                       "%llu: %s, less than one pixel"),
                    w, h, pixels, channels, want, samples, way);
    else
        NETPBM_FAIL(s, N_("the header promises %lux%lu = %llu pixels of %u "
                       "numbers (R G B), %llu in all, but the output has "
                       "%llu: %s, not a whole number of pixels (%s and "
                       "%s)"),
                    w, h, pixels, channels, want, samples, way, whole_text,
                    part_text);
}

void netpbm_note_line_lengths(netpbm_scan *s)
{
    size_t i, length = 0, longest = 0;
    unsigned long line = 1, longest_line = 0, long_lines = 0;
    for (i = 0; i <= s->size; i++) {
        if (i == s->size || s->data[i] == '\n') {
            if (length > NETPBM_LINE_LIMIT) {
                long_lines++;
                if (length > longest) {
                    longest = length;
                    longest_line = line;
                }
            }
            length = 0;
            line++;
        } else if (s->data[i] != '\r') {
            length++;
        }
    }
    if (long_lines > 0)
        NETPBM_SAY(s,
                   rayo_ngettext(rayo_error_lang(s->err),
                                 "note: %lu line is longer than %d "
                                 "characters (the longest, line %lu, has "
                                 "%zu); Netpbm's format page asks for at "
                                 "most %d, but the statement lets the "
                                 "pixels be laid out freely and readers "
                                 "accept longer lines",
                                 "note: %lu lines are longer than %d "
                                 "characters (the longest, line %lu, has "
                                 "%zu); Netpbm's format page asks for at "
                                 "most %d, but the statement lets the "
                                 "pixels be laid out freely and readers "
                                 "accept longer lines",
                                 long_lines),
                   long_lines, NETPBM_LINE_LIMIT, longest_line, longest,
                   NETPBM_LINE_LIMIT);
}
