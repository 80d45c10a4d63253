/*
 * t_preview.c - rayo_preview_render on tiny images whose pictures are
 * worked out by hand: which half blocks, Braille dots and ASCII marks
 * each cell gets, how an image is shrunk (never enlarged) to fit, and
 * how gray is thresholded.
 */
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "bitmap.h"
#include "tap.h"

/* The picture of image in style with this many columns ("" on error). */
static char *picture(const rayo_image *image, rayo_preview_style style,
                     unsigned columns, unsigned *wide, unsigned *lines)
{
    rayo_preview_options options;
    char *text;
    size_t length;
    rayo_preview_options_init(&options);
    options.style = style;
    options.columns = columns;
    if (rayo_preview_render(image, &options, &text, &length, wide, lines,
                            NULL) != RAYO_OK)
        return calloc(1, 1);
    if (strlen(text) != length)
        printf("# length %zu but strlen %zu\n", length, strlen(text));
    return text;
}

int main(void)
{
    /* 2 wide, 4 tall:   column 0   column 1
                row 0    black      black
                row 1    black      white
                row 2    white      white
                row 3    black      white            */
    rayo_image m = bitmap_make(2, 4), big = bitmap_make(8, 8);
    rayo_image_info gray = rayo_image_info_gray8(4, 2);
    rayo_image g;
    rayo_preview_options options;
    rayo_error err;
    unsigned wide = 0, lines = 0, x, y;
    char *t;
    size_t length;
    bitmap_put(&m, 0, 0, 1);
    bitmap_put(&m, 1, 0, 1);
    bitmap_put(&m, 0, 1, 1);
    bitmap_put(&m, 0, 3, 1);

    t = picture(&m, RAYO_PREVIEW_BLOCKS, 80, &wide, &lines);
    /* line 0: column 0 rows 0-1 both black = full block; column 1 only
       the top = upper half.  line 1: column 0 only the bottom (row 3) =
       lower half; column 1 blank. */
    is_string(t, "\xe2\x96\x88\xe2\x96\x80\n\xe2\x96\x84 \n", "blocks: full, upper / lower, blank");
    is_int(wide * 10 + lines, 22, "blocks: 2 cells by 2 lines, never enlarged");
    free(t);

    t = picture(&m, RAYO_PREVIEW_BRAILLE, 80, &wide, &lines);
    /* one cell, 2x4 dots: (0,0) dot 1 = 0x01, (0,1) dot 2 = 0x02, (1,0)
       dot 4 = 0x08, (0,3) dot 7 = 0x40: U+2800 + 0x4B = U+284B */
    is_string(t, "\xe2\xa1\x8b\n", "braille: dots 1, 2, 4 and 7 (U+284B)");
    is_int(wide * 10 + lines, 11, "braille: one cell");
    free(t);

    t = picture(&m, RAYO_PREVIEW_ASCII, 80, NULL, NULL);
    /* a cell is 1x2 pixels: (0, rows 0-1) 2 of 2 black '#'; (1, rows
       0-1) 1 of 2, half counts as black '#'; (0, rows 2-3) 1 of 2 '#';
       (1, rows 2-3) none ' ' */
    is_string(t, "##\n# \n", "ascii: '#' for half or more, ' ' for none");
    free(t);

    /* 8x8 all black in 2 columns: 4 pixels a sub-pixel, 2x2 sub-pixels,
       one line of two full blocks. */
    for (y = 0; y < 8; y++)
        for (x = 0; x < 8; x++)
            bitmap_put(&big, x, y, 1);
    t = picture(&big, RAYO_PREVIEW_BLOCKS, 2, &wide, &lines);
    is_string(t, "\xe2\x96\x88\xe2\x96\x88\n", "8x8 black in 2 columns: one line, two full blocks");
    free(t);
    /* a cell here is 4 x 8 pixels: one black pixel among its 32 is
       less than half, but not nothing: '+' */
    memset(big.pixels, 0, big.stride * 8);
    bitmap_put(&big, 0, 0, 1);
    t = picture(&big, RAYO_PREVIEW_ASCII, 2, NULL, NULL);
    is_string(t, "+ \n", "ascii: 1 black pixel of 32 in a cell is '+'");
    free(t);

    /* Gray: black below half the maximum (2 v < 255). */
    memset(&g, 0, sizeof g);
    rayo_image_create(&g, &gray, NULL);
    memcpy(rayo_image_row(&g, 0), "\x00\x7f\x80\xff", 4);
    memcpy(rayo_image_row(&g, 1), "\x00\x7f\x80\xff", 4);
    t = picture(&g, RAYO_PREVIEW_ASCII, 4, NULL, NULL);
    is_string(t, "##  \n", "gray 0 127 128 255: two black, two white");
    free(t);
    rayo_image_free(&g);

    rayo_preview_options_init(&options);
    is_int(options.columns, 80, "default: 80 columns");
    is_int(options.style, RAYO_PREVIEW_BLOCKS, "default: blocks");
    options.columns = 0;
    is_int(rayo_preview_render(&m, &options, &t, &length, NULL, NULL, &err),
           RAYO_ERR_INVALID, "0 columns refused");
    ok(t == NULL, "nothing returned on failure");
    rayo_image_free(&m);
    rayo_image_free(&big);
    return tap_done();
}
