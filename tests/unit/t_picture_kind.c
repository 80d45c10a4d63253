/*
 * t_picture_kind.c - the kind of a picture (rayo_picture_kind_of), two
 * images showing the same picture whatever their layouts
 * (rayo_image_same_picture), and the report's note when the image's kind
 * is not the reference's (rayo_compare_note_kinds): its wording, its JSON
 * member, and nothing at all for a report that did not set the kinds.
 *
 * The images are built here pixel by pixel; not a test of the command's
 * finding of the course's images (tests/cli/compare_kinds.t).
 */
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

/* A w x h image of the layout, its samples set by fill(x, y, c). */
static rayo_image make(rayo_image_info info, unsigned (*fill)(uint32_t,
                                                              uint32_t,
                                                              unsigned))
{
    rayo_image image;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    uint32_t x, y;
    unsigned c;
    memset(&image, 0, sizeof image);
    if (rayo_image_create(&image, &info, &err) != RAYO_OK)
        return image;
    for (y = 0; y < info.height; y++) {
        unsigned char *row = rayo_image_row(&image, y);
        for (x = 0; x < info.width; x++)
            for (c = 0; c < info.channels; c++) {
                unsigned v = fill(x, y, c);
                if (info.sample == RAYO_SAMPLE_BIT) {
                    if (v)
                        row[x / 8] |= (unsigned char)(0x80u >> (x % 8));
                } else if (info.sample == RAYO_SAMPLE_U16) {
                    uint16_t s = (uint16_t)v;
                    memcpy(row + 2 * ((size_t)x * info.channels + c), &s, 2);
                } else {
                    row[(size_t)x * info.channels + c] = (unsigned char)v;
                }
            }
    }
    return image;
}

/* A black disc-ish square on white: 1 (black) in the bit image. */
static int inside(uint32_t x, uint32_t y)
{
    return x >= 2 && x < 6 && y >= 1 && y < 4;
}
static unsigned bit_square(uint32_t x, uint32_t y, unsigned c)
{
    (void)c;
    return (unsigned)inside(x, y);
}
static unsigned gray_square(uint32_t x, uint32_t y, unsigned c)
{
    (void)c;
    return inside(x, y) ? 0 : 255;
}
static unsigned gray16_square(uint32_t x, uint32_t y, unsigned c)
{
    (void)c;
    return inside(x, y) ? 0 : 65535;
}
static unsigned gray_ramp(uint32_t x, uint32_t y, unsigned c)
{
    (void)c;
    return (x * 30 + y) % 256;
}
static unsigned rgb_ramp_gray(uint32_t x, uint32_t y, unsigned c)
{
    (void)c;
    return (x * 30 + y) % 256;
}
static unsigned rgb_colour(uint32_t x, uint32_t y, unsigned c)
{
    return c == 0 && x == 3 && y == 2 ? 200 : (x * 30 + y) % 256;
}

int main(void)
{
    rayo_image bit = make(rayo_image_info_bit(8, 5), bit_square);
    rayo_image gray = make(rayo_image_info_gray8(8, 5), gray_square);
    rayo_image ramp = make(rayo_image_info_gray8(8, 5), gray_ramp);
    rayo_image rgb_gray = make(rayo_image_info_rgb8(8, 5), rgb_ramp_gray);
    rayo_image colour = make(rayo_image_info_rgb8(8, 5), rgb_colour);
    rayo_image wide = make(rayo_image_info_gray8(9, 5), gray_square);
    rayo_image_info info16 = rayo_image_info_gray8(8, 5);
    rayo_image gray16;
    rayo_compare_report report;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    char text[4096];

    info16.sample = RAYO_SAMPLE_U16;
    info16.maxval = 65535;
    gray16 = make(info16, gray16_square);

    is_int(rayo_picture_kind_of(&bit), RAYO_PICTURE_BILEVEL, "PBM: bilevel");
    is_int(rayo_picture_kind_of(&gray), RAYO_PICTURE_BILEVEL,
           "gray pixels only 0 and 255: bilevel");
    is_int(rayo_picture_kind_of(&gray16), RAYO_PICTURE_BILEVEL,
           "16-bit, only 0 and 65535: bilevel");
    is_int(rayo_picture_kind_of(&ramp), RAYO_PICTURE_GRAY, "a ramp: gray");
    is_int(rayo_picture_kind_of(&rgb_gray), RAYO_PICTURE_GRAY,
           "RGB with equal channels: gray");
    is_int(rayo_picture_kind_of(&colour), RAYO_PICTURE_COLOUR,
           "one pixel whose red differs: colour");
    is_int(rayo_picture_kind_exercise(RAYO_PICTURE_GRAY), RAYO_COURSE_EJ2,
           "gray pictures are EJ2's");
    is_string(rayo_picture_kind_name(RAYO_PICTURE_COLOUR), "colour",
              "the name of colour");

    ok(rayo_image_same_picture(&bit, &gray), "PBM and PGM of one square");
    ok(rayo_image_same_picture(&gray16, &bit), "16-bit and PBM: the same");
    ok(rayo_image_same_picture(&ramp, &rgb_gray), "gray and its RGB");
    ok(!rayo_image_same_picture(&rgb_gray, &colour), "one red value apart");
    ok(!rayo_image_same_picture(&gray, &wide), "one column wider: not");
    ok(!rayo_image_same_picture(&bit, &ramp), "square and ramp: not");

    /* A gray image against a bilevel reference, the reference EJ1's. */
    ok(rayo_compare_images(&bit, &ramp, NULL, &report, &err) == RAYO_OK,
       "compare a ramp with the square");
    rayo_compare_format_text(&report, text, sizeof text);
    ok(strstr(text, "note: your image") == NULL,
       "kinds not set: no note (reports of grade, the page)");
    rayo_compare_format_json(&report, text, sizeof text);
    ok(strstr(text, "\"kinds\"") == NULL, "  nor \"kinds\" in JSON");
    rayo_compare_note_kinds(&report, &bit, &ramp, RAYO_COURSE_EJ1);
    is_int(report.reference_picture, RAYO_PICTURE_BILEVEL,
           "the reference is bilevel");
    is_int(report.image_picture, RAYO_PICTURE_GRAY, "the image gray");
    rayo_compare_format_text(&report, text, sizeof text);
    ok(strstr(text, "note: your image is gray; this reference is exercise "
                    "1's black and white sphere (course:ej1): is your image "
                    "exercise 2's? Compare it with course:ej2\n") != NULL,
       "the note names EJ1 and suggests EJ2");
    rayo_compare_format_json(&report, text, sizeof text);
    ok(strstr(text, "\"kinds\": {\"reference\": \"bilevel\", \"image\": "
                    "\"gray\", \"reference_course\": \"ej1\"}") != NULL,
       "  and JSON says so");
    rayo_compare_note_kinds(&report, &bit, &ramp, RAYO_COURSE_EXERCISES);
    rayo_compare_format_text(&report, text, sizeof text);
    ok(strstr(text, "note: your image is gray and the reference is black "
                    "and white: are they pictures of the same exercise?") !=
           NULL,
       "another reference: both kinds named, no exercise");
    report.image_lossy_levels = 32;
    rayo_compare_note_kinds(&report, &bit, &ramp, RAYO_COURSE_EJ1);
    rayo_compare_format_text(&report, text, sizeof text);
    ok(strstr(text, "note: your image") == NULL, "a lossy image: no note");

    /* The same kind: nothing, whatever the reference is. */
    ok(rayo_compare_images(&bit, &gray, NULL, &report, &err) == RAYO_OK,
       "compare the square with itself as PGM");
    rayo_compare_note_kinds(&report, &bit, &gray, RAYO_COURSE_EJ1);
    rayo_compare_format_text(&report, text, sizeof text);
    ok(strstr(text, "note: your image") == NULL, "the same kind: no note");

    rayo_image_free(&bit);
    rayo_image_free(&gray);
    rayo_image_free(&gray16);
    rayo_image_free(&ramp);
    rayo_image_free(&rgb_gray);
    rayo_image_free(&colour);
    rayo_image_free(&wide);
    return tap_done();
}
