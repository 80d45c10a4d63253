/*
 * preview_color.c - the cells of RAYO_PREVIEW_COLOR_BLOCKS: a sub-pixel's
 * mean colour in 8 bits, xterm's nearest 256-colour index, and the SGR
 * escape sequence plus U+2580 that paint a cell (preview.h has the
 * sequences).
 *
 * Means are of the stored samples, scaled to 0..255 and rounded to
 * nearest in integers (no gamma).  The 256-colour choice leaves out the
 * 16 system colours (0-15), which every terminal theme redefines; of the
 * rest, xterm's cube has levels 0, 95, 135, 175, 215, 255 a channel and
 * the gray ramp 8 + 10 i, i = 0..23.  Not a colour manager or a ditherer.
 */
#include <string.h>

#include "preview_impl.h"

void preview_bin_rgb8(const preview_bin *bin, const rayo_image_info *info,
                      unsigned rgb[3])
{
    unsigned c;
    uint64_t den = 2 * bin->all * (uint64_t)info->maxval;
    for (c = 0; c < 3; c++) {
        uint64_t sum = bin->sum[info->channels == 3 ? c : 0];
        rgb[c] = den == 0 ? 0
                          : (unsigned)((510u * sum + den / 2) / den);
    }
}

static unsigned square(int d)
{
    return (unsigned)(d * d);
}

unsigned preview_xterm_index(const unsigned rgb[3])
{
    static const int level[6] = {0, 95, 135, 175, 215, 255};
    unsigned cube[3], c, k, cube_d = 0, gray = 0, gray_d = ~0u;
    for (c = 0; c < 3; c++) {
        unsigned best = 0;
        for (k = 1; k < 6; k++)
            if (square((int)rgb[c] - level[k]) <
                square((int)rgb[c] - level[best]))
                best = k;
        cube[c] = best;
        cube_d += square((int)rgb[c] - level[best]);
    }
    for (k = 0; k < 24; k++) {
        int v = 8 + 10 * (int)k;
        unsigned d = square((int)rgb[0] - v) + square((int)rgb[1] - v) +
                     square((int)rgb[2] - v);
        if (d < gray_d) {
            gray_d = d;
            gray = k;
        }
    }
    if (gray_d < cube_d)
        return 232 + gray;
    return 16 + 36 * cube[0] + 6 * cube[1] + cube[2];
}

static size_t put_text(char *out, const char *text)
{
    size_t n = strlen(text);
    memcpy(out, text, n);
    return n;
}

static size_t put_uint(char *out, unsigned v)
{
    char digits[12];
    size_t n = 0, i;
    do {
        digits[n++] = (char)('0' + v % 10);
        v /= 10;
    } while (v != 0);
    for (i = 0; i < n; i++)
        out[i] = digits[n - 1 - i];
    return n;
}

/* "38;2;R;G;B" or "38;5;N" (ground "38" or "48"). */
static size_t put_colour(char *out, rayo_preview_color color,
                         const char *ground, const unsigned rgb[3])
{
    size_t n = put_text(out, ground);
    unsigned c;
    if (color == RAYO_PREVIEW_COLOR_256) {
        n += put_text(out + n, ";5;");
        return n + put_uint(out + n, preview_xterm_index(rgb));
    }
    n += put_text(out + n, ";2");
    for (c = 0; c < 3; c++) {
        out[n++] = ';';
        n += put_uint(out + n, rgb[c]);
    }
    return n;
}

size_t preview_color_cell(rayo_preview_color color,
                          const rayo_image_info *info,
                          const preview_bin *upper, const preview_bin *lower,
                          char *out)
{
    unsigned rgb[3];
    size_t n = put_text(out, "\x1b[");
    preview_bin_rgb8(upper, info, rgb);
    n += put_colour(out + n, color, "38", rgb);
    out[n++] = ';';
    if (lower != NULL) {
        preview_bin_rgb8(lower, info, rgb);
        n += put_colour(out + n, color, "48", rgb);
    } else {
        n += put_text(out + n, "49");
    }
    return n + put_text(out + n, "m\xe2\x96\x80");
}
