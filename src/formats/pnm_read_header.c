/*
 * pnm_read_header.c - a Netpbm header read and checked: width, height
 * and maxval, with comments from '#' to the end of the line anywhere and
 * any amount of whitespace between values, as Netpbm's format pages and
 * tools allow.  Each value is checked against limits.h, and the raster
 * it announces against the bytes left in a regular file or in memory,
 * before the image is allocated; an error names the byte and the line
 * of the value.  The raster is pnm_read.c's and pnm_read_plain.c's.
 */
#include <stdio.h>

#include "rayo/lang.h"
#include "rayo/limits.h"
#include "pnm_read_impl.h"

static const char *magic_name(int digit)
{
    static const char *const names[] = {"P1", "P2", "P3", "P4", "P5", "P6"};
    return names[digit - '1'];
}

rayo_status pnm_found_error(const pnm_reader *r, rayo_status status, int c,
                            const char *expected, rayo_error *err)
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
    while (pnm_is_space(c));
    snprintf(expected, sizeof expected, "the %s (a decimal number)", what);
    if (c < '0' || c > '9')
        return pnm_found_error(r, RAYO_ERR_FORMAT, c, expected, err);
    r->value_offset = rayo_source_offset(r->src) - 1;
    r->value_line = r->line;
    *value = 0;
    while (c >= '0' && c <= '9') {
        if (*value <= UINT32_MAX)
            *value = *value * 10 + (uint64_t)(c - '0');
        c = header_getc(r);
    }
    if (!pnm_is_space(c)) {
        snprintf(expected, sizeof expected,
                 "whitespace after the %s", what);
        return pnm_found_error(r, RAYO_ERR_FORMAT, c, expected, err);
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

rayo_status pnm_read_header(pnm_reader *r, rayo_error *err)
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

rayo_image_info pnm_layout_of(const pnm_reader *r)
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

uint64_t pnm_raw_row_bytes(const pnm_reader *r)
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
        return pnm_raw_row_bytes(r) * r->height;
    }
}

rayo_status pnm_check_room(const pnm_reader *r, rayo_error *err)
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
