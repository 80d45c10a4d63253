/*
 * row_runs.h - a bilevel row as runs of black pixels.
 *
 * The span renderer (render/hit_spans.c) finds most rows of a frame of
 * spheres as a run or two of hits, and the plain PBM writer
 * (formats/pbm_plain.c) spells a run by copying it from a row of black
 * digits; packing the runs into bits only to find them again by scanning
 * cost the seed job a fifth of its time.  So render.c hands the library's
 * own plain PBM writer a band's rows as runs where it has them, and as
 * bits where it does not.  Private to the library: rows reach a caller's
 * sink as bits, always.
 */
#ifndef RAYO_ROW_RUNS_H
#define RAYO_ROW_RUNS_H

#include <stddef.h>
#include <stdint.h>

/* Runs a row holds before it goes back to bits. */
#define RAYO_ROW_RUNS_MAX 8
/* The count of a row that is in its bits, not in runs. */
#define RAYO_ROW_RUNS_BITS UINT32_MAX

/*
 * Pixels first[i]..last[i] (inclusive) are black, all others white.  In
 * normal form (rayo_row_runs_normalize) the runs are in order, apart
 * and not touching: last[i] + 1 < first[i + 1].
 */
typedef struct rayo_row_runs {
    uint32_t count; /* runs, or RAYO_ROW_RUNS_BITS */
    uint32_t first[RAYO_ROW_RUNS_MAX];
    uint32_t last[RAYO_ROW_RUNS_MAX];
} rayo_row_runs;

/* Adds a run (first <= last); 0, having added nothing, when the row
 * already holds RAYO_ROW_RUNS_MAX.  Inline: the span renderer adds a run
 * or two to every row. */
static inline int rayo_row_runs_add(rayo_row_runs *runs, uint32_t first,
                                    uint32_t last)
{
    if (runs->count >= RAYO_ROW_RUNS_MAX)
        return 0;
    runs->first[runs->count] = first;
    runs->last[runs->count] = last;
    runs->count++;
    return 1;
}

/* Sorts the runs and merges those that overlap or touch (a row in bits
 * is left as it is). */
void rayo_row_runs_normalize(rayo_row_runs *runs);

/* Sets bits first..last (inclusive) of a packed row, most significant
 * bit first. */
void rayo_row_bits_fill(unsigned char *bits, uint32_t first, uint32_t last);

/* The row as packed bits: (width + 7) / 8 bytes, padding bits zero. */
void rayo_row_runs_to_bits(const rayo_row_runs *runs, uint32_t width,
                           unsigned char *bits);

#endif
