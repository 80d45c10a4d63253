/*
 * t_pbm_plain.c - plain PBM rows from pbm_plain.c against a formatter
 * written here the obvious way (one digit per pixel, a newline after
 * every 70 digits and at the end), on seeded random rows built to hit the
 * formatter's cases: long runs of white and black, mixed bytes, black
 * runs ending at the last byte, garbage in the padding bits, and widths
 * around the multiples of 8 and 70.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/formats/pbm_plain.h"
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

int main(void)
{
    static const uint32_t big[] = {65536, 65535, 4097, 8000};
    size_t cases = 0, wrong = 0, bad_size = 0;
    uint32_t width;
    size_t i;
    unsigned char *row = malloc(8192), *got = malloc(70000),
                  *want = malloc(70000);
    if (row == NULL || got == NULL || want == NULL)
        return 1;
    for (i = 0; i < 300 + sizeof big / sizeof big[0]; i++) {
        rayo_pbm_plain *plain;
        int r;
        width = i < 300 ? (uint32_t)i + 1 : big[i - 300];
        plain = rayo_pbm_plain_new(width);
        if (plain == NULL)
            return 1;
        for (r = 0; r < 40; r++) {
            size_t n, m;
            random_row(row, (width + 7) / 8);
            if (r == 0)
                memset(row, 0, (width + 7) / 8);
            if (r == 1)
                memset(row, 0xFF, (width + 7) / 8);
            memset(got, '?', rayo_pbm_plain_row_size(width) + 1);
            n = rayo_pbm_plain_row(plain, row, got);
            m = obvious(row, width, want);
            cases++;
            bad_size += n != m || n != rayo_pbm_plain_row_size(width);
            wrong += n != m || memcmp(got, want, m) != 0 || got[n] != '?';
        }
        rayo_pbm_plain_free(plain);
    }
    is_int(bad_size, 0, "row sizes agree (%lu rows)", (unsigned long)cases);
    is_int(wrong, 0, "every row spelled as the obvious formatter does, "
                     "nothing written past it");
    free(row);
    free(got);
    free(want);
    return tap_done();
}
