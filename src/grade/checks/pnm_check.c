/*
 * pnm_check.c - the strict plain PGM (P2) and PPM (P3) checker of
 * exercises 2 and 3, and rayo_pnm_check, the entry point for all three
 * plain formats (pbm_check.h).
 *
 * The header is checked as for P1 (netpbm_scan.c) plus the maximum
 * value, which the statements fix at 255; the raster is read number by
 * number, and each kind of wrong number (above 255, exactly 256,
 * negative, with a decimal point) is counted, located (line, column,
 * pixel, channel) and explained by the mistake in the student's program
 * that usually produces it.  The pixels are salvaged, clamped to 0..255,
 * so that the picture can still be compared; a raw magic (P5, P6) or
 * the other plain one (P3 for P2) over a raster of text numbers is read
 * as what it evidently is, and the report says so.
 */
#include <stdio.h>
#include <string.h>

#include "rayo/pbm_check.h"

#include "netpbm_scan.h"
#include "rayo/lang.h"

#define STATEMENT_MAXVAL 255ul

/* The first of one kind of wrong number. */
typedef struct sample_note {
    unsigned long long count, index;
    size_t offset, length;
} sample_note;

typedef struct sample_tally {
    unsigned long long samples, bad, comments;
    size_t first_bad, first_comment;
    sample_note above, negative, fraction;
    sample_note int_min;    /* -2147483648: a NaN or overflow through (int) */
    unsigned long largest;  /* the largest sample, saturated */
    int over_one;           /* some sample is above 1 */
} sample_tally;

/* One number as the walk reads it. */
typedef struct sample {
    size_t offset, length;
    unsigned long value; /* the whole part, saturated */
    int negative, fraction, fraction_nonzero;
    int int_min; /* exactly -2147483648 */
} sample;

static const char *header_name(int magic)
{
    switch (magic) {
    case '2': return N_("plain PGM, gray");
    case '3': return N_("plain PPM, colour");
    case '5': return N_("raw, binary PGM");
    case '6': return N_("raw, binary PPM");
    }
    return "";
}

/*
 * Reads, without saying anything, a header (magic, width, height,
 * maxval) at s->pos and the raster after it: 1 when the raster is text
 * numbers (digits, signs, decimal points, whitespace), with how many.
 */
static int text_raster(const netpbm_scan *s, unsigned long *w,
                       unsigned long *h, unsigned long long *numbers)
{
    netpbm_scan look = *s;
    unsigned long maxval;
    int inside = 0;
    *numbers = 0;
    look.pos += 2;
    netpbm_skip_header_space(&look);
    if (!netpbm_read_number(&look, w))
        return 0;
    netpbm_skip_header_space(&look);
    if (!netpbm_read_number(&look, h))
        return 0;
    netpbm_skip_header_space(&look);
    if (!netpbm_read_number(&look, &maxval))
        return 0;
    for (; look.pos < look.size; look.pos++) {
        int c = look.data[look.pos];
        if (netpbm_is_digit(c)) {
            if (!inside)
                (*numbers)++;
            inside = 1;
        } else if (c == '.' && inside) {
            continue;
        } else if (c == '-' || netpbm_is_space(c)) {
            inside = 0;
        } else {
            return 0;
        }
    }
    return *numbers > 0;
}

/*
 * Another Netpbm magic at s->pos: 1 when the output is evidently the
 * kind asked for under a wrong magic (said so, and pos after it), else
 * 0 (nothing said).
 */
static int relabel(netpbm_scan *s, const netpbm_kind *kind)
{
    const unsigned char *m = s->data + s->pos;
    rayo_lang lang = rayo_error_lang(s->err);
    int other = kind->magic == '2' ? '3' : '2';
    unsigned long w, h;
    unsigned long long numbers;
    if (s->size - s->pos < 2 || !text_raster(s, &w, &h, &numbers))
        return 0;
    if (m[1] == kind->magic + 3) {
        NETPBM_FAIL(s, N_("the header says %c%c (%s) but the samples are "
                       "written as text: a text %s is P%c; the comparison "
                       "reads the numbers as P%c"),
                    m[0], m[1], rayo_gettext(lang, header_name(m[1])), kind->name, kind->magic,
                    kind->magic);
    } else if ((m[1] == other || m[1] == other + 3) &&
               numbers == (unsigned long long)w * h * kind->channels) {
        if (kind->channels == 1)
            NETPBM_FAIL(s, N_("the header says %c%c (%s) but the output has "
                           "1 number per pixel, written as text (%lux%lu "
                           "pixels, %llu numbers): a text gray image is a "
                           "%s, P%c; the comparison reads the numbers as "
                           "P%c"),
                        m[0], m[1], rayo_gettext(lang, header_name(m[1])), w,
                        h, numbers, kind->name, kind->magic, kind->magic);
        else
            NETPBM_FAIL(s, N_("the header says %c%c (%s) but the output has "
                           "%u numbers per pixel, written as text (%lux%lu "
                           "pixels, %llu numbers): a text colour image is a "
                           "%s, P%c; the comparison reads the numbers as "
                           "P%c"),
                        m[0], m[1], rayo_gettext(lang, header_name(m[1])),
                        kind->channels, w, h, numbers, kind->name,
                        kind->magic, kind->magic);
    } else {
        return 0;
    }
    s->pos += 2;
    return 1;
}

/* Reads one number at s->pos into n; 0 (pos unchanged) when none. */
static int read_sample(netpbm_scan *s, sample *n)
{
    size_t p = s->pos;
    memset(n, 0, sizeof *n);
    n->offset = p;
    if (p < s->size && s->data[p] == '-') {
        n->negative = 1;
        p++;
    }
    if (!(p < s->size && (netpbm_is_digit(s->data[p]) ||
                          (s->data[p] == '.' && p + 1 < s->size &&
                           netpbm_is_digit(s->data[p + 1])))))
        return 0;
    for (; p < s->size && netpbm_is_digit(s->data[p]); p++)
        if (n->value < 100000000ul)
            n->value = n->value * 10 + (unsigned long)(s->data[p] - '0');
    if (p < s->size && s->data[p] == '.') {
        n->fraction = 1;
        for (p++; p < s->size && netpbm_is_digit(s->data[p]); p++)
            if (s->data[p] != '0')
                n->fraction_nonzero = 1;
    }
    n->length = p - s->pos;
    n->int_min = n->length == 11 && !n->fraction &&
                 memcmp(s->data + s->pos, "-2147483648", 11) == 0;
    s->pos = p;
    return 1;
}

static void note(sample_note *note_, const sample *n,
                 unsigned long long index)
{
    if (note_->count++ == 0) {
        note_->index = index;
        note_->offset = n->offset;
        note_->length = n->length;
    }
}

/* Counts one number and puts it, clamped, in the image when it fits. */
static void take_sample(sample_tally *t, const sample *n,
                        rayo_image *image)
{
    unsigned long long index = t->samples++;
    unsigned long long row_samples =
        (unsigned long long)image->info.width * image->info.channels;
    unsigned long value = n->negative ? 0
                          : n->value > STATEMENT_MAXVAL ? STATEMENT_MAXVAL
                                                        : n->value;
    if (index < row_samples * image->info.height)
        rayo_image_row(image, (uint32_t)(index / row_samples))
            [index % row_samples] = (unsigned char)value;
    if (n->int_min)
        note(&t->int_min, n, index);
    else if (n->negative)
        note(&t->negative, n, index);
    else if (n->value > STATEMENT_MAXVAL)
        note(&t->above, n, index);
    if (n->fraction)
        note(&t->fraction, n, index);
    if (!n->negative && n->value > t->largest)
        t->largest = n->value;
    if (!n->negative && (n->value > 1 || (n->value == 1 &&
                                          n->fraction_nonzero)))
        t->over_one = 1;
}

/* Walks the raster from s->pos to the end, filling image. */
static void walk_samples(netpbm_scan *s, rayo_image *image, sample_tally *t)
{
    sample n;
    memset(t, 0, sizeof *t);
    while (s->pos < s->size) {
        int c = s->data[s->pos];
        if (netpbm_is_space(c)) {
            s->pos++;
        } else if (c == '#') {
            if (t->comments++ == 0)
                t->first_comment = s->pos;
            while (s->pos < s->size && s->data[s->pos] != '\n')
                s->pos++;
        } else if (read_sample(s, &n)) {
            take_sample(t, &n, image);
        } else {
            if (t->bad++ == 0)
                t->first_bad = s->pos;
            s->pos++;
        }
    }
}

/* "line 3, column 5 (pixel (1, 0), channel G)" for a noted number. */
static void describe(const netpbm_scan *s, const netpbm_kind *kind,
                     unsigned long w, unsigned long h,
                     const sample_note *n, char *out, size_t room)
{
    rayo_lang lang = rayo_error_lang(s->err);
    unsigned long line, column;
    unsigned long long pixel = n->index / kind->channels;
    netpbm_where(s, n->offset, &line, &column);
    if (pixel >= (unsigned long long)w * h)
        snprintf(out, room,
                 rayo_gettext(lang, "line %lu, column %lu (after the last "
                                    "pixel)"),
                 line, column);
    else if (kind->channels == 3)
        snprintf(out, room,
                 rayo_gettext(lang, "line %lu, column %lu (pixel (%llu, "
                                    "%llu), channel %c)"),
                 line, column, pixel % w, pixel / w,
                 "RGB"[n->index % 3]);
    else
        snprintf(out, room,
                 rayo_gettext(lang, "line %lu, column %lu (pixel (%llu, "
                                    "%llu))"),
                 line, column, pixel % w, pixel / w);
}

static void say_wrong_numbers(netpbm_scan *s, const netpbm_kind *kind,
                              unsigned long w, unsigned long h,
                              const sample_tally *t)
{
    rayo_lang lang = rayo_error_lang(s->err);
    char at[160], seen[80];
    const sample_note *n = &t->above;
    if (n->count > 0) {
        describe(s, kind, w, h, n, at, sizeof at);
        netpbm_excerpt(s, n->offset, n->length, seen, sizeof seen);
        if (kind->channels == 3 && t->largest == STATEMENT_MAXVAL + 1)
            NETPBM_FAIL(s,
                        rayo_ngettext(lang,
                                      "%llu number is 256, none above; the "
                                      "first at %s: 0..1 scaled by 256 "
                                      "instead of 255 (a full channel, 1, "
                                      "prints as 255); the comparison takes "
                                      "it as 255",
                                      "%llu numbers are 256, none above; the "
                                      "first at %s: 0..1 scaled by 256 "
                                      "instead of 255 (a full channel, 1, "
                                      "prints as 255); the comparison takes "
                                      "them as 255",
                                      (unsigned long)n->count),
                        n->count, at);
        else if (kind->channels == 3)
            NETPBM_FAIL(s,
                        rayo_ngettext(lang,
                                      "%llu number above 255; the first, "
                                      "'%s', at %s: values above 255 are not "
                                      "clamped (the statement: each channel "
                                      "above 1 becomes 1, printed as 255); "
                                      "the comparison takes it as 255",
                                      "%llu numbers above 255; the first, "
                                      "'%s', at %s: values above 255 are not "
                                      "clamped (the statement: each channel "
                                      "above 1 becomes 1, printed as 255); "
                                      "the comparison takes them as 255",
                                      (unsigned long)n->count),
                        n->count, seen, at);
        else
            NETPBM_FAIL(s,
                        rayo_ngettext(lang,
                                      "%llu number above 255; the first, "
                                      "'%s', at %s: values above 255 are not "
                                      "clamped (the statement: values above "
                                      "255 become 255); the comparison takes "
                                      "it as 255",
                                      "%llu numbers above 255; the first, "
                                      "'%s', at %s: values above 255 are not "
                                      "clamped (the statement: values above "
                                      "255 become 255); the comparison takes "
                                      "them as 255",
                                      (unsigned long)n->count),
                        n->count, seen, at);
    }
    n = &t->negative;
    if (n->count > 0) {
        describe(s, kind, w, h, n, at, sizeof at);
        netpbm_excerpt(s, n->offset, n->length, seen, sizeof seen);
        NETPBM_FAIL(s,
                    rayo_ngettext(lang,
                                  "%llu negative number; the first, '%s', at "
                                  "%s: a negative intensity: the diffuse "
                                  "term is added where L.N < 0 (the "
                                  "statement adds it only when L.N > 0); the "
                                  "comparison takes it as 0",
                                  "%llu negative numbers; the first, '%s', "
                                  "at %s: a negative intensity: the diffuse "
                                  "term is added where L.N < 0 (the "
                                  "statement adds it only when L.N > 0); the "
                                  "comparison takes them as 0",
                                  (unsigned long)n->count),
                    n->count, seen, at);
    }
    n = &t->int_min;
    if (n->count > 0) {
        describe(s, kind, w, h, n, at, sizeof at);
        NETPBM_FAIL(s,
                    rayo_ngettext(lang,
                                  "%llu number is -2147483648, the first at "
                                  "%s: that is what a NaN (not a number) or "
                                  "a value past the int range becomes "
                                  "through (int), not an intensity; look for "
                                  "0/0, the square root of a negative "
                                  "discriminant or a normal of length 0; the "
                                  "comparison takes it as 0",
                                  "%llu numbers are -2147483648, the first "
                                  "at %s: that is what a NaN (not a number) "
                                  "or a value past the int range becomes "
                                  "through (int), not an intensity; look for "
                                  "0/0, the square root of a negative "
                                  "discriminant or a normal of length 0; the "
                                  "comparison takes them as 0",
                                  (unsigned long)n->count),
                    n->count, at);
    }
    n = &t->fraction;
    if (n->count > 0) {
        describe(s, kind, w, h, n, at, sizeof at);
        netpbm_excerpt(s, n->offset, n->length, seen, sizeof seen);
        if (kind->channels == 3 && !t->over_one)
            NETPBM_FAIL(s,
                        rayo_ngettext(lang,
                                      "%llu number with a decimal point; the "
                                      "first, '%s', at %s: printed with %%f "
                                      "instead of %%d? The comparison takes "
                                      "its whole part; every number is "
                                      "between 0 and 1: the channels were "
                                      "not scaled to 0..255",
                                      "%llu numbers with a decimal point; the "
                                      "first, '%s', at %s: printed with %%f "
                                      "instead of %%d? The comparison takes "
                                      "their whole part; every number is "
                                      "between 0 and 1: the channels were "
                                      "not scaled to 0..255",
                                      (unsigned long)n->count),
                        n->count, seen, at);
        else
            NETPBM_FAIL(s,
                        rayo_ngettext(lang,
                                      "%llu number with a decimal point; the "
                                      "first, '%s', at %s: printed with %%f "
                                      "instead of %%d? The comparison takes "
                                      "its whole part",
                                      "%llu numbers with a decimal point; the "
                                      "first, '%s', at %s: printed with %%f "
                                      "instead of %%d? The comparison takes "
                                      "their whole part",
                                      (unsigned long)n->count),
                        n->count, seen, at);
    }
}

static void say_tally(netpbm_scan *s, const netpbm_kind *kind,
                      unsigned long w, unsigned long h,
                      const sample_tally *t)
{
    unsigned long line, column;
    char seen[80];
    if (t->bad > 0) {
        netpbm_where(s, t->first_bad, &line, &column);
        netpbm_excerpt(s, t->first_bad, 16, seen, sizeof seen);
        NETPBM_FAIL(s,
                    rayo_ngettext(rayo_error_lang(s->err),
                                  "%llu character among the numbers other "
                                  "than digits and whitespace; the first at "
                                  "line %lu, column %lu: '%s'",
                                  "%llu characters among the numbers other "
                                  "than digits and whitespace; the first at "
                                  "line %lu, column %lu: '%s'",
                                  (unsigned long)t->bad),
                    t->bad, line, column, seen);
    }
    if (t->comments > 0) {
        netpbm_where(s, t->first_comment, &line, &column);
        NETPBM_FAIL(s,
                    rayo_ngettext(rayo_error_lang(s->err),
                                  "%llu '#' comment among the numbers (the "
                                  "first at line %lu); Netpbm allows "
                                  "comments only in the header",
                                  "%llu '#' comments among the numbers (the "
                                  "first at line %lu); Netpbm allows "
                                  "comments only in the header",
                                  (unsigned long)t->comments),
                    t->comments, line);
    }
    say_wrong_numbers(s, kind, w, h, t);
    netpbm_say_count(s, kind, w, h, t->samples);
}

/*
 * The maximum value, and the raster after it.  A number other than 255
 * followed by one number too few is the first pixel's: the line '255'
 * was left out.  0 when there is no number where the maximum value goes.
 */
static int check_maxval_and_raster(netpbm_scan *s, const netpbm_kind *kind,
                                    unsigned long w, unsigned long h,
                                    rayo_image *image, sample_tally *t)
{
    unsigned long maxval, line, column;
    unsigned long long want = (unsigned long long)w * h * kind->channels;
    size_t at;
    netpbm_skip_header_space(s);
    at = s->pos;
    if (!netpbm_expect_number(s, NETPBM_FIELD_MAXVAL, kind->magic,
                              &maxval))
        return 0;
    if (s->pos < s->size && !netpbm_is_space(netpbm_peek(s)))
        NETPBM_FAIL(s, N_("there is no whitespace between the maximum value "
                       "and the numbers"));
    walk_samples(s, image, t);
    if (maxval == STATEMENT_MAXVAL)
        return 1;
    netpbm_where(s, at, &line, &column);
    if (t->samples + 1 == want) {
        NETPBM_FAIL(s, N_("the header has no maximum value: after the height "
                       "comes %lu (line %lu, column %lu), and as the "
                       "maximum value it would leave one number missing, "
                       "so it is the first pixel's; the header must end "
                       "with 255 ('P%c', width, height, 255)"),
                    maxval, line, column, kind->magic);
        memset(image->pixels, 0, image->stride * image->info.height);
        s->pos = at;
        walk_samples(s, image, t);
    } else {
        NETPBM_FAIL(s, N_("the maximum value is %lu (line %lu, column %lu); "
                       "the statement says it is always 255"),
                    maxval, line, column);
    }
    return 1;
}

void netpbm_check_p2_p3(netpbm_scan *s, const netpbm_kind *kind,
                        uint32_t width, uint32_t height, rayo_image *image)
{
    unsigned long w = 0, h = 0;
    sample_tally tally;
    rayo_image_info info;
    netpbm_magic magic = netpbm_check_magic(s, kind);
    memset(&tally, 0, sizeof tally);
    if (magic == NETPBM_MAGIC_OTHER && !relabel(s, kind)) {
        netpbm_refuse_other(s, kind);
        return; /* another format: the readers may know it */
    }
    if (magic == NETPBM_MAGIC_REFUSED)
        return;
    if (netpbm_check_dimensions(s, kind, width, height, &w, &h)) {
        info = kind->channels == 3
                   ? rayo_image_info_rgb8((uint32_t)w, (uint32_t)h)
                   : rayo_image_info_gray8((uint32_t)w, (uint32_t)h);
        if (s->status == RAYO_OK)
            s->status = rayo_image_create(image, &info, s->err);
        if (s->status != RAYO_OK)
            return;
        if (check_maxval_and_raster(s, kind, w, h, image, &tally))
            say_tally(s, kind, w, h, &tally);
        else
            rayo_image_free(image); /* no header to read pixels by */
    }
    netpbm_note_line_lengths(s);
    if (s->item->result != RAYO_GRADE_PASS)
        return;
    if (kind->channels == 3)
        NETPBM_SAY(s, N_("plain PPM (P3), %lux%lu, maxval 255, %llu pixels "
                      "(%llu numbers)"),
                   w, h, tally.samples / 3, tally.samples);
    else
        NETPBM_SAY(s, N_("plain PGM (P2), %lux%lu, maxval 255, %llu pixels"), w,
                   h, tally.samples);
}

rayo_status rayo_pnm_check(const void *data, size_t size, char magic,
                           uint32_t width, uint32_t height,
                           rayo_grade_item *item, rayo_image *image,
                           rayo_error *err)
{
    const netpbm_kind *kind = netpbm_kind_of(magic);
    netpbm_scan s;
    memset(image, 0, sizeof *image);
    if (kind == NULL)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "pnm check: the magic must be '1', '2' or "
                              "'3'");
    s.data = data;
    s.size = size;
    s.pos = 0;
    s.item = item;
    s.err = err;
    s.status = RAYO_OK;
    item->result = RAYO_GRADE_PASS;
    if (size == 0)
        NETPBM_FAIL(&s, N_("the program wrote nothing on standard output; it "
                        "must write the image there (./programa > %s)"),
                    kind->file);
    else if (magic == '1')
        netpbm_check_p1(&s, width, height, image);
    else
        netpbm_check_p2_p3(&s, kind, width, height, image);
    if (s.status != RAYO_OK)
        rayo_image_free(image);
    return s.status;
}
