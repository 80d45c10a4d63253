/*
 * t_image_convert.c - the layout conversions at their boundaries: the
 * exact thresholds of the bilevel mask (gray and luminance at half the
 * maximum, for 8- and 16-bit samples), the rounding of luminance to gray,
 * and the expansion of bilevel to gray and RGB.  Expected values are
 * worked out by hand in the comments.
 */
#include <string.h>

#include "rayo.h"
#include "tap.h"

static void set_sample(rayo_image *image, uint32_t x, unsigned c,
                       unsigned value)
{
    unsigned char *row = rayo_image_row(image, 0);
    size_t i = (size_t)x * image->info.channels + c;
    uint16_t v = (uint16_t)value;
    if (image->info.sample == RAYO_SAMPLE_U8)
        row[i] = (unsigned char)value;
    else
        memcpy(row + 2 * i, &v, sizeof v);
}

static unsigned get_sample(const rayo_image *image, uint32_t x, unsigned c)
{
    const unsigned char *row = rayo_image_row(image, 0);
    size_t i = (size_t)x * image->info.channels + c;
    uint16_t v;
    if (image->info.sample == RAYO_SAMPLE_U8)
        return row[i];
    memcpy(&v, row + 2 * i, sizeof v);
    return v;
}

/* A one-row image with the given samples. */
static int make_row(rayo_image *image, unsigned channels, unsigned maxval,
                    const unsigned *samples, uint32_t width)
{
    rayo_image_info info;
    uint32_t x;
    unsigned c;
    info.width = width;
    info.height = 1;
    info.channels = channels;
    info.maxval = maxval;
    info.sample = maxval > 255 ? RAYO_SAMPLE_U16 : RAYO_SAMPLE_U8;
    if (rayo_image_create(image, &info, NULL) != RAYO_OK)
        return 0;
    for (x = 0; x < width; x++)
        for (c = 0; c < channels; c++)
            set_sample(image, x, c, samples[x * channels + c]);
    return 1;
}

static void test_gray_threshold(void)
{
    /* maxval 255: 2*127 = 254 < 255 black; 2*128 = 256 white.
       maxval 10: 2*4 = 8 < 10 black; 2*5 = 10 is not < 10: white. */
    static const unsigned gray8[] = {0, 127, 128, 255};
    static const unsigned gray10[] = {4, 5, 10, 0};
    static const unsigned gray16[] = {32767, 32768, 0, 65535};
    rayo_image src, dst;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    if (!make_row(&src, 1, 255, gray8, 4))
        return;
    is_int(rayo_image_to_bit(&src, &dst, &err), RAYO_OK, "gray8 to bit");
    is_int(rayo_image_row(&dst, 0)[0], 0xC0, "0 and 127 black, 128 and 255 "
                                             "white");
    is_int(dst.info.sample, RAYO_SAMPLE_BIT, "result is bilevel");
    rayo_image_free(&src);
    rayo_image_free(&dst);
    if (!make_row(&src, 1, 10, gray10, 4))
        return;
    rayo_image_to_bit(&src, &dst, &err);
    is_int(rayo_image_row(&dst, 0)[0], 0x90, "maxval 10: 4 black, 5 white, "
                                             "0 black");
    rayo_image_free(&src);
    rayo_image_free(&dst);
    if (!make_row(&src, 1, 65535, gray16, 4))
        return;
    rayo_image_to_bit(&src, &dst, &err);
    is_int(rayo_image_row(&dst, 0)[0], 0xA0, "16-bit: 32767 black, 32768 "
                                             "white");
    rayo_image_free(&src);
    rayo_image_free(&dst);
}

static void test_rgb_threshold(void)
{
    /* 2*(299*255) = 152490 < 255000: pure red is black.
       2*(587*255) = 299370: pure green is white.
       (128,128,128): 2*1000*128 = 256000: white; (127,...) black.
       (0,217,0): 2*587*217 = 254758 < 255000 black; 218: 255916 white. */
    static const unsigned rgb[] = {255, 0,   0,   0,   255, 0,
                                   128, 128, 128, 127, 127, 127,
                                   0,   217, 0,   0,   218, 0};
    rayo_image src, dst;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    if (!make_row(&src, 3, 255, rgb, 6))
        return;
    is_int(rayo_image_to_bit(&src, &dst, &err), RAYO_OK, "rgb to bit");
    is_int(rayo_image_row(&dst, 0)[0], 0x98, "red black, green white, "
                                             "gray 128 white, 127 black, "
                                             "green 217 black, 218 white");
    rayo_image_free(&dst);
    is_int(rayo_image_to_gray(&src, &dst, &err), RAYO_OK, "rgb to gray");
    /* (299*255 + 500)/1000 = 76.745 -> 76; 587*255 -> 150.185 -> 150 */
    is_int(get_sample(&dst, 0, 0), 76, "red is gray 76");
    is_int(get_sample(&dst, 1, 0), 150, "green is gray 150");
    is_int(get_sample(&dst, 2, 0), 128, "gray stays gray");
    is_int(dst.info.channels, 1, "one channel");
    rayo_image_free(&dst);
    rayo_image_free(&src);
}

static void test_gray_rounding(void)
{
    /* (299*1 + 500)/1000 = 0; (299*2 + 500)/1000 = 1 (1.098);
       (114*5 + 500)/1000 = 1 (1.07); 16-bit (65535,65535,65535) stays. */
    static const unsigned rgb16[] = {1, 0, 0, 2, 0, 0, 0, 0, 5,
                                     65535, 65535, 65535};
    rayo_image src, dst;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    if (!make_row(&src, 3, 65535, rgb16, 4))
        return;
    is_int(rayo_image_to_gray(&src, &dst, &err), RAYO_OK, "rgb16 to gray");
    is_int(get_sample(&dst, 0, 0), 0, "299/1000 rounds to 0");
    is_int(get_sample(&dst, 1, 0), 1, "598/1000 rounds to 1");
    is_int(get_sample(&dst, 2, 0), 1, "570/1000 rounds to 1");
    is_int(get_sample(&dst, 3, 0), 65535, "white stays 65535");
    is_int(dst.info.maxval, 65535, "maxval kept");
    rayo_image_free(&dst);
    rayo_image_free(&src);
}

static void test_bit_expansion(void)
{
    rayo_image_info info = rayo_image_info_bit(3, 1);
    rayo_image src, gray, rgb, again;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    if (rayo_image_create(&src, &info, &err) != RAYO_OK)
        return;
    rayo_image_row(&src, 0)[0] = 0xA0; /* black, white, black */
    is_int(rayo_image_to_gray(&src, &gray, &err), RAYO_OK, "bit to gray");
    is_int(gray.info.maxval, 255, "gray maxval 255");
    ok(get_sample(&gray, 0, 0) == 0 && get_sample(&gray, 1, 0) == 255 &&
           get_sample(&gray, 2, 0) == 0,
       "black 0, white 255");
    is_int(rayo_image_to_rgb(&src, &rgb, &err), RAYO_OK, "bit to rgb");
    ok(rgb.info.channels == 3 && get_sample(&rgb, 1, 0) == 255 &&
           get_sample(&rgb, 1, 2) == 255 && get_sample(&rgb, 2, 1) == 0,
       "white 255,255,255; black 0,0,0");
    is_int(rayo_image_to_bit(&rgb, &again, &err), RAYO_OK, "back to bit");
    is_int(rayo_image_row(&again, 0)[0], 0xA0, "bit -> rgb -> bit is exact");
    rayo_image_free(&again);
    is_int(rayo_image_to_rgb(&gray, &again, &err), RAYO_OK, "gray to rgb");
    ok(get_sample(&again, 1, 0) == 255 && get_sample(&again, 0, 2) == 0,
       "gray repeated in three channels");
    rayo_image_free(&again);
    rayo_image_free(&rgb);
    rayo_image_free(&gray);
    rayo_image_free(&src);
}

int main(void)
{
    test_gray_threshold();
    test_rgb_threshold();
    test_gray_rounding();
    test_bit_expansion();
    return tap_done();
}
