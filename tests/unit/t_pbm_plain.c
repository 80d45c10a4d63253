/*
 * t_pbm_plain.c - plain PBM rows from pbm_plain.c against a formatter
 * written here the obvious way (one digit per pixel, a newline after
 * every 70 digits and at the end), on seeded random rows built to hit the
 * formatter's cases: long runs of white and black, mixed bytes, black
 * runs ending at the last byte, garbage in the padding bits, and widths
 * around the multiples of 8 and 70.  Rows are formatted in blocks of
 * random length, strides with slack between rows, so that blocks end
 * inside and past the formatter's template of white rows (8 KiB).  In
 * two widths of three, rows come as runs of black pixels (row_runs.h)
 * mixed with rows in bits, as render.c hands them over; the bits of a
 * row given as runs are garbage, which the formatter must not read.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/formats/pbm_plain.h"
#include "../../src/image/row_runs.h"
#include "tap.h"

static uint64_t state = 0x2545F4914F6CDD1Dull;

static unsigned next(void)
{
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return (unsigned)(state >> 32);
}

static size_t obvious(const unsigned char *row, uint32_t width,
                      unsigned char *out)
{
    size_t n = 0;
    uint32_t x;
    for (x = 0; x < width; x++) {
        out[n++] = (unsigned char)('0' + ((row[x / 8] >> (7 - x % 8)) & 1));
        if ((x + 1) % 70 == 0 || x + 1 == width)
            out[n++] = '\n';
    }
    return n;
}

/* Runs of 0x00 and 0xFF bytes with mixed bytes between, padding random. */
static void random_row(unsigned char *row, size_t bytes)
{
    size_t k = 0;
    while (k < bytes) {
        size_t run = 1 + next() % 40;
        unsigned kind = next() % 3;
        for (; run > 0 && k < bytes; run--, k++)
            row[k] = kind == 0   ? 0x00
                     : kind == 1 ? 0xFF
                                 : (unsigned char)next();
    }
}

#define ROWS 40

/* Random runs in normal form, up to RAYO_ROW_RUNS_MAX of them. */
static void random_runs(rayo_row_runs *runs, uint32_t width)
{
    unsigned n = next() % (RAYO_ROW_RUNS_MAX + 1), i;
    runs->count = 0;
    for (i = 0; i < n; i++) {
        uint32_t first = next() % width;
        uint32_t last = first + next() % (width - first);
        if (next() % 2)
            last = first + (last - first) % 12; /* short ones too */
        rayo_row_runs_add(runs, first, last);
    }
    rayo_row_runs_normalize(runs);
}

int main(void)
{
    static const uint32_t big[] = {65536, 65535, 4097, 8000};
    size_t cases = 0, wrong = 0, bad_size = 0;
    size_t i;
    unsigned char *rows = malloc(ROWS * 8200), *got = malloc(ROWS * 70000),
                  *want = malloc(ROWS * 70000), *packed = malloc(8200);
    rayo_row_runs runs[ROWS];
    long as_runs = 0;
    if (rows == NULL || got == NULL || want == NULL || packed == NULL)
        return 1;
    for (i = 0; i < 300 + sizeof big / sizeof big[0]; i++) {
        uint32_t width = i < 300 ? (uint32_t)i + 1 : big[i - 300];
        size_t bytes = (width + 7) / 8, stride = bytes + i % 3;
        size_t size = rayo_pbm_plain_row_size(width), m = 0, n = 0;
        rayo_pbm_plain *plain = rayo_pbm_plain_new(width);
        int r, with_runs = i % 3 != 0;
        if (plain == NULL)
            return 1;
        for (r = 0; r < ROWS; r++) {
            unsigned char *row = rows + (size_t)r * stride;
            random_row(row, bytes);
            if (r == 0)
                memset(row, 0, bytes);
            if (r == 1)
                memset(row, 0xFF, bytes);
            runs[r].count = RAYO_ROW_RUNS_BITS;
            if (with_runs && next() % 2) {
                random_runs(&runs[r], width);
                rayo_row_runs_to_bits(&runs[r], width, packed);
                m += obvious(packed, width, want + m);
                as_runs++;
                continue; /* the row's bits stay garbage */
            }
            m += obvious(row, width, want + m);
        }
        memset(got, '?', ROWS * size + 1);
        for (r = 0; r < ROWS;) {
            size_t count = 1 + next() % (i % 2 ? ROWS : 4);
            if (count > (size_t)(ROWS - r))
                count = (size_t)(ROWS - r);
            bad_size += rayo_pbm_plain_rows(plain, rows + (size_t)r * stride,
                                            stride, with_runs ? runs + r : NULL,
                                            count, got + n) != count * size;
            n += count * size;
            r += (int)count;
        }
        cases += ROWS;
        bad_size += n != m;
        wrong += n != m || memcmp(got, want, m) != 0 || got[n] != '?';
        rayo_pbm_plain_free(plain);
    }
    is_int(bad_size, 0, "row sizes agree (%lu rows)", (unsigned long)cases);
    is_int(wrong, 0, "every row spelled as the obvious formatter does, "
                     "nothing written past it (%ld rows given as runs)",
           as_runs);
    free(rows);
    free(got);
    free(want);
    free(packed);
    return tap_done();
}
