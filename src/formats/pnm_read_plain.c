/*
 * pnm_read_plain.c - the rasters of plain Netpbm (P1-P3): decimal
 * samples separated by whitespace and comments, each checked against
 * maxval, or clamped and counted when the caller asks (reader.h).
 *
 * Plain PBM has a tight loop of its own that works on the source's
 * window directly, eight digits at a time where it can: it is the format
 * of the assignment and of the large images `rayo compare` reads.
 * Strict about the raster: every sample present, nothing but digits,
 * whitespace and comments.  Raw rasters are pnm_read.c's.
 */
#include <stdio.h>
#include <string.h>

#include "pnm_read_impl.h"

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
rayo_status pnm_read_plain_pbm(pnm_reader *r, rayo_image *image,
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
                return pnm_found_error(r, RAYO_ERR_FORMAT, -1,
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
            } else if (!pnm_is_space((int)c)) {
                src->next = p;
                return pnm_found_error(r, RAYO_ERR_FORMAT, (int)c,
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

/* One decimal sample of a plain PGM/PPM raster, at most maxval. */
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
        else if (!pnm_is_space(c))
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
        return pnm_found_error(r, RAYO_ERR_FORMAT, c, expected, err);
    }
    while (c >= '0' && c <= '9') {
        if (v <= 65536)
            v = v * 10 + (uint64_t)(c - '0');
        c = rayo_source_peek(r->src);
        if (c >= '0' && c <= '9')
            rayo_source_getc(r->src);
    }
    if (c >= 0 && !pnm_is_space(c) && c != '#') {
        rayo_source_getc(r->src);
        return pnm_found_error(r, RAYO_ERR_FORMAT, c,
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

rayo_status pnm_read_plain_samples(pnm_reader *r, rayo_image *image,
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

void pnm_skip_final_space(pnm_reader *r)
{
    for (;;) {
        int c = rayo_source_peek(r->src);
        if (c == '#')
            skip_comment(r);
        else if (pnm_is_space(c))
            rayo_source_getc(r->src);
        else
            return;
    }
}
