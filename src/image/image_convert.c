/*
 * image_convert.c - bilevel, gray and RGB conversions between whole
 * images (the rules are in image_convert.h).
 *
 * Each conversion is a loop over rows with one small per-pixel rule; the
 * sample readers hide whether samples are 8 or 16 bits.  Not used by the
 * renderer, which produces the layout it means to write.
 */
#include "rayo/image_convert.h"

#include <string.h>

static unsigned sample_at(const rayo_image *image, const unsigned char *row,
                          size_t index)
{
    uint16_t v;
    if (image->info.sample == RAYO_SAMPLE_U8)
        return row[index];
    memcpy(&v, row + 2 * index, sizeof v);
    return v;
}

static void sample_put(const rayo_image_info *info, unsigned char *row,
                       size_t index, unsigned value)
{
    uint16_t v = (uint16_t)value;
    if (info->sample == RAYO_SAMPLE_U8)
        row[index] = (unsigned char)value;
    else
        memcpy(row + 2 * index, &v, sizeof v);
}

/* 1000 times the pixel's luminance (BT.601 weights), or 1000 v for gray. */
static uint64_t luminance_1000(const rayo_image *src, const unsigned char *row,
                               uint32_t x)
{
    size_t i = (size_t)x * src->info.channels;
    if (src->info.channels == 1)
        return 1000u * (uint64_t)sample_at(src, row, i);
    return 299u * (uint64_t)sample_at(src, row, i) +
           587u * (uint64_t)sample_at(src, row, i + 1) +
           114u * (uint64_t)sample_at(src, row, i + 2);
}

static rayo_status create(rayo_image *dst, const rayo_image_info *info,
                          rayo_error *err)
{
    rayo_status status = rayo_image_create(dst, info, err);
    if (status != RAYO_OK)
        memset(dst, 0, sizeof *dst);
    return status;
}

static rayo_status copy_image(const rayo_image *src, rayo_image *dst,
                              rayo_error *err)
{
    uint32_t y;
    size_t bytes = rayo_image_info_row_bytes(&src->info);
    rayo_status status = create(dst, &src->info, err);
    if (status != RAYO_OK)
        return status;
    for (y = 0; y < src->info.height; y++)
        memcpy(rayo_image_row(dst, y), rayo_image_row(src, y), bytes);
    return RAYO_OK;
}

rayo_status rayo_image_to_bit(const rayo_image *src, rayo_image *dst,
                              rayo_error *err)
{
    rayo_image_info info =
        rayo_image_info_bit(src->info.width, src->info.height);
    uint64_t half = 500u * (uint64_t)src->info.maxval;
    uint32_t x, y;
    rayo_status status;
    if (src->info.sample == RAYO_SAMPLE_BIT)
        return copy_image(src, dst, err);
    status = create(dst, &info, err);
    if (status != RAYO_OK)
        return status;
    for (y = 0; y < info.height; y++) {
        const unsigned char *in = rayo_image_row(src, y);
        unsigned char *out = rayo_image_row(dst, y);
        for (x = 0; x < info.width; x++)
            rayo_bit_set(out, x, luminance_1000(src, in, x) < half);
    }
    return RAYO_OK;
}

/* BIT to 8-bit, channels 1 or 3: black 0, white 255. */
static rayo_status expand_bits(const rayo_image *src, rayo_image *dst,
                               unsigned channels, rayo_error *err)
{
    rayo_image_info info =
        channels == 1 ? rayo_image_info_gray8(src->info.width,
                                              src->info.height)
                      : rayo_image_info_rgb8(src->info.width,
                                             src->info.height);
    uint32_t x, y;
    rayo_status status = create(dst, &info, err);
    if (status != RAYO_OK)
        return status;
    for (y = 0; y < info.height; y++) {
        const unsigned char *in = rayo_image_row(src, y);
        unsigned char *out = rayo_image_row(dst, y);
        for (x = 0; x < info.width; x++)
            memset(out + (size_t)x * channels,
                   rayo_bit_get(in, x) ? 0 : 255, channels);
    }
    return RAYO_OK;
}

/* src as gray (channels 1, by luminance) or RGB (channels 3, a gray
 * sample in all three), in its own sample type. */
static rayo_status to_channels(const rayo_image *src, rayo_image *dst,
                               unsigned channels, rayo_error *err)
{
    rayo_image_info info = src->info;
    uint32_t x, y;
    unsigned c;
    rayo_status status;
    if (src->info.sample == RAYO_SAMPLE_BIT)
        return expand_bits(src, dst, channels, err);
    if (src->info.channels == channels)
        return copy_image(src, dst, err);
    info.channels = channels;
    status = create(dst, &info, err);
    if (status != RAYO_OK)
        return status;
    for (y = 0; y < info.height; y++) {
        const unsigned char *in = rayo_image_row(src, y);
        unsigned char *out = rayo_image_row(dst, y);
        for (x = 0; x < info.width; x++) {
            if (channels == 1) {
                sample_put(&info, out, x,
                           (unsigned)((luminance_1000(src, in, x) + 500) /
                                      1000));
                continue;
            }
            for (c = 0; c < channels; c++)
                sample_put(&info, out, channels * (size_t)x + c,
                           sample_at(src, in, x));
        }
    }
    return RAYO_OK;
}

rayo_status rayo_image_to_gray(const rayo_image *src, rayo_image *dst,
                               rayo_error *err)
{
    return to_channels(src, dst, 1, err);
}

rayo_status rayo_image_to_rgb(const rayo_image *src, rayo_image *dst,
                              rayo_error *err)
{
    return to_channels(src, dst, 3, err);
}
