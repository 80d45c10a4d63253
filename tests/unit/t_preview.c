/*
 * t_preview.c - rayo_preview_render on tiny images whose pictures are
 * worked out by hand: which half blocks, Braille dots and ASCII marks
 * each cell gets, how an image is shrunk (never enlarged) to fit, how
 * gray is thresholded, and the exact escape sequences of colour blocks
 * (24-bit, and 256 colours checked against a nearest-colour search over
 * xterm's palette written here from its formula); then rayo_preview's
 * rows, a band at a time, against the whole image.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "bitmap.h"
#include "tap.h"

#define UPPER "\xe2\x96\x80" /* U+2580, the colour cell */

/* xterm's colour n (16-255): the 6x6x6 cube, levels 0 and 55 + 40 k,
 * then 24 grays 8 + 10 k. */
static void xterm_rgb(unsigned n, int rgb[3])
{
    static const int level[6] = {0, 95, 135, 175, 215, 255};
    if (n >= 232) {
        rgb[0] = rgb[1] = rgb[2] = 8 + 10 * (int)(n - 232);
        return;
    }
    n -= 16;
    rgb[0] = level[n / 36];
    rgb[1] = level[n / 6 % 6];
    rgb[2] = level[n % 6];
}

/* The nearest of colours 16-255 by squared distance, the lowest on a
 * tie: a plain search over all 240. */
static unsigned nearest_xterm(int r, int g, int b)
{
    unsigned n, best = 16;
    long best_d = -1;
    for (n = 16; n < 256; n++) {
        int c[3];
        long d;
        xterm_rgb(n, c);
        d = (long)(r - c[0]) * (r - c[0]) + (long)(g - c[1]) * (g - c[1]) +
            (long)(b - c[2]) * (b - c[2]);
        if (best_d < 0 || d < best_d) {
            best_d = d;
            best = n;
        }
    }
    return best;
}

static rayo_image make_image(uint32_t w, uint32_t h, unsigned channels,
                             rayo_sample_type sample, unsigned maxval)
{
    rayo_image image;
    rayo_image_info info;
    memset(&image, 0, sizeof image);
    info.width = w;
    info.height = h;
    info.channels = channels;
    info.maxval = maxval;
    info.sample = sample;
    if (rayo_image_create(&image, &info, NULL) != RAYO_OK)
        abort();
    return image;
}

static void put_rgb(rayo_image *m, uint32_t x, uint32_t y, unsigned r,
                    unsigned g, unsigned b)
{
    unsigned char *p = rayo_image_row(m, y) + 3 * (size_t)x;
    p[0] = (unsigned char)r;
    p[1] = (unsigned char)g;
    p[2] = (unsigned char)b;
}

static void put_u16(rayo_image *m, uint32_t x, uint32_t y, unsigned v)
{
    uint16_t s = (uint16_t)v;
    memcpy(rayo_image_row(m, y) + 2 * (size_t)x, &s, sizeof s);
}

/* The picture in colour blocks with this colour mode ("" on error). */
static char *colour(const rayo_image *image, rayo_preview_color mode,
                    unsigned columns)
{
    rayo_preview_options options;
    char *text;
    size_t length;
    rayo_preview_options_init(&options);
    options.style = RAYO_PREVIEW_COLOR_BLOCKS;
    options.color = mode;
    options.columns = columns;
    if (rayo_preview_render(image, &options, &text, &length, NULL, NULL,
                            NULL) != RAYO_OK)
        return calloc(1, 1);
    return text;
}

/* The same picture drawn from rows handed to a rayo_preview in bands of
 * band rows, last band first; 1 when it matches rayo_preview_render. */
static int stream_matches(const rayo_image *image,
                          const rayo_preview_options *options,
                          uint32_t band)
{
    rayo_preview *p = NULL;
    char *whole = NULL, *streamed = NULL;
    size_t wl, sl;
    uint32_t first;
    int same = 0;
    if (rayo_preview_render(image, options, &whole, &wl, NULL, NULL, NULL) !=
            RAYO_OK ||
        rayo_preview_create(&p, &image->info, options, NULL) != RAYO_OK)
        goto done;
    first = (image->info.height - 1) / band * band;
    for (;;) {
        uint32_t n = image->info.height - first < band
                         ? image->info.height - first
                         : band;
        if (rayo_preview_rows(p, rayo_image_row(image, first), image->stride,
                              first, n, NULL) != RAYO_OK)
            goto done;
        if (first == 0)
            break;
        first -= band;
    }
    if (rayo_preview_text(p, options, &streamed, &sl, NULL, NULL, NULL) !=
        RAYO_OK)
        goto done;
    same = wl == sl && memcmp(whole, streamed, wl) == 0;
done:
    free(whole);
    free(streamed);
    rayo_preview_free(p);
    return same;
}

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
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
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
    is_int(options.color, RAYO_PREVIEW_COLOR_NONE, "default: no colour");
    options.columns = 80;
    options.style = (rayo_preview_style)9;
    is_int(rayo_preview_render(&m, &options, &t, &length, NULL, NULL, &err),
           RAYO_ERR_INVALID, "a style outside the enum refused");
    options.style = RAYO_PREVIEW_COLOR_BLOCKS;
    options.color = (rayo_preview_color)7;
    is_int(rayo_preview_render(&m, &options, &t, &length, NULL, NULL, &err),
           RAYO_ERR_INVALID, "a colour mode outside the enum refused");
    rayo_image_free(&m);
    rayo_image_free(&big);

    {
        /* 2x2 RGB, one cell a column:  red    green
                                        blue   (10, 20, 30)   */
        rayo_image c = make_image(2, 2, 3, RAYO_SAMPLE_U8, 255);
        char want[200];
        put_rgb(&c, 0, 0, 255, 0, 0);
        put_rgb(&c, 1, 0, 0, 255, 0);
        put_rgb(&c, 0, 1, 0, 0, 255);
        put_rgb(&c, 1, 1, 10, 20, 30);
        t = colour(&c, RAYO_PREVIEW_COLOR_TRUECOLOR, 80);
        is_string(t, "\x1b[38;2;255;0;0;48;2;0;0;255m" UPPER
                     "\x1b[38;2;0;255;0;48;2;10;20;30m" UPPER "\x1b[0m\n",
                  "truecolor 2x2: red over blue, green over (10,20,30)");
        free(t);
        /* red is cube (5,0,0) = 16 + 180 = 196; (10,20,30) is nearer
           gray 18 (distance 212) than black (1400): 233 */
        is_int(nearest_xterm(255, 0, 0), 196, "xterm search: red is 196");
        is_int(nearest_xterm(10, 20, 30), 233, "xterm search: (10,20,30) is gray 233");
        snprintf(want, sizeof want,
                 "\x1b[38;5;%u;48;5;%um" UPPER "\x1b[38;5;%u;48;5;%um" UPPER
                 "\x1b[0m\n",
                 nearest_xterm(255, 0, 0), nearest_xterm(0, 0, 255),
                 nearest_xterm(0, 255, 0), nearest_xterm(10, 20, 30));
        t = colour(&c, RAYO_PREVIEW_COLOR_256, 80);
        is_string(t, want, "256 colours 2x2: the nearest xterm colours");
        ok(strstr(t, "38;5;196;") == t + 2, "  red is 196");
        free(t);
        t = colour(&c, RAYO_PREVIEW_COLOR_NONE, 80);
        is_string(t, "\xe2\x96\x88\xe2\x96\x84\n",
                  "colour blocks, no colour: the silhouette (green is light)");
        free(t);
        rayo_image_free(&c);
    }
    {
        /* mid gray 128 everywhere: nearest is gray 8 + 10 x 12 = 128 */
        rayo_image g8 = make_image(1, 2, 1, RAYO_SAMPLE_U8, 255);
        char want[100];
        unsigned n = nearest_xterm(128, 128, 128);
        rayo_image_row(&g8, 0)[0] = 128;
        rayo_image_row(&g8, 1)[0] = 128;
        is_int(n, 244, "xterm search: gray 128 is 244 (232 + 12)");
        snprintf(want, sizeof want, "\x1b[38;5;%u;48;5;%um" UPPER "\x1b[0m\n",
                 n, n);
        t = colour(&g8, RAYO_PREVIEW_COLOR_256, 80);
        is_string(t, want, "256 colours: mid gray on the gray ramp");
        free(t);
        t = colour(&g8, RAYO_PREVIEW_COLOR_TRUECOLOR, 80);
        is_string(t, "\x1b[38;2;128;128;128;48;2;128;128;128m" UPPER "\x1b[0m\n",
                  "truecolor: gray repeated in R, G and B");
        free(t);
        rayo_image_free(&g8);
    }
    {
        /* 4x4 RGB in 2 columns: 2x2 pixels a sub-pixel, one line.  The
           top left square: red 0 255 255 255 (191.25), green 0 0 0 1
           (0.25), blue 10 11 12 13 (11.5, halves up: 12).  The rest:
           top right all (200, 100, 50); bottom left two black, two
           white (127.5: 128); bottom right (1,2,3) (3,4,5) (5,6,7)
           (7,8,9): (4, 5, 6). */
        rayo_image c = make_image(4, 4, 3, RAYO_SAMPLE_U8, 255);
        put_rgb(&c, 0, 0, 0, 0, 10);
        put_rgb(&c, 1, 0, 255, 0, 11);
        put_rgb(&c, 0, 1, 255, 0, 12);
        put_rgb(&c, 1, 1, 255, 1, 13);
        for (y = 0; y < 2; y++)
            for (x = 2; x < 4; x++)
                put_rgb(&c, x, y, 200, 100, 50);
        put_rgb(&c, 0, 2, 255, 255, 255);
        put_rgb(&c, 1, 3, 255, 255, 255);
        put_rgb(&c, 2, 2, 1, 2, 3);
        put_rgb(&c, 3, 2, 3, 4, 5);
        put_rgb(&c, 2, 3, 5, 6, 7);
        put_rgb(&c, 3, 3, 7, 8, 9);
        t = colour(&c, RAYO_PREVIEW_COLOR_TRUECOLOR, 2);
        is_string(t, "\x1b[38;2;191;0;12;48;2;128;128;128m" UPPER
                     "\x1b[38;2;200;100;50;48;2;4;5;6m" UPPER "\x1b[0m\n",
                  "shrunk 4x4 to 2 columns: each half the mean of its 2x2");
        free(t);
        /* 3 columns: s = 4/3, sub-pixels [0,1) [1,2) [2,4) across and
           [0,1) [1,2) [2,4) down (3 of them: the last line has no lower
           half) */
        t = colour(&c, RAYO_PREVIEW_COLOR_TRUECOLOR, 3);
        is_string(t, "\x1b[38;2;0;0;10;48;2;255;0;12m" UPPER
                     "\x1b[38;2;255;0;11;48;2;255;1;13m" UPPER
                     "\x1b[38;2;200;100;50;48;2;200;100;50m" UPPER "\x1b[0m\n"
                     "\x1b[38;2;128;128;128;49m" UPPER
                     "\x1b[38;2;128;128;128;49m" UPPER
                     "\x1b[38;2;4;5;6;49m" UPPER "\x1b[0m\n",
                  "4x4 in 3 columns: sub-pixels of 1, 1 and 2 pixels a side");
        free(t);
        rayo_image_free(&c);
    }
    {
        /* Every gray level and 200 pseudo-random colours, one a cell: the
           256-colour indices are those of the plain search. */
        rayo_image g8 = make_image(256, 2, 1, RAYO_SAMPLE_U8, 255);
        rayo_image c = make_image(200, 2, 3, RAYO_SAMPLE_U8, 255);
        char *want = malloc(256 * 40 + 10), *w;
        unsigned state = 777, v;
        for (x = 0; x < 256; x++) {
            rayo_image_row(&g8, 0)[x] = (unsigned char)x;
            rayo_image_row(&g8, 1)[x] = (unsigned char)(255 - x);
        }
        for (w = want, x = 0; x < 256; x++)
            w += sprintf(w, "\x1b[38;5;%u;48;5;%um" UPPER,
                         nearest_xterm((int)x, (int)x, (int)x),
                         nearest_xterm(255 - (int)x, 255 - (int)x,
                                       255 - (int)x));
        strcpy(w, "\x1b[0m\n");
        t = colour(&g8, RAYO_PREVIEW_COLOR_256, 256);
        is_string(t, want, "256 colours: every gray level maps to the nearest");
        free(t);
        for (w = want, x = 0; x < 200; x++) {
            unsigned rgb[2][3], k;
            for (y = 0; y < 2; y++)
                for (k = 0; k < 3; k++) {
                    state = state * 1103515245u + 12345u;
                    v = (state >> 16) & 255;
                    rgb[y][k] = v;
                }
            put_rgb(&c, x, 0, rgb[0][0], rgb[0][1], rgb[0][2]);
            put_rgb(&c, x, 1, rgb[1][0], rgb[1][1], rgb[1][2]);
            w += sprintf(w, "\x1b[38;5;%u;48;5;%um" UPPER,
                         nearest_xterm((int)rgb[0][0], (int)rgb[0][1],
                                       (int)rgb[0][2]),
                         nearest_xterm((int)rgb[1][0], (int)rgb[1][1],
                                       (int)rgb[1][2]));
        }
        strcpy(w, "\x1b[0m\n");
        t = colour(&c, RAYO_PREVIEW_COLOR_256, 200);
        is_string(t, want, "256 colours: 400 random colours map to the nearest");
        free(t);
        free(want);
        rayo_image_free(&g8);
        rayo_image_free(&c);
    }
    {
        /* 16-bit gray, maxval 65535: 65535 -> 255, 32768 -> 127.5019 ->
           128, 0 -> 0; a third row alone on the last line gets the
           default background (49). */
        rayo_image w = make_image(1, 3, 1, RAYO_SAMPLE_U16, 65535);
        rayo_image k = make_image(1, 2, 1, RAYO_SAMPLE_U16, 1000);
        put_u16(&w, 0, 0, 65535);
        put_u16(&w, 0, 1, 0);
        put_u16(&w, 0, 2, 32768);
        t = colour(&w, RAYO_PREVIEW_COLOR_TRUECOLOR, 80);
        is_string(t, "\x1b[38;2;255;255;255;48;2;0;0;0m" UPPER "\x1b[0m\n"
                     "\x1b[38;2;128;128;128;49m" UPPER "\x1b[0m\n",
                  "16-bit gray scaled to 8 bits; a lone last row over the default background");
        free(t);
        /* maxval 1000: 500 -> 127.5 -> 128, 1 -> 0.255 -> 0 */
        put_u16(&k, 0, 0, 500);
        put_u16(&k, 0, 1, 1);
        t = colour(&k, RAYO_PREVIEW_COLOR_TRUECOLOR, 80);
        is_string(t, "\x1b[38;2;128;128;128;48;2;0;0;0m" UPPER "\x1b[0m\n",
                  "maxval 1000: 500 is 128, 1 is 0");
        free(t);
        rayo_image_free(&w);
        rayo_image_free(&k);
    }
    {
        /* A 37x23 RGB pattern: each silhouette style draws what it draws
           for the mask rayo_image_to_bit makes; colour blocks without
           colour are blocks; rows in bands give the whole image's text. */
        static const rayo_preview_style styles[4] = {
            RAYO_PREVIEW_BLOCKS, RAYO_PREVIEW_BRAILLE, RAYO_PREVIEW_ASCII,
            RAYO_PREVIEW_COLOR_BLOCKS};
        rayo_image c = make_image(37, 23, 3, RAYO_SAMPLE_U8, 255), bits;
        unsigned i, mode, state = 12345;
        int same_mask = 1, same_stream = 1;
        char *a, *b;
        memset(&bits, 0, sizeof bits);
        for (y = 0; y < 23; y++)
            for (x = 0; x < 37; x++) {
                state = state * 1103515245u + 12345u;
                put_rgb(&c, x, y, (state >> 8) & 255, (state >> 16) & 255,
                        (x * 7 + y * 5) & 255);
            }
        rayo_image_to_bit(&c, &bits, NULL);
        for (i = 0; i < 3; i++) {
            a = picture(&c, styles[i], 9, NULL, NULL);
            b = picture(&bits, styles[i], 9, NULL, NULL);
            same_mask &= strcmp(a, b) == 0 && *a != '\0';
            free(a);
            free(b);
        }
        ok(same_mask, "RGB silhouettes: those of rayo_image_to_bit's mask");
        a = colour(&c, RAYO_PREVIEW_COLOR_NONE, 9);
        b = picture(&c, RAYO_PREVIEW_BLOCKS, 9, NULL, NULL);
        is_string(a, b, "colour blocks with no colour: blocks, byte for byte");
        free(a);
        free(b);
        rayo_preview_options_init(&options);
        for (i = 0; i < 4; i++)
            for (mode = 0; mode < 3; mode++) {
                options.style = styles[i];
                options.color = (rayo_preview_color)mode;
                options.columns = 9;
                same_stream &= stream_matches(&c, &options, 4);
                options.columns = 80;
                same_stream &= stream_matches(&c, &options, 5);
                same_stream &= stream_matches(&bits, &options, 7);
            }
        ok(same_stream, "rows in bands, last first: the whole image's text (every style, colour, RGB and bilevel)");

        /* rayo_preview's refusals */
        {
            rayo_preview *p = NULL;
            options.style = RAYO_PREVIEW_COLOR_BLOCKS;
            options.columns = 9;
            rayo_preview_create(&p, &c.info, &options, NULL);
            ok(p != NULL, "rayo_preview_create");
            is_int(rayo_preview_rows(p, c.pixels, c.stride, 20, 4, &err),
                   RAYO_ERR_INVALID, "rows past the last refused");
            options.columns = 10;
            is_int(rayo_preview_text(p, &options, &t, &length, NULL, NULL,
                                     &err),
                   RAYO_ERR_INVALID, "text with other columns refused");
            options.columns = 9;
            options.style = RAYO_PREVIEW_BLOCKS;
            is_int(rayo_preview_text(p, &options, &t, &length, NULL, NULL,
                                     &err),
                   RAYO_ERR_INVALID, "text in another style refused");
            ok(t == NULL, "  nothing returned");
            rayo_preview_free(p);
            rayo_preview_free(NULL);
        }
        rayo_image_free(&c);
        rayo_image_free(&bits);
    }
    return tap_done();
}
