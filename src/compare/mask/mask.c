/*
 * mask.c - counting and tidying packed rows of bits, the masks compare
 * works on (1 = black, most significant bit first, as in image.h).
 *
 * Counting is done eight bytes at a time with the classic SWAR
 * reduction, so a 4096-pixel row is 64 steps.  Nothing here knows what
 * the bits mean.
 */
#include <string.h>

#include "rayo/image_convert.h"

#include "../compare_impl.h"

uint64_t cmp_popcount(const unsigned char *bytes, size_t n)
{
    uint64_t total = 0, word;
    size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        memcpy(&word, bytes + i, sizeof word);
        total += cmp_popcount64(word);
    }
    for (; i < n; i++)
        total += cmp_popcount64(bytes[i]);
    return total;
}

void cmp_clear_padding(unsigned char *row, uint32_t width)
{
    unsigned used = width & 7u;
    if (used != 0)
        row[width >> 3] &= (unsigned char)(0xFFu << (8 - used));
}

static rayo_status mask_of(const rayo_image *image, rayo_image *owned,
                           cmp_mask *mask, rayo_error *err)
{
    const rayo_image *bits = image;
    rayo_status s = rayo_image_info_check(&image->info, err);
    if (s != RAYO_OK)
        return s;
    if (image->info.sample != RAYO_SAMPLE_BIT) {
        s = rayo_image_to_bit(image, owned, err);
        if (s != RAYO_OK)
            return s;
        bits = owned;
    }
    mask->width = bits->info.width;
    mask->height = bits->info.height;
    mask->stride = bits->stride;
    mask->bits = bits->pixels;
    return RAYO_OK;
}

rayo_status cmp_pair_make(cmp_pair *pair, const rayo_image *reference,
                          const rayo_image *image, rayo_error *err)
{
    rayo_status s;
    memset(pair, 0, sizeof *pair);
    s = mask_of(reference, &pair->owned_ref, &pair->ref, err);
    if (s == RAYO_OK)
        s = mask_of(image, &pair->owned_image, &pair->image, err);
    if (s != RAYO_OK)
        cmp_pair_free(pair);
    return s;
}

void cmp_pair_free(cmp_pair *pair)
{
    rayo_image_free(&pair->owned_ref);
    rayo_image_free(&pair->owned_image);
}
