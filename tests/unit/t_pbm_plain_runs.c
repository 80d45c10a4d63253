/*
 * t_pbm_plain_runs.c - the plain PBM reader takes eight digits at once
 * when eight come in a row and one byte at a time otherwise; this checks
 * that the two ways agree wherever the runs are broken.
 *
 * Pseudo-random bilevel images of widths around multiples of 8 are
 * written here as P1 text in several layouts (lines of 70 as the Netpbm
 * tools write them, one line a row, digits apart, everything on one
 * line, whitespace and comments dropped in at random places), read back
 * with rayo_image_read_memory and compared pixel by pixel with the bits
 * they were written from.  Texts with a bad character at a random place
 * must fail with the byte and line of that character, computed here.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

static unsigned long next(unsigned long *seed)
{
    *seed = *seed * 6364136223846793005ul + 1442695040888963407ul;
    return *seed >> 33;
}

typedef struct text {
    char *bytes;
    size_t length, room;
} text;

static void add(text *t, const char *s)
{
    size_t n = strlen(s);
    if (t->length + n + 1 > t->room) {
        t->room = 2 * (t->length + n + 1);
        t->bytes = realloc(t->bytes, t->room);
        if (t->bytes == NULL)
            abort();
    }
    memcpy(t->bytes + t->length, s, n + 1);
    t->length += n;
}

/* The P1 text of bits (w x h, one char '0'/'1' a pixel) in a layout. */
static void write_text(text *t, const char *bits, uint32_t w, uint32_t h,
                       int layout, unsigned long *seed)
{
    char header[64], one[2] = {0, 0};
    size_t i, n = (size_t)w * h;
    t->length = 0;
    snprintf(header, sizeof header, "P1\n%u %u\n", w, h);
    add(t, header);
    for (i = 0; i < n; i++) {
        one[0] = bits[i];
        add(t, one);
        if (layout == 0 && (i + 1) % 70 == 0)
            add(t, "\n");
        else if (layout == 1 && (i + 1) % w == 0)
            add(t, "\n");
        else if (layout == 2)
            add(t, " ");
        else if (layout == 4) {
            unsigned long r = next(seed) % 40;
            if (r == 0)
                add(t, "\n");
            else if (r == 1)
                add(t, " \t");
            else if (r == 2)
                add(t, "#0101 1111 0000\n");
            else if (r == 3)
                add(t, "\r\n");
        }
    }
    add(t, "\n");
}

static int same_pixels(const rayo_image *image, const char *bits,
                       uint32_t w, uint32_t h)
{
    uint32_t x, y;
    if (image->info.width != w || image->info.height != h)
        return 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            if (rayo_bit_get(rayo_image_row(image, y), x) !=
                (bits[(size_t)y * w + x] == '1'))
                return 0;
    return 1;
}

/* The first pixel digit of the raster at or after offset k (comments
 * skipped), or length when there is none. */
static size_t pixel_at_or_after(const text *t, size_t k)
{
    size_t i = strlen("P1\n"), lines = 0;
    int comment = 0;
    while (lines < 1) /* past the size line */
        lines += t->bytes[i++] == '\n';
    for (; i < t->length; i++) {
        char c = t->bytes[i];
        if (comment) {
            comment = c != '\n';
            continue;
        }
        comment = c == '#';
        if (i >= k && (c == '0' || c == '1'))
            return i;
    }
    return t->length;
}

/* Line (1-based) of byte offset k of s. */
static unsigned long line_of(const char *s, size_t k)
{
    unsigned long line = 1;
    size_t i;
    for (i = 0; i < k; i++)
        line += s[i] == '\n';
    return line;
}

int main(void)
{
    static const uint32_t widths[] = {1, 7, 8, 9, 15, 16, 17, 63, 64, 65, 70, 71, 200};
    unsigned long seed = 77;
    text t = {NULL, 0, 0};
    size_t wi;
    int layout;
    for (wi = 0; wi < sizeof widths / sizeof widths[0]; wi++) {
        uint32_t w = widths[wi], h = 1 + (uint32_t)(next(&seed) % 9);
        size_t i, n = (size_t)w * h;
        char *bits = malloc(n + 1);
        if (bits == NULL)
            abort();
        for (i = 0; i < n; i++)
            bits[i] = next(&seed) % 3 == 0 ? '1' : '0';
        bits[n] = 0;
        for (layout = 0; layout < 5; layout++) {
            rayo_image image;
            rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
            rayo_status s;
            size_t k;
            char want[96];
            write_text(&t, bits, w, h, layout, &seed);
            s = rayo_image_read_memory(t.bytes, t.length, "runs.pbm", &image,
                                       NULL, &err);
            ok(s == RAYO_OK && same_pixels(&image, bits, w, h),
               "%ux%u, layout %d: every pixel as written", w, h, layout);
            if (s == RAYO_OK)
                rayo_image_free(&image);
            /* a bad character somewhere in the raster */
            k = pixel_at_or_after(&t, next(&seed) % t.length);
            if (k >= t.length)
                continue;
            t.bytes[k] = 'x';
            s = rayo_image_read_memory(t.bytes, t.length, "runs.pbm", &image,
                                       NULL, &err);
            snprintf(want, sizeof want, "byte %zu (line %lu): found 'x'", k,
                     line_of(t.bytes, k));
            ok(s == RAYO_ERR_FORMAT && strstr(err.message, want) != NULL,
               "%ux%u, layout %d, 'x' at byte %zu: %s", w, h, layout, k, want);
            if (s == RAYO_OK)
                rayo_image_free(&image);
        }
        free(bits);
    }
    free(t.bytes);
    return tap_done();
}
