/*
 * pbm_plain.h - spelling out rows of bits as plain PBM text ("0"/"1"
 * digits, lines of at most 70, a newline after each row).  Private to
 * pnm_write.c, which owns the header, the output and every other format;
 * this file exists because the seed job spends most of its time here.
 */
#ifndef RAYO_PBM_PLAIN_H
#define RAYO_PBM_PLAIN_H

#include <stddef.h>
#include <stdint.h>

#include "../image/row_runs.h"

typedef struct rayo_pbm_plain rayo_pbm_plain;

/* Bytes one formatted row of this width takes, newlines included. */
size_t rayo_pbm_plain_row_size(uint32_t width);

/* A formatter for rows of width pixels (1..RAYO_MAX_DIMENSION); NULL
 * when out of memory. */
rayo_pbm_plain *rayo_pbm_plain_new(uint32_t width);

void rayo_pbm_plain_free(rayo_pbm_plain *plain);

/* The formatted bytes of white rows, one after the other, as many as
 * *rows is set to (at least one); they stay as they are until
 * rayo_pbm_plain_free. */
const unsigned char *rayo_pbm_plain_white(const rayo_pbm_plain *plain,
                                          size_t *rows);

/*
 * Formats count rows into out, one after the other, count *
 * rayo_pbm_plain_row_size() bytes, which it returns.  Row r is runs[r]
 * (normal form, image/row_runs.h) when runs is not NULL and runs[r].count
 * is not RAYO_ROW_RUNS_BITS; otherwise its packed bits at rows + r *
 * stride (most significant first; padding bits ignored).
 */
size_t rayo_pbm_plain_rows(const rayo_pbm_plain *plain,
                           const unsigned char *rows, size_t stride,
                           const rayo_row_runs *runs, size_t count,
                           unsigned char *out);

#endif
