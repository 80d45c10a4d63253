/*
 * pnm_read_impl.h - what the three parts of the Netpbm reader share:
 * the reader's state, and the header (pnm_read_header.c) and plain
 * raster (pnm_read_plain.c) steps that pnm_read.c calls in turn.
 * Private to src/formats/pnm_read*.c.
 */
#ifndef RAYO_PNM_READ_IMPL_H
#define RAYO_PNM_READ_IMPL_H

#include <stdint.h>

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

static inline int pnm_is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
           c == '\f';
}

/* "FILE: byte N (line L): found X; expected WHAT" at the byte before the
   cursor (c < 0: the end of the source, or its read error). */
rayo_status pnm_found_error(const pnm_reader *r, rayo_status status, int c,
                            const char *expected, rayo_error *err);

/* The header after the magic: width, height and (but for PBM) maxval,
   checked against limits.h; then whether the bytes left in a regular
   file or in memory can hold the raster, before anything is allocated. */
rayo_status pnm_read_header(pnm_reader *r, rayo_error *err);
rayo_status pnm_check_room(const pnm_reader *r, rayo_error *err);

/* The image the header describes, and the bytes of one raw row as
   stored in the file. */
rayo_image_info pnm_layout_of(const pnm_reader *r);
uint64_t pnm_raw_row_bytes(const pnm_reader *r);

/* A plain raster into image: PBM (P1), or PGM and PPM (P2, P3). */
rayo_status pnm_read_plain_pbm(pnm_reader *r, rayo_image *image,
                               rayo_error *err);
rayo_status pnm_read_plain_samples(pnm_reader *r, rayo_image *image,
                                   rayo_error *err);

/* After a plain raster: whitespace and comments are not trailing data. */
void pnm_skip_final_space(pnm_reader *r);

#endif
