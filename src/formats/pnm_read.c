/*
 * pnm_read.c - reading Netpbm images: PBM, PGM and PPM, plain (P1-P3)
 * and raw (P4-P6).
 *
 * Tolerant where Netpbm's format pages and tools are: comments from '#'
 * to the end of the line anywhere in the header (and between samples of a
 * plain raster), any amount of whitespace between header values.  Strict
 * about the raster: every sample present, none over maxval, nothing but
 * digits, whitespace and comments in a plain raster.  The header is
 * checked against limits.h, and against the bytes left in a regular file
 * or in memory, before the image is allocated.
 *
 * Plain PBM has a tight loop of its own that works on the source's
 * window directly: it is the format of the assignment and of the large
 * images `rayo compare` reads.  Not a writer (pnm_write.c), and not a
 * reader of PAM (P7) or of more than the first image in a file; what
 * follows the first image is only looked at, to say whether it is more
 * samples (a row too many) or whitespace.
 */
#include <stdio.h>
#include <string.h>

#include "rayo/lang.h"
#include "rayo/limits.h"
#include "reader_impl.h"

typedef struct pnm_reader {
    rayo_source *src;
    int digit;       /* '1'..'6' */
    uint64_t line;   /* 1-based line of the cursor (plain and header) */
    uint64_t value_offset, value_line; /* where the last header value began */
    uint32_t width, height;
    unsigned maxval; /* 1 for PBM */
    unsigned channels;
    int clamp;       /* plain samples out of range clamped, counted */
    rayo_read_report *report;
} pnm_reader;

static int is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
           c == '\f';
}

static const char *magic_name(int digit)
{
    static const char *const names[] = {"P1", "P2", "P3", "P4", "P5", "P6"};
    return names[digit - '1'];
}

/* "FILE: byte N (line L): found X; expected WHAT" at the byte before the
   cursor. */
static rayo_status found_error(const pnm_reader *r, rayo_status status,
                               int c, const char *expected, rayo_error *err)
{
    char found[32];
    uint64_t offset = rayo_source_offset(r->src);
    if (c >= 0 && offset > 0)
        offset--;
    if (c < 0 && r->src->read_errno != 0)
        return rayo_source_end_error(r->src, expected, err);
    if (c < 0) /* a whole sentence, for its translation */
        return rayo_error_set(err, status,
                              "%s: byte %llu (line %llu): found the end of "
                              "the file; expected %s",
                              r->src->name, (unsigned long long)offset,
                              (unsigned long long)r->line,
                              rayo_gettext(rayo_error_lang(err), expected));
    return rayo_error_set(err, status,
                          "%s: byte %llu (line %llu): found %s; expected %s",
                          r->src->name, (unsigned long long)offset,
                          (unsigned long long)r->line,
                          rayo_source_describe(c, found, sizeof found),
                          rayo_gettext(rayo_error_lang(err), expected));
}

/* The next character with comments folded into the newline ending them. */
static int header_getc(pnm_reader *r)
{
    int c = rayo_source_getc(r->src);
    if (c == '#') {
        do
            c = rayo_source_getc(r->src);
        while (c >= 0 && c != '\n' && c != '\r');
    }
    if (c == '\n')
        r->line++;
    return c;
}

/*
 * Reads one header value: skips whitespace and comments, takes decimal
 * digits, and consumes the single character after them, which must be
 * whitespace (or a comment).  Values past 2^32 saturate (*overflow).
 */
static rayo_status read_header_number(pnm_reader *r, const char *what,
                                      uint64_t *value, rayo_error *err)
{
    char expected[96];
    int c;
    do
        c = header_getc(r);
    while (is_space(c));
    snprintf(expected, sizeof expected, "the %s (a decimal number)", what);
    if (c < '0' || c > '9')
        return found_error(r, RAYO_ERR_FORMAT, c, expected, err);
    r->value_offset = rayo_source_offset(r->src) - 1;
    r->value_line = r->line;
    *value = 0;
    while (c >= '0' && c <= '9') {
        if (*value <= UINT32_MAX)
            *value = *value * 10 + (uint64_t)(c - '0');
        c = header_getc(r);
    }
    if (!is_space(c)) {
        snprintf(expected, sizeof expected,
                 "whitespace after the %s", what);
        return found_error(r, RAYO_ERR_FORMAT, c, expected, err);
    }
    return RAYO_OK;
}

/* "FILE: byte N (line L): found WHAT VALUE; expected ..." for the last
   header value read; values past 2^32 are shown as "over 4294967295". */
static rayo_status value_error(const pnm_reader *r, rayo_status status,
                               const char *what, uint64_t value,
                               const char *expected, rayo_error *err)
{
    char shown[32];
    if (value > UINT32_MAX)
        snprintf(shown, sizeof shown, "over 4294967295");
    else
        snprintf(shown, sizeof shown, "%llu", (unsigned long long)value);
    return rayo_error_set(err, status,
                          "%s: byte %llu (line %llu): found %s %s in the %s "
                          "header; expected %s",
                          r->src->name, (unsigned long long)r->value_offset,
                          (unsigned long long)r->value_line, what, shown,
                          magic_name(r->digit), expected);
}

static rayo_status check_size(const pnm_reader *r, const char *what,
                              uint64_t value, rayo_error *err)
{
    if (value == 0)
        return value_error(r, RAYO_ERR_FORMAT, what, value,
                           "1 to 65536 pixels", err);
    if (value > RAYO_MAX_DIMENSION)
        return value_error(r, RAYO_ERR_LIMIT, what, value,
                           "at most 65536 pixels", err);
    return RAYO_OK;
}

static rayo_status read_header(pnm_reader *r, rayo_error *err)
{
    uint64_t width, height, maxval = 1;
    rayo_status status = read_header_number(r, "width", &width, err);
    if (status == RAYO_OK)
        status = check_size(r, "width", width, err);
    if (status == RAYO_OK)
        status = read_header_number(r, "height", &height, err);
    if (status == RAYO_OK)
        status = check_size(r, "height", height, err);
    if (status != RAYO_OK)
        return status;
    if (width * height > RAYO_MAX_PIXELS)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "%s: byte %llu (line %llu): found %llux%llu = "
                              "%llu pixels in the %s header; expected at "
                              "most %lu (2^30)",
                              r->src->name,
                              (unsigned long long)r->value_offset,
                              (unsigned long long)r->value_line,
                              (unsigned long long)width,
                              (unsigned long long)height,
                              (unsigned long long)(width * height),
                              magic_name(r->digit), RAYO_MAX_PIXELS);
    if (r->digit != '1' && r->digit != '4') {
        status = read_header_number(r, "maxval", &maxval, err);
        if (status != RAYO_OK)
            return status;
        if (maxval < 1 || maxval > 65535)
            return value_error(r, RAYO_ERR_FORMAT, "maxval", maxval,
                               "1 to 65535", err);
    }
    r->width = (uint32_t)width;
    r->height = (uint32_t)height;
    r->maxval = (unsigned)maxval;
    r->channels = (r->digit == '3' || r->digit == '6') ? 3 : 1;
    return RAYO_OK;
}

static rayo_image_info layout_of(const pnm_reader *r)
{
    rayo_image_info info;
    info.width = r->width;
    info.height = r->height;
    info.channels = r->channels;
    info.maxval = r->maxval;
    if (r->digit == '1' || r->digit == '4')
        info.sample = RAYO_SAMPLE_BIT;
    else
        info.sample = r->maxval <= 255 ? RAYO_SAMPLE_U8 : RAYO_SAMPLE_U16;
    return info;
}

/* Bytes of one raw row as stored in the file. */
static uint64_t raw_row_bytes(const pnm_reader *r)
{
    if (r->digit == '4')
        return ((uint64_t)r->width + 7) / 8;
    return (uint64_t)r->width * r->channels * (r->maxval > 255 ? 2 : 1);
}

/* The fewest bytes a raster of this header can take. */
static uint64_t least_raster_bytes(const pnm_reader *r)
{
    uint64_t samples = (uint64_t)r->width * r->height * r->channels;
    switch (r->digit) {
    case '1':
        return samples;
    case '2':
    case '3':
        return 2 * samples - 1;
    default:
        return raw_row_bytes(r) * r->height;
    }
}

static rayo_status check_room(const pnm_reader *r, rayo_error *err)
{
    uint64_t remaining, needed = least_raster_bytes(r);
    if (!rayo_source_remaining(r->src, &remaining) || remaining >= needed)
        return RAYO_OK;
    return rayo_error_set(err, RAYO_ERR_FORMAT,
                          "%s: byte %llu: found %llu bytes of raster; "
                          "expected %s%llu for a %lux%lu %s%s",
                          r->src->name,
                          (unsigned long long)rayo_source_offset(r->src),
                          (unsigned long long)remaining,
                          r->digit <= '3' ? "at least " : "",
                          (unsigned long long)needed,
                          (unsigned long)r->width, (unsigned long)r->height,
                          magic_name(r->digit),
                          r->maxval > 255 ? " with 16-bit samples" : "");
}

/* Clears the bits after the last pixel of a BIT row. */
static void clear_padding(unsigned char *row, uint32_t width)
{
    if (width & 7)
        row[width >> 3] &= (unsigned char)(0xFFu << (8 - (width & 7)));
}

static rayo_status skip_comment(pnm_reader *r)
{
    int c;
    do
        c = rayo_source_getc(r->src);
    while (c >= 0 && c != '\n' && c != '\r');
    if (c == '\n')
        r->line++;
    return RAYO_OK;
}

/* Eight pixels from p[0..7] as a byte (p[0] in the top bit), or -1 when
 * the eight bytes are not all '0' or '1' (whitespace, a comment, an
 * error: the byte-by-byte loop deals with those). */
static int eight_pixels(const unsigned char *p)
{
    uint64_t v = (uint64_t)p[0] << 56 | (uint64_t)p[1] << 48 |
                 (uint64_t)p[2] << 40 | (uint64_t)p[3] << 32 |
                 (uint64_t)p[4] << 24 | (uint64_t)p[5] << 16 |
                 (uint64_t)p[6] << 8 | (uint64_t)p[7];
    if ((v & 0xFEFEFEFEFEFEFEFEull) != 0x3030303030303030ull)
        return -1;
    /* bit 0 of each byte gathered into the top byte, p[0] first */
    return (int)(((v & 0x0101010101010101ull) * 0x0102040810204080ull) >>
                 56);
}

/*
 * Plain PBM: the hot loop.  Works on the source's window in place,
 * packing eight pixels into a byte at a time: eight digits in a row
 * (rayo and the Netpbm tools write lines of 70 without spaces) are
 * taken at once, anything else one byte at a time.
 */
static rayo_status read_plain_pbm(pnm_reader *r, rayo_image *image,
                                  rayo_error *err)
{
    rayo_source *src = r->src;
    const uint32_t width = r->width;
    uint32_t x = 0, y = 0;
    unsigned acc = 0;
    unsigned char *row = rayo_image_row(image, 0);
    while (y < r->height) {
        const unsigned char *p = src->next, *end = src->end;
        if (p == end) {
            if (!rayo_source_refill(src))
                return found_error(r, RAYO_ERR_FORMAT, -1,
                                   "more pixels (0 or 1)", err);
            continue;
        }
        while (p < end) {
            unsigned c;
            int eight;
            if (end - p >= 8 && width - x > 8 &&
                (eight = eight_pixels(p)) >= 0) {
                /* acc holds the x & 7 pixels not yet stored */
                acc = (acc << 8) | (unsigned)eight;
                x += 8;
                row[(x >> 3) - 1] = (unsigned char)(acc >> (x & 7));
                acc &= (1u << (x & 7)) - 1;
                p += 8;
                continue;
            }
            c = *p++;
            if ((c | 1u) == '1') {
                acc = (acc << 1) | (c & 1u);
                x++;
                if ((x & 7) == 0) {
                    row[(x >> 3) - 1] = (unsigned char)acc;
                    acc = 0;
                }
                if (x == width) {
                    if (x & 7)
                        row[x >> 3] = (unsigned char)(acc << (8 - (x & 7)));
                    acc = 0;
                    x = 0;
                    if (++y == r->height)
                        break;
                    row += image->stride;
                }
            } else if (c == '\n') {
                r->line++;
            } else if (c == '#') {
                src->next = p;
                skip_comment(r);
                p = src->next;
                end = src->end;
            } else if (!is_space((int)c)) {
                src->next = p;
                return found_error(r, RAYO_ERR_FORMAT, (int)c,
                                   "0 or 1 (a PBM pixel)", err);
            }
        }
        src->next = p;
    }
    return RAYO_OK;
}

static void store_sample(rayo_image *image, unsigned char *row, size_t index,
                         unsigned value)
{
    if (image->info.sample == RAYO_SAMPLE_U8) {
        row[index] = (unsigned char)value;
    } else {
        uint16_t v = (uint16_t)value;
        memcpy(row + 2 * index, &v, sizeof v);
    }
}

/* One decimal sample of a plain PGM/PPM raster, at most maxval. */
/* A sample out of range, read with clamping: counted, taken as 0 or
   maxval. */
static rayo_status clamped(pnm_reader *r, int negative, uint64_t v,
                           unsigned *value)
{
    rayo_read_report *rp = r->report;
    long found = (long)(v > 65536 ? 65536 : v);
    if (negative) {
        found = -found;
        if (rp->clamped_low++ == 0)
            rp->first_low_line = r->line;
        if (found < rp->smallest_found)
            rp->smallest_found = found;
        *value = 0;
    } else {
        if (rp->clamped_high++ == 0)
            rp->first_high_line = r->line;
        if (found > rp->largest_found)
            rp->largest_found = found;
        *value = r->maxval;
    }
    return RAYO_OK;
}

static rayo_status read_plain_sample(pnm_reader *r, unsigned *value,
                                     rayo_error *err)
{
    char expected[64];
    int c, negative = 0;
    uint64_t v = 0;
    for (;;) {
        c = rayo_source_getc(r->src);
        if (c == '#')
            skip_comment(r);
        else if (c == '\n')
            r->line++;
        else if (!is_space(c))
            break;
    }
    if (c == '-' && r->clamp && r->digit != '1') {
        int d = rayo_source_peek(r->src);
        if (d >= '0' && d <= '9') {
            negative = 1;
            c = rayo_source_getc(r->src);
        }
    }
    if (c < '0' || c > '9') {
        /* Only here: a message formatted per sample was a fifth of
           reading a plain PPM. */
        snprintf(expected, sizeof expected, "a sample from 0 to %u",
                 r->maxval);
        return found_error(r, RAYO_ERR_FORMAT, c, expected, err);
    }
    while (c >= '0' && c <= '9') {
        if (v <= 65536)
            v = v * 10 + (uint64_t)(c - '0');
        c = rayo_source_peek(r->src);
        if (c >= '0' && c <= '9')
            rayo_source_getc(r->src);
    }
    if (c >= 0 && !is_space(c) && c != '#') {
        rayo_source_getc(r->src);
        return found_error(r, RAYO_ERR_FORMAT, c,
                           "whitespace after a sample", err);
    }
    if (r->clamp && (negative || v > r->maxval))
        return clamped(r, negative, v, value);
    if (v > r->maxval) {
        char found[48];
        snprintf(found, sizeof found, "%s%llu", v > 65535 ? "over " : "",
                 (unsigned long long)(v > 65535 ? 65535 : v));
        return rayo_error_set(err, RAYO_ERR_FORMAT,
                              "%s: byte %llu (line %llu): found sample %s; "
                              "expected 0 to maxval %u",
                              r->src->name,
                              (unsigned long long)rayo_source_offset(r->src),
                              (unsigned long long)r->line, found, r->maxval);
    }
    *value = (unsigned)v;
    return RAYO_OK;
}

static rayo_status read_plain_samples(pnm_reader *r, rayo_image *image,
                                      rayo_error *err)
{
    size_t per_row = (size_t)r->width * r->channels;
    uint32_t y;
    for (y = 0; y < r->height; y++) {
        unsigned char *row = rayo_image_row(image, y);
        size_t i;
        for (i = 0; i < per_row; i++) {
            unsigned v = 0;
            rayo_status status = read_plain_sample(r, &v, err);
            if (status != RAYO_OK)
                return status;
            store_sample(image, row, i, v);
        }
    }
    return RAYO_OK;
}

static rayo_status raw_row_short(const pnm_reader *r, uint32_t y,
                                 rayo_error *err)
{
    char expected[96];
    snprintf(expected, sizeof expected, "the rest of raster row %lu of %lu",
             (unsigned long)y + 1, (unsigned long)r->height);
    return rayo_source_end_error(r->src, expected, err);
}

static rayo_status sample_over_maxval(const pnm_reader *r, uint64_t offset,
                                      unsigned value, rayo_error *err)
{
    return rayo_error_set(err, RAYO_ERR_FORMAT,
                          "%s: byte %llu: found sample %u; expected 0 to "
                          "maxval %u",
                          r->src->name, (unsigned long long)offset, value,
                          r->maxval);
}

/* Turns a row of big-endian 16-bit samples into native ones, checking. */
static rayo_status convert_row16(const pnm_reader *r, unsigned char *row,
                                 size_t samples, uint64_t row_offset,
                                 rayo_error *err)
{
    size_t i;
    for (i = 0; i < samples; i++) {
        unsigned char *p = row + 2 * i;
        uint16_t v = (uint16_t)((p[0] << 8) | p[1]);
        if (v > r->maxval)
            return sample_over_maxval(r, row_offset + 2 * i, v, err);
        memcpy(p, &v, sizeof v);
    }
    return RAYO_OK;
}

static rayo_status check_row8(const pnm_reader *r, const unsigned char *row,
                              size_t samples, uint64_t row_offset,
                              rayo_error *err)
{
    size_t i;
    if (r->maxval == 255)
        return RAYO_OK;
    for (i = 0; i < samples; i++)
        if (row[i] > r->maxval)
            return sample_over_maxval(r, row_offset + i, row[i], err);
    return RAYO_OK;
}

static rayo_status read_raw(pnm_reader *r, rayo_image *image,
                            rayo_error *err)
{
    size_t row_bytes = (size_t)raw_row_bytes(r);
    size_t samples = (size_t)r->width * r->channels;
    uint32_t y;
    for (y = 0; y < r->height; y++) {
        unsigned char *row = rayo_image_row(image, y);
        uint64_t row_offset = rayo_source_offset(r->src);
        rayo_status status = RAYO_OK;
        size_t got;
        rayo_source_read(r->src, row, row_bytes, &got);
        if (got < row_bytes)
            return raw_row_short(r, y, err);
        if (r->digit == '4')
            clear_padding(row, r->width);
        else if (r->maxval > 255)
            status = convert_row16(r, row, samples, row_offset, err);
        else
            status = check_row8(r, row, samples, row_offset, err);
        if (status != RAYO_OK)
            return status;
    }
    return RAYO_OK;
}

/* After a plain raster: whitespace and comments are not trailing data. */
static void skip_final_space(pnm_reader *r)
{
    for (;;) {
        int c = rayo_source_peek(r->src);
        if (c == '#')
            skip_comment(r);
        else if (is_space(c))
            rayo_source_getc(r->src);
        else
            return;
    }
}

/* Whole samples in n raw bytes after the raster (reader.h). */
static uint64_t raw_samples(const pnm_reader *r, uint64_t n)
{
    if (r->digit == '4') {
        uint64_t row = raw_row_bytes(r), rest = n % row;
        return n / row * r->width +
               (rest * 8 < r->width ? rest * 8 : r->width);
    }
    return n / (r->maxval > 255 ? 2 : 1);
}

/*
 * What follows the raster: reads up to RAYO_TRAILING_SCAN_BYTES bytes,
 * counting them in report->trailing_bytes, and fills trailing_samples
 * and trailing_data as reader.h says.  A plain tail is read the way a
 * raster is: whitespace and comments separate samples and are not data.
 */
static rayo_status scan_trailing(pnm_reader *r, rayo_read_report *report,
                                 rayo_error *err)
{
    const int plain = r->digit <= '3';
    uint64_t scanned = 0, samples = 0, data = 0;
    int counting = 1, in_number = 0, in_comment = 0;
    int lead[2] = {-1, -1}; /* the first two bytes after whitespace */
    while (scanned < RAYO_TRAILING_SCAN_BYTES) {
        int c = rayo_source_getc(r->src);
        if (c < 0)
            break;
        scanned++;
        if (in_comment) {
            in_comment = c != '\n' && c != '\r';
            continue;
        }
        if (is_space(c) || (plain && c == '#')) {
            if (in_number)
                samples++;
            in_number = 0;
            in_comment = c == '#';
            continue;
        }
        if (data < 2)
            lead[data] = c;
        data++;
        if (!plain || !counting)
            continue;
        if (c >= '0' && c <= (r->digit == '1' ? '1' : '9')) {
            if (r->digit == '1')
                samples++;
            else
                in_number = 1;
        } else {
            counting = 0; /* "12x": that was not a sample either */
            in_number = 0;
        }
    }
    if (in_number)
        samples++;
    if (!plain && data > 0 &&
        !(lead[0] == 'P' && lead[1] >= '1' && lead[1] <= '7'))
        samples = raw_samples(r, scanned);
    report->trailing_bytes = scanned;
    report->trailing_samples = samples;
    report->trailing_data = data;
    if (r->src->read_errno != 0 || r->src->over_limit)
        return rayo_source_end_error(r->src, "the rest of the file", err);
    return RAYO_OK;
}

static rayo_status read_raster(pnm_reader *r, rayo_image *image,
                               rayo_error *err)
{
    rayo_status status;
    if (r->digit == '1')
        status = read_plain_pbm(r, image, err);
    else if (r->digit == '2' || r->digit == '3')
        status = read_plain_samples(r, image, err);
    else
        status = read_raw(r, image, err);
    if (status == RAYO_OK && r->digit <= '3')
        skip_final_space(r);
    return status;
}

rayo_status rayo_pnm_read(rayo_source *src, int digit, int clamp,
                          rayo_image *image, rayo_read_report *report,
                          rayo_error *err)
{
    static const rayo_format formats[] = {RAYO_FORMAT_PBM, RAYO_FORMAT_PGM,
                                          RAYO_FORMAT_PPM};
    pnm_reader r;
    rayo_image_info info;
    rayo_status status;
    memset(&r, 0, sizeof r);
    r.src = src;
    r.digit = digit;
    r.line = 1;
    r.clamp = clamp;
    r.report = report;
    report->format = formats[(digit - '1') % 3];
    report->plain = digit <= '3';
    status = read_header(&r, err);
    if (status == RAYO_OK)
        status = check_room(&r, err);
    if (status != RAYO_OK)
        return status;
    info = layout_of(&r);
    status = rayo_image_create(image, &info, NULL);
    if (status != RAYO_OK)
        return rayo_error_set(err, status, "%s: out of memory for a %lux%lu "
                              "image", src->name, (unsigned long)r.width,
                              (unsigned long)r.height);
    status = read_raster(&r, image, err);
    if (status == RAYO_OK)
        status = scan_trailing(&r, report, err);
    if (status != RAYO_OK)
        rayo_image_free(image);
    return status;
}
