/*
 * pbm_plain.c - plain PBM rows from two templates.
 *
 * A formatted row has its newlines in the same places whatever the
 * pixels, so the formatter keeps the row spelled out all white and all
 * black.  Rows start as a copy of the white one, a block of rows at a
 * time (one long copy costs less than many row-sized ones:
 * docs/performance.md); each run of black pixels is then copied from the
 * black row, newlines included.  Rendered rows are long runs of one
 * colour, so a row costs a few copies instead of one store per eight
 * pixels; a row of noise costs what spelling out every byte does.
 */
#include "pbm_plain.h"

#include <stdlib.h>
#include <string.h>

/*
 * Rows that come as runs (row_runs.h: the span renderer's, through
 * render.c) need nothing more than the copies.  Rows that come as bits
 * are scanned for runs of black bytes (0xFF), eight bytes at a time, and
 * only the bytes that mix black and white are spelled out, digit by
 * digit.
 */

#define LINE_MAX_DIGITS 70
/* The white template holds as many rows as fit here, and at least one. */
#define WHITE_BYTES 8192

struct rayo_pbm_plain {
    uint32_t width;
    size_t size;          /* bytes of a formatted row */
    size_t white_rows;    /* rows in the white template */
    unsigned char *white; /* white_rows rows of all 0 digits */
    unsigned char *black; /* one row of all 1 digits */
};

/* Where digit x of a row goes: one newline after every full line. */
static size_t position(size_t x)
{
    return x + x / LINE_MAX_DIGITS;
}

size_t rayo_pbm_plain_row_size(uint32_t width)
{
    return (size_t)width + ((size_t)width + LINE_MAX_DIGITS - 1) /
                               LINE_MAX_DIGITS;
}

/* size bytes of digit, a newline after every full line and at the end. */
static void fill_template(unsigned char *row, size_t size, char digit)
{
    size_t at;
    memset(row, digit, size);
    for (at = LINE_MAX_DIGITS; at < size; at += LINE_MAX_DIGITS + 1)
        row[at] = '\n';
    row[size - 1] = '\n';
}

rayo_pbm_plain *rayo_pbm_plain_new(uint32_t width)
{
    rayo_pbm_plain *plain = malloc(sizeof *plain);
    size_t i;
    if (plain == NULL)
        return NULL;
    plain->width = width;
    plain->size = rayo_pbm_plain_row_size(width);
    plain->white_rows =
        plain->size < WHITE_BYTES ? WHITE_BYTES / plain->size : 1;
    plain->white = malloc(plain->size * plain->white_rows);
    plain->black = malloc(plain->size);
    if (plain->white == NULL || plain->black == NULL) {
        rayo_pbm_plain_free(plain);
        return NULL;
    }
    fill_template(plain->white, plain->size, '0');
    for (i = 1; i < plain->white_rows; i++)
        memcpy(plain->white + i * plain->size, plain->white, plain->size);
    fill_template(plain->black, plain->size, '1');
    return plain;
}

void rayo_pbm_plain_free(rayo_pbm_plain *plain)
{
    if (plain == NULL)
        return;
    free(plain->white);
    free(plain->black);
    free(plain);
}

const unsigned char *rayo_pbm_plain_white(const rayo_pbm_plain *plain,
                                          size_t *rows)
{
    *rows = plain->white_rows;
    return plain->white;
}

/* Digits first..last (inclusive) from the black template. */
static void copy_black(const rayo_pbm_plain *plain, unsigned char *out,
                       size_t first, size_t last)
{
    size_t from = position(first), to = position(last) + 1;
    memcpy(out + from, plain->black + from, to - from);
}

/* The digits of each nibble. */
static const char nibble_digits[16][4] = {
    {'0', '0', '0', '0'}, {'0', '0', '0', '1'}, {'0', '0', '1', '0'},
    {'0', '0', '1', '1'}, {'0', '1', '0', '0'}, {'0', '1', '0', '1'},
    {'0', '1', '1', '0'}, {'0', '1', '1', '1'}, {'1', '0', '0', '0'},
    {'1', '0', '0', '1'}, {'1', '0', '1', '0'}, {'1', '0', '1', '1'},
    {'1', '1', '0', '0'}, {'1', '1', '0', '1'}, {'1', '1', '1', '0'},
    {'1', '1', '1', '1'}};

/* The digits of byte k, which holds both colours. */
static void spell_byte(const rayo_pbm_plain *plain, unsigned char *out,
                       size_t k, unsigned byte)
{
    size_t x = 8 * k;
    size_t count = plain->width - x < 8 ? plain->width - x : 8;
    size_t d;
    if (count == 8 && x % LINE_MAX_DIGITS <= LINE_MAX_DIGITS - 8) {
        /* No line break inside the byte. */
        memcpy(out + position(x), nibble_digits[byte >> 4], 4);
        memcpy(out + position(x) + 4, nibble_digits[byte & 15], 4);
        return;
    }
    for (d = 0; d < count; d++)
        out[position(x + d)] = (unsigned char)('0' + ((byte >> (7 - d)) & 1));
}

/* The first k at or after start where row[k] is not `fill` (0x00 or
 * 0xFF), or bytes. */
static size_t skip_run(const unsigned char *row, size_t start, size_t bytes,
                       unsigned char fill)
{
    uint64_t run = fill ? UINT64_MAX : 0;
    size_t k = start;
    while (bytes - k >= 8) {
        uint64_t word;
        memcpy(&word, row + k, 8);
        if (word != run) {
#if defined(__GNUC__) && defined(__BYTE_ORDER__) && \
    __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
            /* The first byte in memory is the least significant. */
            return k + (size_t)__builtin_ctzll(word ^ run) / 8;
#else
            break;
#endif
        }
        k += 8;
    }
    while (k < bytes && row[k] == fill)
        k++;
    return k;
}

/* Turns the white row at out into row's digits. */
static void mark_row(const rayo_pbm_plain *plain, const unsigned char *row,
                     unsigned char *out)
{
    size_t bytes = ((size_t)plain->width + 7) / 8, k = 0;
    for (;;) {
        k = skip_run(row, k, bytes, 0x00);
        if (k == bytes)
            break;
        if (row[k] == 0xFF) {
            size_t j = skip_run(row, k + 1, bytes, 0xFF), end;
            end = 8 * j < plain->width ? 8 * j : plain->width;
            copy_black(plain, out, 8 * k, end - 1);
            k = j;
        } else {
            spell_byte(plain, out, k, row[k]);
            k++;
        }
    }
}

size_t rayo_pbm_plain_rows(const rayo_pbm_plain *plain,
                           const unsigned char *rows, size_t stride,
                           const rayo_row_runs *runs, size_t count,
                           unsigned char *out)
{
    size_t total = count * plain->size, done, r;
    size_t block = plain->white_rows * plain->size;
    uint32_t i;
    for (done = 0; done < total; done += block)
        memcpy(out + done, plain->white,
               total - done < block ? total - done : block);
    for (r = 0; r < count; r++) {
        unsigned char *row_out = out + r * plain->size;
        if (runs == NULL || runs[r].count == RAYO_ROW_RUNS_BITS) {
            mark_row(plain, rows + r * stride, row_out);
            continue;
        }
        for (i = 0; i < runs[r].count; i++)
            copy_black(plain, row_out, runs[r].first[i], runs[r].last[i]);
    }
    return total;
}
