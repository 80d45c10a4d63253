/*
 * tone_window.c - the largest or smallest value within a square window
 * around every pixel of a map, in time independent of the window's size.
 *
 * The tone comparison asks, for a differing pixel, whether an edge lies
 * within the tolerance, how steep the shading is there and which values
 * the reference takes there.  Asked pixel by pixel that costs the
 * window's area, (2r + 1)^2, each time; as maps made once it costs a few
 * operations a pixel whatever r is (van Herk's and Gil and Werman's
 * method, below).
 */
#include <stdlib.h>
#include <string.h>

#include "tone_impl.h"

/*
 * The window is separable: a running extreme along each row, then along
 * each column of the result.  Along a line: cut the line (padded by r
 * neutral values at both ends) into blocks of the window's length w; a
 * prefix extreme from each block's start and a suffix extreme to each
 * block's end; the window starting at i covers the end of one block and
 * the start of the next, so its extreme is that of suffix[i] and
 * prefix[i + w - 1].  Three comparisons a value.  Rows are passed one at
 * a time; columns a tile of them at once, read row by row.
 */

static unsigned char pick(unsigned char a, unsigned char b, int max)
{
    return max ? (a > b ? a : b) : (a < b ? a : b);
}

/* in[k * stride] for k = j - r, or the neutral value outside 0..n-1. */
static unsigned char padded(const unsigned char *in, size_t stride,
                            uint32_t n, int64_t k, int max)
{
    if (k < 0 || k >= (int64_t)n)
        return (unsigned char)(max ? 0 : 255);
    return in[(size_t)k * stride];
}

void tone_window_line(const unsigned char *in, size_t stride,
                      unsigned char *out, size_t out_stride, uint32_t n,
                      int radius, int max, unsigned char *prefix,
                      unsigned char *suffix)
{
    size_t w = 2 * (size_t)radius + 1, total = (size_t)n + 2 * radius, j;
    for (j = 0; j < total; j++) {
        unsigned char a = padded(in, stride, n, (int64_t)j - radius, max);
        prefix[j] = j % w == 0 ? a : pick(prefix[j - 1], a, max);
    }
    for (j = total; j-- > 0;) {
        unsigned char a = padded(in, stride, n, (int64_t)j - radius, max);
        suffix[j] = j % w == w - 1 || j == total - 1
                        ? a
                        : pick(suffix[j + 1], a, max);
    }
    for (j = 0; j < n; j++)
        out[j * out_stride] = pick(suffix[j], prefix[j + w - 1], max);
}

/* Columns a vertical pass takes at once: their values are copied into a
 * tile, row by row, so that the pass reads memory in order instead of a
 * cache line a value down each column. */
#define TILE_COLUMNS 64u

/* The vertical pass over columns x0..x0+cols-1 of in (row bytes apart),
 * the same running extremes as tone_window_line, on all the tile's
 * columns at once. */
static void window_columns(const unsigned char *in, unsigned char *out,
                           size_t row, uint32_t height, size_t x0,
                           size_t cols, int radius, int max,
                           unsigned char *tile, unsigned char *prefix,
                           unsigned char *suffix)
{
    size_t w = 2 * (size_t)radius + 1, total = (size_t)height + 2 * radius;
    size_t j, c;
    unsigned char neutral = (unsigned char)(max ? 0 : 255);
    for (j = 0; j < total; j++) {
        unsigned char *t = tile + j * TILE_COLUMNS;
        int64_t y = (int64_t)j - radius;
        if (y < 0 || y >= (int64_t)height)
            for (c = 0; c < cols; c++)
                t[c] = neutral;
        else
            for (c = 0; c < cols; c++)
                t[c] = in[(size_t)y * row + x0 + c];
    }
    for (j = 0; j < total; j++) {
        const unsigned char *a = tile + j * TILE_COLUMNS;
        unsigned char *p = prefix + j * TILE_COLUMNS;
        for (c = 0; c < cols; c++)
            p[c] = j % w == 0 ? a[c]
                              : pick((p - TILE_COLUMNS)[c], a[c], max);
    }
    for (j = total; j-- > 0;) {
        const unsigned char *a = tile + j * TILE_COLUMNS;
        unsigned char *q = suffix + j * TILE_COLUMNS;
        for (c = 0; c < cols; c++)
            q[c] = j % w == w - 1 || j == total - 1
                       ? a[c]
                       : pick(q[c + TILE_COLUMNS], a[c], max);
    }
    for (j = 0; j < height; j++)
        for (c = 0; c < cols; c++)
            out[j * row + x0 + c] =
                pick(suffix[j * TILE_COLUMNS + c],
                     prefix[(j + w - 1) * TILE_COLUMNS + c], max);
}

/* Up to this radius the extreme is taken directly, the 2 r + 1 values
 * of a window one after another, a whole row of bytes at a time: more
 * comparisons a value than van Herk's three, but in loops a compiler
 * runs many bytes at once, and without the padding's branches. */
#define DIRECT_RADIUS 4

/* dst[i] = extreme(dst[i], src[i]) for i < n. */
static void pick_into(unsigned char *dst, const unsigned char *src, size_t n,
                      int max)
{
    size_t i;
    if (max)
        for (i = 0; i < n; i++)
            dst[i] = src[i] > dst[i] ? src[i] : dst[i];
    else
        for (i = 0; i < n; i++)
            dst[i] = src[i] < dst[i] ? src[i] : dst[i];
}

/* tone_window_map for radius <= DIRECT_RADIUS.  pad: a row of bytes with
   radius pixels of neutral values on each side; across: the row pass. */
static void window_direct(const unsigned char *in, unsigned char *out,
                          uint32_t width, uint32_t height, unsigned channels,
                          int radius, int max, unsigned char *pad,
                          unsigned char *across)
{
    size_t row = (size_t)width * channels;
    size_t side = (size_t)radius * channels;
    unsigned char neutral = (unsigned char)(max ? 0 : 255);
    uint32_t y;
    int k;
    memset(pad, neutral, side);
    memset(pad + side + row, neutral, side);
    for (y = 0; y < height; y++) {
        unsigned char *a = across + (size_t)y * row;
        memcpy(pad + side, in + (size_t)y * row, row);
        memcpy(a, pad, row);
        for (k = 1; k <= 2 * radius; k++)
            pick_into(a, pad + (size_t)k * channels, row, max);
    }
    for (y = 0; y < height; y++) {
        int64_t y0 = (int64_t)y - radius, y1 = (int64_t)y + radius, j;
        unsigned char *o = out + (size_t)y * row;
        if (y0 < 0)
            y0 = 0;
        if (y1 >= (int64_t)height)
            y1 = (int64_t)height - 1;
        memcpy(o, across + (size_t)y0 * row, row);
        for (j = y0 + 1; j <= y1; j++)
            pick_into(o, across + (size_t)j * row, row, max);
    }
}

rayo_status tone_window_map(const unsigned char *in, unsigned char *out,
                            uint32_t width, uint32_t height,
                            unsigned channels, int radius, int max,
                            rayo_error *err)
{
    size_t longest = (width > height ? width : height) + 2 * (size_t)radius;
    size_t row = (size_t)width * channels, tall = height + 2 * (size_t)radius;
    size_t padded_row = row + 2 * (size_t)radius * channels;
    unsigned char *line =
        malloc(2 * longest > padded_row ? 2 * longest : padded_row);
    unsigned char *across = malloc(row * height);
    unsigned char *tile = NULL;
    uint32_t y;
    size_t x;
    unsigned c;
    if (line != NULL && across != NULL && radius <= DIRECT_RADIUS) {
        window_direct(in, out, width, height, channels, radius, max, line,
                      across);
        free(line);
        free(across);
        return RAYO_OK;
    }
    if (line != NULL && across != NULL)
        tile = malloc(3 * tall * TILE_COLUMNS);
    if (tile == NULL) {
        free(line);
        free(across);
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: out of memory for a %ux%u window "
                              "map",
                              width, height);
    }
    for (y = 0; y < height; y++)
        for (c = 0; c < channels; c++)
            tone_window_line(in + y * row + c, channels,
                             across + y * row + c, channels, width, radius,
                             max, line, line + longest);
    /* The columns of every channel, interleaved as they are, a tile of
       bytes at a time. */
    for (x = 0; x < row; x += TILE_COLUMNS)
        window_columns(across, out, row, height, x,
                       row - x < TILE_COLUMNS ? row - x : TILE_COLUMNS,
                       radius, max, tile, tile + tall * TILE_COLUMNS,
                       tile + 2 * tall * TILE_COLUMNS);
    free(line);
    free(across);
    free(tile);
    return RAYO_OK;
}
