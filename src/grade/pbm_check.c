/*
 * pbm_check.c - the strict plain PBM checker (pbm_check.h): one pass
 * over the header and one over the raster, noting every deviation with
 * its line and column, then a single verdict on the pixel count.
 *
 * Positions are counted from 1 (line:column, as compilers and editors
 * do) and bytes from 0 (as the readers do).  What this file does not do
 * is decide whether the picture is right: that is compare's job.
 */
#include <stdio.h>
#include <string.h>

#include "rayo/limits.h"
#include "rayo/pbm_check.h"

#include "grade_impl.h"

#define NETPBM_LINE_LIMIT 70

typedef struct scan {
    const unsigned char *data;
    size_t size, pos;
    rayo_grade_item *item;
    rayo_error *err;
    rayo_status status; /* the first failure to record a line */
} scan;

static int is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
           c == '\f';
}

static int is_digit(int c)
{
    return c >= '0' && c <= '9';
}

static int peek(const scan *s)
{
    return s->pos < s->size ? s->data[s->pos] : -1;
}

/* Line and column (from 1) of a byte offset. */
static void where(const scan *s, size_t offset, unsigned long *line,
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

/* Up to 16 bytes from offset, printable, for quoting in a message. */
static void excerpt(const scan *s, size_t offset, char *out, size_t room)
{
    size_t i, n = 0;
    for (i = offset; i < s->size && i < offset + 16 && n + 5 < room; i++) {
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

#define FAIL(s, ...)                                                         \
    do {                                                                     \
        if ((s)->status == RAYO_OK)                                          \
            (s)->status = grade_fail((s)->item, (s)->err, __VA_ARGS__);      \
    } while (0)

#define SAY(s, ...)                                                          \
    do {                                                                     \
        if ((s)->status == RAYO_OK)                                          \
            (s)->status = grade_say((s)->item, (s)->err, __VA_ARGS__);       \
    } while (0)

/* Whitespace and '#' comments, as a header allows. */
static void skip_header_space(scan *s)
{
    while (s->pos < s->size) {
        int c = peek(s);
        if (c == '#') {
            while (s->pos < s->size && s->data[s->pos] != '\n')
                s->pos++;
        } else if (is_space(c)) {
            s->pos++;
        } else {
            break;
        }
    }
}

/* A decimal number; 0 when there is none here.  Saturates. */
static int read_number(scan *s, unsigned long *value)
{
    size_t start = s->pos;
    *value = 0;
    while (is_digit(peek(s))) {
        if (*value < 100000000ul)
            *value = *value * 10 + (unsigned long)(peek(s) - '0');
        s->pos++;
    }
    return s->pos > start;
}

static const char *other_format(const unsigned char *m)
{
    if (m[0] != 'P' && m[0] != 'p')
        return NULL;
    switch (m[1]) {
    case '2': return "plain PGM (gray)";
    case '3': return "plain PPM (colour)";
    case '4': return "raw PBM (binary)";
    case '5': return "raw PGM (gray, binary)";
    case '6': return "raw PPM (colour, binary)";
    }
    return NULL;
}

/* The magic number; 1 when the rest can be read as P1. */
static int check_magic(scan *s)
{
    static const unsigned char png[4] = {0x89, 'P', 'N', 'G'};
    char seen[80];
    size_t start = 0;
    while (start < s->size && is_space(s->data[start]))
        start++;
    if (start > 0 && start + 1 < s->size &&
        (s->data[start] == 'P' || s->data[start] == 'p'))
        FAIL(s, "the output begins with %zu whitespace character%s before "
                "the magic number; a PBM file must begin with 'P1' itself",
             start, start == 1 ? "" : "s");
    else
        start = 0;
    s->pos = start;
    if (s->size - start >= 4 && memcmp(s->data + start, png, 4) == 0) {
        FAIL(s, "the output is a PNG image; the exercise asks for plain "
                "PBM ('P1' and digits) on standard output");
        return 0;
    }
    if (s->size - start >= 2 && other_format(s->data + start) != NULL) {
        FAIL(s, "the magic number is '%c%c', %s; the exercise asks for "
                "plain PBM, 'P1'",
             s->data[start], s->data[start + 1],
             other_format(s->data + start));
        return 0;
    }
    if (s->size - start >= 2 && s->data[start] == 'p' &&
        s->data[start + 1] == '1') {
        FAIL(s, "the magic number is 'p1' in lowercase; Netpbm needs a "
                "capital 'P1', and viewers refuse the file");
    } else if (s->size - start < 2 || s->data[start] != 'P' ||
               s->data[start + 1] != '1') {
        excerpt(s, start, seen, sizeof seen);
        FAIL(s, "the output does not begin with the magic number 'P1'; it "
                "begins with '%s'",
             seen);
        return 0;
    }
    s->pos = start + 2;
    if (s->pos < s->size && !is_space(peek(s)) && peek(s) != '#')
        FAIL(s, "there is no whitespace after the magic number 'P1'");
    return 1;
}

static int expect_number(scan *s, const char *what, const char *after,
                         unsigned long *value)
{
    unsigned long line, column;
    char seen[80];
    skip_header_space(s);
    if (read_number(s, value))
        return 1;
    where(s, s->pos, &line, &column);
    excerpt(s, s->pos, seen, sizeof seen);
    if (s->pos >= s->size)
        FAIL(s, "the output ends before the %s (expected after %s)", what,
             after);
    else
        FAIL(s, "expected the %s after %s at line %lu, column %lu; found "
                "'%s'",
             what, after, line, column, seen);
    return 0;
}

/* Width and height; 1 when both could be read. */
static int check_dimensions(scan *s, uint32_t want_w, uint32_t want_h,
                            unsigned long *w, unsigned long *h)
{
    if (!expect_number(s, "width", "'P1'", w))
        return 0;
    if ((peek(s) == 'x' || peek(s) == 'X') && s->pos + 1 < s->size &&
        is_digit(s->data[s->pos + 1])) {
        int separator = peek(s);
        s->pos++;
        read_number(s, h);
        FAIL(s, "the dimensions are written '%lu%c%lu'; Netpbm needs two "
                "numbers separated by whitespace: '%lu %lu'",
             *w, separator, *h, *w, *h);
    } else if (!expect_number(s, "height", "the width", h)) {
        return 0;
    }
    if (*w == 0 || *h == 0 || *w > RAYO_MAX_DIMENSION ||
        *h > RAYO_MAX_DIMENSION ||
        (unsigned long long)*w * *h > RAYO_MAX_PIXELS) {
        FAIL(s, "the header promises a %lux%lu image, which no reader "
                "accepts; the exercise asks for %ux%u",
             *w, *h, (unsigned)want_w, (unsigned)want_h);
        return 0;
    }
    if (*w == want_h && *h == want_w && want_w != want_h)
        FAIL(s, "the header says %lu %lu (width %lu, height %lu); the "
                "exercise asks for %u %u: width and height are swapped",
             *w, *h, *w, *h, (unsigned)want_w, (unsigned)want_h);
    else if (*w != want_w || *h != want_h)
        FAIL(s, "the header says %lux%lu; the exercise asks for %ux%u",
             *w, *h, (unsigned)want_w, (unsigned)want_h);
    if (s->pos < s->size && !is_space(peek(s)))
        FAIL(s, "there is no whitespace between the height and the pixels");
    return 1;
}

typedef struct raster_tally {
    unsigned long long pixels, bad, comments;
    size_t first_bad, first_comment;
} raster_tally;

/* Walks the raster, filling image (when not NULL) with the first pixels. */
static void walk_raster(scan *s, rayo_image *image, raster_tally *t)
{
    unsigned long long limit =
        image != NULL ? (unsigned long long)image->info.width *
                            image->info.height
                      : 0;
    while (s->pos < s->size) {
        int c = s->data[s->pos];
        if (c == '0' || c == '1') {
            if (t->pixels < limit && c == '1')
                rayo_bit_set(rayo_image_row(image, (uint32_t)(
                                 t->pixels / image->info.width)),
                             (uint32_t)(t->pixels % image->info.width), 1);
            t->pixels++;
        } else if (c == '#') {
            if (t->comments++ == 0)
                t->first_comment = s->pos;
            while (s->pos + 1 < s->size && s->data[s->pos + 1] != '\n')
                s->pos++;
        } else if (!is_space(c)) {
            if (t->bad++ == 0)
                t->first_bad = s->pos;
        }
        s->pos++;
    }
}

static void say_count(scan *s, unsigned long w, unsigned long h,
                      unsigned long long pixels)
{
    unsigned long long want = (unsigned long long)w * h;
    unsigned long long diff = pixels > want ? pixels - want : want - pixels;
    unsigned long long rows = diff / w, rest = diff % w;
    const char *way = pixels > want ? "more" : "fewer";
    char rows_text[160];
    if (diff == 0)
        return;
    if (rows == 0)
        snprintf(rows_text, sizeof rows_text, "less than one row");
    else if (rest == 0)
        snprintf(rows_text, sizeof rows_text, "exactly %llu row%s %s",
                 rows, rows == 1 ? "" : "s",
                 pixels > want ? "too many" : "missing");
    else
        snprintf(rows_text, sizeof rows_text, "%llu row%s and %llu pixel%s",
                 rows, rows == 1 ? "" : "s", rest, rest == 1 ? "" : "s");
    FAIL(s, "the header promises %lux%lu = %llu pixels but the output has "
            "%llu: %llu %s, %s",
         w, h, want, pixels, diff, way, rows_text);
}

static void check_raster_tally(scan *s, const raster_tally *t)
{
    unsigned long line, column;
    char seen[80];
    if (t->bad > 0) {
        where(s, t->first_bad, &line, &column);
        excerpt(s, t->first_bad, seen, sizeof seen);
        FAIL(s, "%llu character%s in the pixels other than 0, 1 and "
                "whitespace; the first at line %lu, column %lu: '%s'",
             t->bad, t->bad == 1 ? "" : "s", line, column, seen);
    }
    if (t->comments > 0) {
        where(s, t->first_comment, &line, &column);
        FAIL(s, "a '#' comment among the pixels (line %lu); Netpbm allows "
                "comments only in the header",
             line);
    }
}

static void check_line_lengths(scan *s)
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
        SAY(s, "warning: %lu line%s longer than %d characters (the longest, "
               "line %lu, has %zu); Netpbm's format page asks for at most "
               "%d, though most viewers accept longer lines",
            long_lines, long_lines == 1 ? " is" : "s are",
            NETPBM_LINE_LIMIT, longest_line, longest, NETPBM_LINE_LIMIT);
}

rayo_status rayo_pbm_check(const void *data, size_t size, uint32_t width,
                           uint32_t height, rayo_grade_item *item,
                           rayo_image *image, rayo_error *err)
{
    scan s;
    unsigned long w = 0, h = 0;
    raster_tally tally;
    memset(image, 0, sizeof *image);
    memset(&tally, 0, sizeof tally);
    s.data = data;
    s.size = size;
    s.pos = 0;
    s.item = item;
    s.err = err;
    s.status = RAYO_OK;
    item->result = RAYO_GRADE_PASS;
    if (size == 0) {
        FAIL(&s, "the program wrote nothing on standard output; it must "
                 "write the image there (./programa > imagen.pbm)");
        return s.status;
    }
    if (!check_magic(&s))
        return s.status; /* not text PBM: line lengths mean nothing */
    if (check_dimensions(&s, width, height, &w, &h)) {
        rayo_image_info info = rayo_image_info_bit((uint32_t)w,
                                                   (uint32_t)h);
        rayo_status status = rayo_image_create(image, &info, err);
        if (status != RAYO_OK)
            return status;
        walk_raster(&s, image, &tally);
        check_raster_tally(&s, &tally);
        say_count(&s, w, h, tally.pixels);
    }
    check_line_lengths(&s);
    if (s.status == RAYO_OK && item->result == RAYO_GRADE_PASS)
        SAY(&s, "plain PBM (P1), %lux%lu, %llu pixels", w, h, tally.pixels);
    if (s.status != RAYO_OK)
        rayo_image_free(image);
    return s.status;
}
