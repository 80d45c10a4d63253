/*
 * tone_diff.c - the difference picture of a tone comparison: the
 * reference dimmed to a third of its brightness, in gray, with every
 * pixel that differs by more than the levels painted over it, amber
 * where the reference explains it (an outline, a shadow edge or shading
 * within the tolerance) and red where nothing does, brighter the larger
 * the difference (full colour from 64 levels on).  So a student sees
 * where the image is wrong and by how much, over the picture it should
 * be.
 *
 * Written as an 8-bit RGB PNG of the reference's size through the
 * library's writer, one row at a time; the image is laid on the
 * reference's frame as the comparison lays it.
 */
#include <stdlib.h>

#include "rayo/writer.h"

#include "tone_impl.h"

static const unsigned char explained_rgb[3] = {RAYO_DIFF_EXPLAINED_RGB};
static const unsigned char unexplained_rgb[3] = {RAYO_DIFF_UNEXPLAINED_RGB};

static void paint(const tone_image *ref, const tone_image *image,
                  const rayo_compare_options *o, uint32_t y,
                  unsigned char *row)
{
    uint32_t x;
    for (x = 0; x < ref->width; x++) {
        const unsigned char *r = tone_pixel(ref, x, y);
        unsigned luma = ref->channels == 1
                            ? r[0]
                            : (299u * r[0] + 587u * r[1] + 114u * r[2] +
                               500u) / 1000u;
        unsigned dim = luma / 3, d, c;
        int kind = tone_classify_pixel(ref, image, x, y, o->tolerance,
                                       o->levels, &d);
        const unsigned char *paint_rgb =
            kind == TONE_PIXEL_EXPLAINED
                ? explained_rgb
                : kind == TONE_PIXEL_UNEXPLAINED ? unexplained_rgb : NULL;
        for (c = 0; c < 3; c++) {
            unsigned v = dim;
            if (paint_rgb != NULL) {
                /* weight of the colour, in 64ths: 24 + 40 d / 64 */
                unsigned w = d >= 64 ? 64 : 24 + 40 * d / 64;
                v = (dim * (64 - w) + paint_rgb[c] * w) / 64;
            }
            row[3 * x + c] = (unsigned char)v;
        }
    }
}

rayo_status tone_write_diff(const rayo_image *reference,
                            const rayo_image *image,
                            const rayo_compare_options *options,
                            rayo_output *out, rayo_error *err)
{
    tone_image ref, img;
    unsigned channels =
        tone_has_colour(reference) || tone_has_colour(image) ? 3 : 1;
    rayo_image_info info;
    rayo_write_options wo;
    rayo_writer *writer = NULL;
    unsigned char *row;
    uint32_t y;
    rayo_status s = tone_image_make(reference, channels, &ref, err);
    if (s != RAYO_OK)
        return s;
    if ((s = tone_image_make(image, channels, &img, err)) != RAYO_OK ||
        (s = tone_image_find_edges_kept(&ref, options->tolerance,
                                        options->levels, err)) != RAYO_OK) {
        tone_image_free(&ref);
        tone_image_free(&img);
        return s;
    }
    info = rayo_image_info_rgb8(ref.width, ref.height);
    wo.format = RAYO_FORMAT_PNG;
    wo.plain = 0;
    row = malloc((size_t)ref.width * 3);
    if (row == NULL)
        s = rayo_error_set(err, RAYO_ERR_NOMEM,
                           "compare: out of memory for the diff picture");
    else
        s = rayo_writer_open(&writer, out, &info, &wo, err);
    for (y = 0; s == RAYO_OK && y < ref.height; y++) {
        paint(&ref, &img, options, y, row);
        s = rayo_writer_write_rows(writer, row, 0, 1, err);
    }
    if (writer != NULL) {
        if (s == RAYO_OK)
            s = rayo_writer_finish(writer, err);
        else
            rayo_writer_discard(writer);
    }
    free(row);
    tone_image_free(&ref);
    tone_image_free(&img);
    return s;
}
