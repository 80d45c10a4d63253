/*
 * pnm_read.c - reading Netpbm images: PBM, PGM and PPM, plain (P1-P3)
 * and raw (P4-P6); the header is pnm_read_header.c's, the plain rasters
 * pnm_read_plain.c's, the raw ones and what follows the image are here.
 *
 * Strict about the raster: every sample present, none over maxval.  Not
 * a writer (pnm_write.c), and not a reader of PAM (P7) or of more than
 * the first image in a file; what follows the first image is only
 * looked at, to say whether it is more samples (a row too many) or
 * whitespace.
 */
#include <stdio.h>
#include <string.h>

#include "rayo/limits.h"
#include "pnm_read_impl.h"

/* Clears the bits after the last pixel of a BIT row. */
static void clear_padding(unsigned char *row, uint32_t width)
{
    if (width & 7)
        row[width >> 3] &= (unsigned char)(0xFFu << (8 - (width & 7)));
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
    size_t row_bytes = (size_t)pnm_raw_row_bytes(r);
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

/* Whole samples in n raw bytes after the raster (reader.h). */
static uint64_t raw_samples(const pnm_reader *r, uint64_t n)
{
    if (r->digit == '4') {
        uint64_t row = pnm_raw_row_bytes(r), rest = n % row;
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
        if (pnm_is_space(c) || (plain && c == '#')) {
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
        status = pnm_read_plain_pbm(r, image, err);
    else if (r->digit == '2' || r->digit == '3')
        status = pnm_read_plain_samples(r, image, err);
    else
        status = read_raw(r, image, err);
    if (status == RAYO_OK && r->digit <= '3')
        pnm_skip_final_space(r);
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
    status = pnm_read_header(&r, err);
    if (status == RAYO_OK)
        status = pnm_check_room(&r, err);
    if (status != RAYO_OK)
        return status;
    info = pnm_layout_of(&r);
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
