/*
 * row_runs.c - bilevel rows as runs of black pixels (row_runs.h): putting
 * them in order, and packing them into bits.
 */
#include "row_runs.h"

#include <string.h>

void rayo_row_runs_normalize(rayo_row_runs *runs)
{
    uint32_t i, j, kept = 0;
    if (runs->count < 2 || runs->count == RAYO_ROW_RUNS_BITS)
        return; /* in order already, or in bits */
    /* Insertion sort by first pixel: a handful of runs at most. */
    for (i = 1; i < runs->count; i++) {
        uint32_t first = runs->first[i], last = runs->last[i];
        for (j = i; j > 0 && runs->first[j - 1] > first; j--) {
            runs->first[j] = runs->first[j - 1];
            runs->last[j] = runs->last[j - 1];
        }
        runs->first[j] = first;
        runs->last[j] = last;
    }
    for (i = 0; i < runs->count; i++) {
        /* Overlaps or touches the last run kept. */
        if (kept > 0 && (runs->last[kept - 1] == UINT32_MAX ||
                         runs->first[i] <= runs->last[kept - 1] + 1)) {
            if (runs->last[i] > runs->last[kept - 1])
                runs->last[kept - 1] = runs->last[i];
            continue;
        }
        runs->first[kept] = runs->first[i];
        runs->last[kept] = runs->last[i];
        kept++;
    }
    runs->count = kept;
}

void rayo_row_bits_fill(unsigned char *bits, uint32_t first, uint32_t last)
{
    size_t b0 = first >> 3, b1 = last >> 3;
    unsigned char m0 = (unsigned char)(0xFFu >> (first & 7));
    unsigned char m1 = (unsigned char)(0xFF00u >> (1 + (last & 7)));
    if (b0 == b1) {
        bits[b0] = (unsigned char)(bits[b0] | (m0 & m1));
        return;
    }
    bits[b0] = (unsigned char)(bits[b0] | m0);
    memset(bits + b0 + 1, 0xFF, b1 - b0 - 1);
    bits[b1] = (unsigned char)(bits[b1] | m1);
}

void rayo_row_runs_to_bits(const rayo_row_runs *runs, uint32_t width,
                           unsigned char *bits)
{
    uint32_t i;
    memset(bits, 0, ((size_t)width + 7) / 8);
    for (i = 0; i < runs->count; i++)
        rayo_row_bits_fill(bits, runs->first[i], runs->last[i]);
}
