/*
 * tone_window.c - the largest or smallest value within a square window
 * around every pixel of a map, in time independent of the window's size.
 *
 * The tone comparison asks, for a differing pixel, whether an edge lies
 * within the tolerance, how steep the shading is there and which values
 * the reference takes there.  Asked pixel by pixel that costs the
 * window's area, (2r + 1)^2, each time; as maps made once it costs a few
 * operations a pixel whatever r is.  The window is separable: a running
 * extreme along each row, then along each column of the result.  Along a
 * line, van Herk's and Gil and Werman's method: cut the line (padded by
 * r neutral values at both ends) into blocks of the window's length w;
 * a prefix extreme from each block's start and a suffix extreme to each
 * block's end; the window starting at i covers the end of one block and
 * the start of the next, so its extreme is that of suffix[i] and
 * prefix[i + w - 1].  Three comparisons a value.
 */
#include <stdlib.h>

#include "tone_impl.h"

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

rayo_status tone_window_map(const unsigned char *in, unsigned char *out,
                            uint32_t width, uint32_t height,
                            unsigned channels, int radius, int max,
                            rayo_error *err)
{
    size_t longest = (width > height ? width : height) + 2 * (size_t)radius;
    size_t row = (size_t)width * channels;
    unsigned char *line = malloc(2 * longest);
    unsigned char *across = malloc(row * height);
    uint32_t x, y;
    unsigned c;
    if (line == NULL || across == NULL) {
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
    for (x = 0; x < width; x++)
        for (c = 0; c < channels; c++)
            tone_window_line(across + (size_t)x * channels + c, row,
                             out + (size_t)x * channels + c, row, height,
                             radius, max, line, line + longest);
    free(line);
    free(across);
    return RAYO_OK;
}
