/*
 * diff_image.c - the difference picture of a comparison, streamed to a
 * PNG one row at a time.
 *
 * Agreement stays black and white; a pixel black only in the reference
 * is red and one black only in the image is blue (compare.h), so a
 * student sees at a glance which side of the outline is wrong.  The
 * picture has the reference's frame, with the image laid on it as
 * compare does (centres aligned).  Four colours fit a 2-bit palette PNG,
 * which writer.h does not make, so this file drives libpng itself.  Bytes
 * go through the rayo_output, so the file appears whole or not at all.
 */
#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "../compare_impl.h"
#include "../tone/tone_impl.h"

/*
 * A 2-bit palette makes a 4096 x 4096 picture 4 MiB of samples instead of
 * 48 MiB of RGB, compressed at zlib's fastest level.  Memory is one
 * packed row.  A gray or colour pair is handed to the tone comparison's
 * own picture (tone/tone_diff.c).
 */

enum { WHITE, BLACK, REFERENCE_ONLY, IMAGE_ONLY };

typedef struct diff_png {
    png_structp png;
    png_infop info;
    rayo_output *out;
    rayo_error error;
} diff_png;

static void on_error(png_structp png, png_const_charp message)
{
    diff_png *d = png_get_error_ptr(png);
    if (d->error.status == RAYO_OK)
        rayo_error_set(&d->error, RAYO_ERR_IO, "%s: libpng: %s",
                       rayo_output_name(d->out), message);
    png_longjmp(png, 1);
}

static void on_warning(png_structp png, png_const_charp message)
{
    (void)png;
    (void)message;
}

static void on_write(png_structp png, png_bytep data, size_t length)
{
    diff_png *d = png_get_io_ptr(png);
    if (rayo_output_write(d->out, data, length, &d->error) != RAYO_OK)
        png_error(png, "write failed");
}

static void on_flush(png_structp png)
{
    (void)png;
}

/* The eight bits of v spread to the even bits of 16 (bit i to 2i). */
static unsigned spread(unsigned v)
{
    v = (v | (v << 4)) & 0x0F0Fu;
    v = (v | (v << 2)) & 0x3333u;
    return (v | (v << 1)) & 0x5555u;
}

/* Eight pixels of reference (a) and image (b) as two bytes of 2-bit
 * palette indices: the high bit of an index says they differ, the low
 * bit is the image's (WHITE 00, BLACK 01, REFERENCE_ONLY 10, IMAGE_ONLY
 * 11), so all eight are two spreads of whole bytes. */
static void pack_byte(unsigned a, unsigned b, unsigned char *out)
{
    unsigned v;
    if (a == b && (a == 0 || a == 0xFFu)) {
        out[0] = out[1] = a ? 0x55 : 0x00;
        return;
    }
    v = spread((a ^ b) & 0xFFu) << 1 | spread(b & 0xFFu);
    out[0] = (unsigned char)(v >> 8);
    out[1] = (unsigned char)(v & 0xFFu);
}

static void header(diff_png *d, uint32_t width, uint32_t height)
{
    static const unsigned char ref_only[3] = {RAYO_DIFF_REFERENCE_ONLY_RGB};
    static const unsigned char img_only[3] = {RAYO_DIFF_IMAGE_ONLY_RGB};
    png_color palette[4];
    memset(palette, 0, sizeof palette);
    palette[WHITE].red = palette[WHITE].green = palette[WHITE].blue = 255;
    palette[REFERENCE_ONLY].red = ref_only[0];
    palette[REFERENCE_ONLY].green = ref_only[1];
    palette[REFERENCE_ONLY].blue = ref_only[2];
    palette[IMAGE_ONLY].red = img_only[0];
    palette[IMAGE_ONLY].green = img_only[1];
    palette[IMAGE_ONLY].blue = img_only[2];
    png_set_write_fn(d->png, d, on_write, on_flush);
    png_set_compression_level(d->png, Z_BEST_SPEED);
    png_set_filter(d->png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
    png_set_IHDR(d->png, d->info, width, height, 2, PNG_COLOR_TYPE_PALETTE,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_set_PLTE(d->png, d->info, palette, 4);
    png_write_info(d->png, d->info);
}

/* All of libpng's work, under one jump buffer. */
static rayo_status write_png(diff_png *d, const cmp_pair *pair,
                             unsigned char *rows)
{
    cmp_transform frame = {CMP_IDENTITY, 0, 0, 1, 1, NULL, NULL};
    uint32_t w = pair->ref.width, y;
    size_t n = cmp_row_bytes(w), k;
    unsigned char *img = rows, *known = rows + n, *out = rows + 2 * n;
    if (setjmp(png_jmpbuf(d->png)))
        return d->error.status != RAYO_OK ? d->error.status : RAYO_ERR_IO;
    header(d, w, pair->ref.height);
    for (y = 0; y < pair->ref.height; y++) {
        const unsigned char *ref = cmp_mask_row(&pair->ref, y);
        cmp_transform_row(&frame, &pair->image, w, pair->ref.height, y, img,
                          known);
        for (k = 0; k < n; k++) {
            unsigned a = ref[k];
            if (k == n - 1)
                a &= (0xFFu << ((8 - (w & 7u)) & 7u)) & 0xFFu;
            pack_byte(a, img[k], out + 2 * k);
        }
        png_write_row(d->png, out);
    }
    png_write_end(d->png, NULL);
    return RAYO_OK;
}

rayo_status rayo_compare_write_diff(const rayo_image *reference,
                                    const rayo_image *image,
                                    const rayo_compare_options *options,
                                    rayo_output *out, rayo_error *err)
{
    diff_png d;
    cmp_pair pair;
    unsigned char *rows;
    rayo_compare_options defaults;
    rayo_status s;
    rayo_compare_options_init(&defaults);
    if (options == NULL)
        options = &defaults;
    if ((s = cmp_options_check(options, err)) != RAYO_OK ||
        (s = rayo_image_info_check(&reference->info, err)) != RAYO_OK ||
        (s = rayo_image_info_check(&image->info, err)) != RAYO_OK)
        return s;
    if (!tone_is_bilevel(reference) || !tone_is_bilevel(image))
        return tone_write_diff(reference, image, options, out, err);
    s = cmp_pair_make(&pair, reference, image, err);
    if (s != RAYO_OK)
        return s;
    memset(&d, 0, sizeof d);
    d.out = out;
    rayo_error_init(&d.error, rayo_error_lang(err));
    rows = malloc(4 * cmp_row_bytes(pair.ref.width));
    d.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &d, on_error,
                                    on_warning);
    if (d.png != NULL)
        d.info = png_create_info_struct(d.png);
    if (rows == NULL || d.info == NULL)
        s = rayo_error_set(err, RAYO_ERR_NOMEM,
                           "compare: out of memory for the diff picture");
    else if ((s = write_png(&d, &pair, rows)) != RAYO_OK && err != NULL)
        *err = d.error;
    png_destroy_write_struct(&d.png, &d.info);
    free(rows);
    cmp_pair_free(&pair);
    return s;
}
