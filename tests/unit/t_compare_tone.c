/*
 * t_compare_tone.c - the tone comparison on small images made here,
 * whose numbers can be worked out by hand: per-channel counts, largest
 * difference, RMSE and PSNR; which differences an edge or the shading
 * explains and which nothing does; the verdicts; the diagnoses that
 * undo a mistake (channel order, offset, flip, shift, size); bilevel
 * images still compared as masks; the JSON form; the window extremes
 * the comparison's maps are made with, against a plain search.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

#include "../../src/compare/tone/tone_impl.h"

static rayo_image gray(uint32_t w, uint32_t h, unsigned char fill)
{
    rayo_image image;
    rayo_image_info info = rayo_image_info_gray8(w, h);
    rayo_image_create(&image, &info, NULL);
    memset(image.pixels, fill, image.stride * h);
    return image;
}

static rayo_image rgb(uint32_t w, uint32_t h)
{
    rayo_image image;
    rayo_image_info info = rayo_image_info_rgb8(w, h);
    rayo_image_create(&image, &info, NULL);
    return image;
}

static unsigned char *at(rayo_image *image, uint32_t x, uint32_t y)
{
    return rayo_image_row(image, y) + (size_t)x * image->info.channels;
}

static rayo_compare_report compare(const rayo_image *ref,
                                   const rayo_image *image, unsigned levels)
{
    rayo_compare_options o;
    rayo_compare_report r;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_compare_options_init(&o);
    o.levels = levels;
    o.course = RAYO_COMPARE_COURSE_NONE;
    if (rayo_compare_images(ref, image, &o, &r, &err) != RAYO_OK) {
        ok(0, "compare failed: %.200s", err.message);
        memset(&r, 0, sizeof r);
    }
    return r;
}

static void test_statistics(void)
{
    /* 8x8 of 100, two pixels off by 10: sum of squares 200 over 64. */
    rayo_image a = gray(8, 8, 100), b = gray(8, 8, 100);
    rayo_compare_report r;
    double rmse = sqrt(200.0 / 64);
    at(&b, 3, 3)[0] = 110;
    at(&b, 5, 5)[0] = 90;
    r = compare(&a, &b, 1);
    is_int(r.kind, RAYO_COMPARE_TONE, "gray: compared by value");
    is_int(r.tone.channels, 1, "  one channel");
    is_int(r.tone.channel[0].beyond, 2, "  two pixels off by more than 1");
    is_int(r.tone.channel[0].max_difference, 10, "  largest difference 10");
    is_double(r.tone.channel[0].rmse, rmse, 1e-9, "  RMSE sqrt(200/64)");
    is_double(r.tone.channel[0].psnr, 20 * log10(255 / rmse), 1e-9,
              "  PSNR 20 log10(255 / RMSE)");
    is_int(r.tone.unexplained, 2, "  on a flat picture nothing explains them");
    is_int(r.tone.first_x * 100 + r.tone.first_y, 303,
           "  the first unexplained is (3, 3)");
    is_int(r.verdict, RAYO_VERDICT_INCONSISTENT, "  inconsistent");
    r = compare(&a, &b, 10);
    is_int(r.verdict, RAYO_VERDICT_IDENTICAL, "  with --levels 10: identical");
    rayo_image_free(&a);
    rayo_image_free(&b);
}

/* 16x16: columns 0-7 black, 8-15 at 200; the edge between 7 and 8. */
static rayo_image edge_image(void)
{
    rayo_image image = gray(16, 16, 0);
    uint32_t x, y;
    for (y = 0; y < 16; y++)
        for (x = 8; x < 16; x++)
            at(&image, x, y)[0] = 200;
    return image;
}

static void test_edges(void)
{
    rayo_image a = edge_image(), b = edge_image(), c = edge_image();
    rayo_compare_report r;
    uint32_t y;
    /* The edge a pixel to the right in four rows: the outline moved. */
    for (y = 0; y < 4; y++)
        at(&b, 8, y)[0] = 0;
    r = compare(&a, &b, 1);
    is_int(r.tone.differing, 4, "edge moved in 4 rows: 4 pixels differ");
    is_int(r.tone.at_edges, 4, "  all 4 at the outline");
    is_int(r.tone.max_edge_difference, 200, "  by 200 levels");
    is_int(r.verdict, RAYO_VERDICT_CONSISTENT, "  consistent");
    /* A bright pixel 5 columns from the edge: nothing explains it. */
    at(&c, 2, 8)[0] = 200;
    r = compare(&a, &c, 1);
    is_int(r.tone.unexplained, 1, "a stray bright pixel: unexplained");
    is_int(r.verdict, RAYO_VERDICT_INCONSISTENT, "  inconsistent");
    rayo_image_free(&a);
    rayo_image_free(&b);
    rayo_image_free(&c);
}

static void test_shading(void)
{
    /* A ramp of 10 levels a pixel (no edge: every step is like its
       neighbours); four rows of the image a pixel ahead. */
    rayo_image a = gray(24, 16, 0), b = gray(24, 16, 0);
    rayo_compare_report r;
    uint32_t x, y;
    for (y = 0; y < 16; y++)
        for (x = 0; x < 24; x++) {
            at(&a, x, y)[0] = (unsigned char)(10 * x);
            at(&b, x, y)[0] = (unsigned char)(10 * (x + (y < 4)));
        }
    r = compare(&a, &b, 1);
    is_int(r.tone.differing, 4 * 24, "a ramp a pixel ahead in 4 rows");
    is_int(r.tone.in_shading, 4 * 24, "  explained by the shading");
    is_int(r.tone.at_edges, 0, "  no edge in a ramp");
    is_int(r.verdict, RAYO_VERDICT_CONSISTENT, "  consistent");
    /* The same rows 25 levels up: no pixel of the ramp within 2 px
       has those values (give or take a step). */
    for (y = 0; y < 4; y++)
        for (x = 0; x < 24; x++)
            at(&b, x, y)[0] = (unsigned char)(10 * x + 35);
    r = compare(&a, &b, 1);
    ok(r.tone.unexplained > 0, "  35 levels off: unexplained (%llu)",
       (unsigned long long)r.tone.unexplained);
    rayo_image_free(&a);
    rayo_image_free(&b);
}

/* A 32x24 colour picture: black, with a blob of (255, 128, 0). */
static rayo_image blob(int swapped)
{
    rayo_image image = rgb(32, 24);
    uint32_t x, y;
    for (y = 6; y < 18; y++)
        for (x = 10; x < 22; x++) {
            unsigned char *p = at(&image, x, y);
            p[0] = swapped ? 0 : 255;
            p[1] = 128;
            p[2] = swapped ? 255 : 0;
        }
    return image;
}

static void test_diagnoses(void)
{
    rayo_image a = blob(0), b = blob(1), c = rgb(32, 24), d = rgb(16, 24);
    rayo_image e = gray(32, 24, 0), f = gray(32, 24, 0);
    rayo_compare_report r;
    uint32_t x, y;
    r = compare(&a, &b, 1);
    is_int(r.tone.channels, 3, "colour: three channels");
    is_int(r.diagnosis, RAYO_DIAGNOSIS_CHANNELS_SWAPPED,
           "R and B swapped: channels-swapped");
    is_int(r.tone.order[0] * 100 + r.tone.order[1] * 10 + r.tone.order[2],
           210, "  order 2, 1, 0");
    ok(r.diagnosis_exact, "  exactly");
    /* Upside down: the picture's rows mirrored (the blob moved up first,
       so that the flip moves it). */
    for (y = 0; y < 20; y++)
        memcpy(rayo_image_row(&a, y), rayo_image_row(&a, y + 4), 32 * 3);
    memset(rayo_image_row(&a, 20), 0, 4 * 32 * 3);
    for (y = 0; y < 24; y++)
        memcpy(rayo_image_row(&c, y), rayo_image_row(&a, 23 - y), 32 * 3);
    r = compare(&a, &c, 1);
    is_int(r.verdict * 100 + r.diagnosis,
           RAYO_VERDICT_INCONSISTENT * 100 +
               RAYO_DIAGNOSIS_FLIPPED_VERTICALLY,
           "rows mirrored: inconsistent, flipped vertically");
    r = compare(&a, &d, 1);
    is_int(r.diagnosis, RAYO_DIAGNOSIS_DIFFERENT_SIZE,
           "16x24 against 32x24: different size");
    /* A gray disc 5 levels darker on black: an offset. */
    for (y = 4; y < 20; y++)
        for (x = 8; x < 24; x++) {
            at(&e, x, y)[0] = 100;
            at(&f, x, y)[0] = 95;
        }
    r = compare(&e, &f, 1);
    is_int(r.diagnosis, RAYO_DIAGNOSIS_OFFSET,
           "a disc 5 levels darker: offset");
    is_int(r.tone.offset[0], -5, "  of -5");
    ok(r.tone.offset_on_shapes, "  on the objects, not the black background");
    /* Moved a row down: a shift, said as (0, +1). */
    memset(f.pixels, 0, f.stride * 24);
    for (y = 5; y < 21; y++)
        for (x = 8; x < 24; x++)
            at(&f, x, y)[0] = 100;
    r = compare(&e, &f, 1);
    is_int(r.verdict * 100 + r.diagnosis,
           RAYO_VERDICT_INCONSISTENT * 100 + RAYO_DIAGNOSIS_SHIFTED,
           "a row lower: inconsistent, shifted");
    is_int(r.shift_x * 10 + r.shift_y, 1, "  by (0, +1)");
    rayo_image_free(&a);
    rayo_image_free(&b);
    rayo_image_free(&c);
    rayo_image_free(&d);
    rayo_image_free(&e);
    rayo_image_free(&f);
}

static void test_forms(void)
{
    rayo_image a = gray(8, 8, 0), b = gray(8, 8, 255), c = gray(8, 8, 0);
    rayo_compare_report r;
    char text[4096];
    /* Black and white only: bilevel, so a mask comparison. */
    r = compare(&a, &b, 1);
    is_int(r.kind, RAYO_COMPARE_MASK, "0 and 255 only: compared as masks");
    r = compare(&a, &c, 1);
    rayo_compare_format_json(&r, text, sizeof text);
    ok(strstr(text, "{\"reference\": {") == text,
       "  the mask JSON is as it was");
    at(&c, 1, 1)[0] = 7;
    r = compare(&a, &c, 1);
    rayo_compare_format_json(&r, text, sizeof text);
    ok(strstr(text, "{\"kind\": \"tone\"") == text, "tone JSON: kind tone");
    ok(strstr(text, "\"psnr\": ") != NULL, "  with the PSNR");
    r = compare(&c, &c, 1);
    rayo_compare_format_json(&r, text, sizeof text);
    ok(strstr(text, "\"psnr\": null") != NULL,
       "  an infinite PSNR is null in JSON");
    rayo_compare_format_text(&r, text, sizeof text);
    ok(strstr(text, "PSNR infinite") != NULL, "  and 'infinite' in text");
    is_int(rayo_compare_format_diagnosis(&r, text, sizeof text), 4,
           "  no diagnosis: 'none'");
    rayo_image_free(&a);
    rayo_image_free(&b);
    rayo_image_free(&c);
}

static void test_windows(void)
{
    /* Random lines and radii against the obvious double loop. */
    unsigned char in[97], out[97], prefix[97 + 2 * 9], suffix[97 + 2 * 9];
    unsigned seed = 12345, wrong = 0, n, r, i, j, max;
    for (n = 1; n <= 97; n += 8)
        for (r = 0; r <= 9; r++)
            for (max = 0; max <= 1; max++) {
                for (i = 0; i < n; i++) {
                    seed = seed * 1103515245u + 12345u;
                    in[i] = (unsigned char)(seed >> 16);
                }
                tone_window_line(in, 1, out, 1, n, (int)r, (int)max, prefix,
                                 suffix);
                for (i = 0; i < n; i++) {
                    unsigned char best = max ? 0 : 255;
                    for (j = i > r ? i - r : 0; j <= i + r && j < n; j++)
                        if (max ? in[j] > best : in[j] < best)
                            best = in[j];
                    wrong += out[i] != best;
                }
            }
    is_int(wrong, 0, "window extremes equal a plain search (lines 1-97, "
                     "radii 0-9)");
}

static void test_frame(void)
{
    /* A candidate cannot win by pushing what differs off the frame. */
    rayo_image a = gray(1, 1, 0), b = gray(1, 1, 200);
    rayo_image c = gray(64, 48, 0), d = gray(64, 48, 0);
    rayo_compare_report r;
    uint32_t x, y;
    r = compare(&a, &b, 1);
    ok(r.diagnosis != RAYO_DIAGNOSIS_SHIFTED &&
           r.diagnosis != RAYO_DIAGNOSIS_SCALED,
       "1x1, 0 against 200: not a shift nor a scale (%s)",
       rayo_compare_diagnosis_name(r.diagnosis));
    for (y = 0; y < 48; y++)
        for (x = 0; x < 64; x++) {
            at(&c, x, y)[0] = (unsigned char)(2 * x + y);
            at(&d, x, y)[0] = x == 63 ? 0 : (unsigned char)(2 * x + y);
        }
    r = compare(&c, &d, 1);
    is_int(r.tone.differing, 48, "a gradient with its last column black: "
                                 "48 pixels differ");
    ok(r.diagnosis != RAYO_DIAGNOSIS_SHIFTED, "  not a shift (%s)",
       rayo_compare_diagnosis_name(r.diagnosis));
    is_double(r.tone.scale_fit, 1, 0, "  and no scale fits better");
    rayo_image_free(&a);
    rayo_image_free(&b);
    rayo_image_free(&c);
    rayo_image_free(&d);
}

int main(void)
{
    test_statistics();
    test_edges();
    test_shading();
    test_diagnoses();
    test_forms();
    test_windows();
    test_frame();
    return tap_done();
}
