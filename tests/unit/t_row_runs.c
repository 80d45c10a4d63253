/*
 * t_row_runs.c - rows as runs of black pixels (src/image/row_runs.h):
 * normalising seeded random runs (overlapping, touching, repeated, in any
 * order, up to RAYO_ROW_RUNS_MAX) keeps exactly the same pixels, packed
 * into bits as a pixel-by-pixel reference packs them, and leaves the runs
 * in order, apart and not touching.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/image/row_runs.h"
#include "tap.h"

static uint64_t state = 0x853C49E6748FEA9Bull;

static uint32_t below(uint32_t n)
{
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return (uint32_t)((state >> 33) % n);
}

/* The pixels the runs cover, one byte a pixel. */
static void covered(const rayo_row_runs *runs, uint32_t width,
                    unsigned char *pixels)
{
    uint32_t i, x;
    memset(pixels, 0, width);
    for (i = 0; i < runs->count; i++)
        for (x = runs->first[i]; x <= runs->last[i]; x++)
            pixels[x] = 1;
}

/* Bits packed from pixels, most significant first, padding zero. */
static void pack(const unsigned char *pixels, uint32_t width,
                 unsigned char *bits)
{
    uint32_t x;
    memset(bits, 0, (width + 7) / 8);
    for (x = 0; x < width; x++)
        if (pixels[x])
            bits[x / 8] = (unsigned char)(bits[x / 8] | (0x80u >> (x % 8)));
}

int main(void)
{
    enum { ROWS = 20000, WIDTH_MAX = 300 };
    unsigned char before[WIDTH_MAX], after[WIDTH_MAX];
    unsigned char want[WIDTH_MAX / 8 + 1], got[WIDTH_MAX / 8 + 1];
    long changed = 0, out_of_form = 0, wrong_bits = 0, merged = 0;
    long bad_add = 0, full = 0;
    int n;
    for (n = 0; n < ROWS; n++) {
        uint32_t width = 1 + below(WIDTH_MAX), i;
        uint32_t count = below(RAYO_ROW_RUNS_MAX + 1);
        rayo_row_runs runs;
        runs.count = 0;
        for (i = 0; i < count; i++) {
            /* Short runs, so that they meet often. */
            uint32_t first = below(width), length = below(6);
            uint32_t last = first + length < width ? first + length
                                                   : width - 1;
            bad_add += !rayo_row_runs_add(&runs, first, last);
        }
        if (runs.count == RAYO_ROW_RUNS_MAX) {
            /* A full row refuses another run and stays as it was. */
            bad_add += rayo_row_runs_add(&runs, 0, 0) ||
                       runs.count != RAYO_ROW_RUNS_MAX;
            full++;
        }
        covered(&runs, width, before);
        count = runs.count;
        rayo_row_runs_normalize(&runs);
        merged += runs.count < count;
        covered(&runs, width, after);
        changed += memcmp(before, after, width) != 0;
        for (i = 0; i < runs.count; i++)
            out_of_form += runs.first[i] > runs.last[i] ||
                           runs.last[i] >= width ||
                           (i > 0 && runs.first[i] <= runs.last[i - 1] + 1);
        pack(before, width, want);
        memset(got, 0xA5, sizeof got);
        rayo_row_runs_to_bits(&runs, width, got);
        wrong_bits += memcmp(got, want, (width + 7) / 8) != 0;
    }
    is_int(bad_add, 0, "runs are added until the row holds %d, then refused "
                       "(%ld full rows)",
           RAYO_ROW_RUNS_MAX, full);
    is_int(changed, 0, "normalising keeps every pixel (%d rows)", ROWS);
    ok(merged > ROWS / 4, "runs were merged in %ld rows", merged);
    is_int(out_of_form, 0, "normalised runs are in order, apart, not touching");
    is_int(wrong_bits, 0, "runs packed into bits as pixel by pixel");
    {
        rayo_row_runs bits_row;
        bits_row.count = RAYO_ROW_RUNS_BITS;
        rayo_row_runs_normalize(&bits_row);
        is_int(bits_row.count == RAYO_ROW_RUNS_BITS, 1,
               "a row in bits is left as it is");
    }
    return tap_done();
}
