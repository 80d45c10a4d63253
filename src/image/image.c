/*
 * image.c - checking image headers and owning whole-frame pixel buffers.
 *
 * Every size is checked against limits.h, and every product against
 * overflow, before memory is requested.
 */
#include "rayo/image.h"

#include <stdlib.h>

#include "rayo/limits.h"

static rayo_image_info make_info(uint32_t width, uint32_t height,
                                 unsigned channels, unsigned maxval,
                                 rayo_sample_type sample)
{
    rayo_image_info info;
    info.width = width;
    info.height = height;
    info.channels = channels;
    info.maxval = maxval;
    info.sample = sample;
    return info;
}

rayo_image_info rayo_image_info_bit(uint32_t width, uint32_t height)
{
    return make_info(width, height, 1, 1, RAYO_SAMPLE_BIT);
}

rayo_image_info rayo_image_info_gray8(uint32_t width, uint32_t height)
{
    return make_info(width, height, 1, 255, RAYO_SAMPLE_U8);
}

rayo_image_info rayo_image_info_rgb8(uint32_t width, uint32_t height)
{
    return make_info(width, height, 3, 255, RAYO_SAMPLE_U8);
}

rayo_status rayo_image_info_check(const rayo_image_info *info,
                                  rayo_error *err)
{
    if (info->width < 1 || info->height < 1 ||
        info->width > RAYO_MAX_DIMENSION || info->height > RAYO_MAX_DIMENSION)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "image size %lux%lu is out of range; expected "
                              "1 to %u pixels each way",
                              (unsigned long)info->width,
                              (unsigned long)info->height, RAYO_MAX_DIMENSION);
    if ((uint64_t)info->width * info->height > RAYO_MAX_PIXELS)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "image size %lux%lu is more than %lu pixels",
                              (unsigned long)info->width,
                              (unsigned long)info->height, RAYO_MAX_PIXELS);
    switch (info->sample) {
    case RAYO_SAMPLE_BIT:
        if (info->channels == 1 && info->maxval == 1)
            return RAYO_OK;
        break;
    case RAYO_SAMPLE_U8:
        if ((info->channels == 1 || info->channels == 3) &&
            info->maxval >= 1 && info->maxval <= 255)
            return RAYO_OK;
        break;
    case RAYO_SAMPLE_U16:
        if ((info->channels == 1 || info->channels == 3) &&
            info->maxval >= 1 && info->maxval <= 65535)
            return RAYO_OK;
        break;
    }
    return rayo_error_set(err, RAYO_ERR_INVALID,
                          "inconsistent image layout: %u channels, maxval %u",
                          info->channels, info->maxval);
}

size_t rayo_image_info_row_bytes(const rayo_image_info *info)
{
    switch (info->sample) {
    case RAYO_SAMPLE_BIT:
        return ((size_t)info->width + 7) / 8;
    case RAYO_SAMPLE_U8:
        return (size_t)info->width * info->channels;
    case RAYO_SAMPLE_U16:
        return (size_t)info->width * info->channels * 2;
    }
    return 0;
}

rayo_status rayo_image_create(rayo_image *image, const rayo_image_info *info,
                              rayo_error *err)
{
    rayo_status status = rayo_image_info_check(info, err);
    size_t stride;
    image->pixels = NULL;
    image->stride = 0;
    image->info = *info;
    if (status != RAYO_OK)
        return status;
    /* width * height <= 2^30 and at most 6 bytes a pixel: no overflow. */
    stride = rayo_image_info_row_bytes(info);
    image->pixels = calloc(info->height, stride);
    if (image->pixels == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "out of memory for a %lux%lu image",
                              (unsigned long)info->width,
                              (unsigned long)info->height);
    image->stride = stride;
    return RAYO_OK;
}

void rayo_image_free(rayo_image *image)
{
    free(image->pixels);
    image->pixels = NULL;
    image->stride = 0;
}
