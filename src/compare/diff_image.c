/*
 * diff_image.c - the difference picture of a comparison, streamed to a
 * PNG writer one row at a time.
 *
 * Agreement stays black and white; a pixel black only in the reference
 * is red and one black only in the image is blue (compare.h), so a
 * student sees at a glance which side of the outline is wrong.  The
 * picture has the reference's frame, with the image laid on it as
 * compare does (centres aligned).  Memory is one RGB row.
 */
#include <stdlib.h>
#include <string.h>

#include "rayo/writer.h"

#include "compare_impl.h"

static void colour_row(const unsigned char *ref, const unsigned char *img,
                       uint32_t width, unsigned char *rgb)
{
    static const unsigned char ref_only[3] = {RAYO_DIFF_REFERENCE_ONLY_RGB};
    static const unsigned char img_only[3] = {RAYO_DIFF_IMAGE_ONLY_RGB};
    uint32_t i;
    for (i = 0; i < width; i++) {
        int a = rayo_bit_get(ref, i), b = rayo_bit_get(img, i);
        unsigned char *p = rgb + 3 * (size_t)i;
        if (a == b)
            memset(p, a ? 0 : 255, 3);
        else
            memcpy(p, a ? ref_only : img_only, 3);
    }
}

static rayo_status stream(const cmp_pair *pair, rayo_writer *writer,
                          unsigned char *rgb, unsigned char *img,
                          rayo_error *err)
{
    cmp_transform frame = {CMP_IDENTITY, 0, 0, 1, 1};
    uint32_t y, w = pair->ref.width;
    unsigned char *known = img + cmp_row_bytes(w);
    for (y = 0; y < pair->ref.height; y++) {
        rayo_status s;
        cmp_transform_row(&frame, &pair->image, w, pair->ref.height, y, img,
                          known);
        colour_row(cmp_mask_row(&pair->ref, y), img, w, rgb);
        s = rayo_writer_write_rows(writer, rgb, 0, 1, err);
        if (s != RAYO_OK)
            return s;
    }
    return RAYO_OK;
}

rayo_status rayo_compare_write_diff(const rayo_image *reference,
                                    const rayo_image *image,
                                    rayo_output *out, rayo_error *err)
{
    rayo_write_options options = {RAYO_FORMAT_PNG, 0};
    rayo_image_info info;
    rayo_writer *writer;
    unsigned char *rgb, *img;
    cmp_pair pair;
    rayo_status s = cmp_pair_make(&pair, reference, image, err);
    if (s != RAYO_OK)
        return s;
    info = rayo_image_info_rgb8(pair.ref.width, pair.ref.height);
    rgb = malloc(rayo_image_info_row_bytes(&info));
    img = malloc(2 * cmp_row_bytes(pair.ref.width));
    if (rgb == NULL || img == NULL)
        s = rayo_error_set(err, RAYO_ERR_NOMEM,
                           "compare: out of memory for a diff row");
    if (s == RAYO_OK)
        s = rayo_writer_open(&writer, out, &info, &options, err);
    if (s == RAYO_OK) {
        s = stream(&pair, writer, rgb, img, err);
        if (s == RAYO_OK)
            s = rayo_writer_finish(writer, err);
        else
            rayo_writer_discard(writer);
    }
    free(rgb);
    free(img);
    cmp_pair_free(&pair);
    return s;
}
