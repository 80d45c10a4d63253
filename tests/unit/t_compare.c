/*
 * t_compare.c - rayo_compare_images on masks built by hand: counts, IoU,
 * offsets and scale worked out in the comments; the distance of every
 * mismatch from the outline checked against a brute-force search over
 * every pixel pair on pseudo-random masks; verdicts and diagnoses of
 * flips, inversion and shifts made in memory; the report formats.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "bitmap.h"
#include "tap.h"

/* A filled disk of radius r centred on pixel (cx, cy). */
static void disk(rayo_image *m, double cx, double cy, double r)
{
    uint32_t x, y;
    for (y = 0; y < m->info.height; y++)
        for (x = 0; x < m->info.width; x++)
            if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r)
                bitmap_put(m, x, y, 1);
}

static rayo_compare_report compare(const rayo_image *a, const rayo_image *b,
                                   double tolerance)
{
    return bitmap_compare(a, b, tolerance);
}

static void test_square(void)
{
    /* 9x9, black 3x3 square at columns/rows 3..5; the image adds (0,0)
       and removes (4,4).  (0,0) is sqrt(3^2 + 3^2) from the nearest
       black pixel (3,3); (4,4) is 2 from the nearest white ones, (4,2)
       and (2,4), the square being rows and columns 3..5. */
    rayo_image a = bitmap_make(9, 9), b = bitmap_make(9, 9);
    rayo_compare_report r;
    uint32_t x, y;
    for (y = 3; y <= 5; y++)
        for (x = 3; x <= 5; x++) {
            bitmap_put(&a, x, y, 1);
            bitmap_put(&b, x, y, 1);
        }
    bitmap_put(&b, 0, 0, 1);
    bitmap_put(&b, 4, 4, 0);
    r = compare(&a, &b, 2);
    is_int(r.mismatches, 2, "square: 2 mismatches");
    is_int(r.reference_only, 1, "square: 1 black only in the reference");
    is_int(r.image_only, 1, "square: 1 black only in the image");
    is_double(r.iou, 8.0 / 10.0, 1e-12, "square: IoU = 8 / (9 + 1)");
    is_double(r.max_distance, sqrt(18.0), 1e-12, "square: farthest is (0,0), sqrt 18");
    is_int(r.beyond_tolerance, 1, "square: one mismatch beyond 2 px");
    is_double(r.mismatch_percent, 200.0 / 81, 1e-12, "square: 2 of 81 pixels");
    is_int(r.verdict, RAYO_VERDICT_INCONSISTENT, "square: inconsistent");
    r = compare(&a, &b, 4.25);
    is_int(r.beyond_tolerance, 0, "square, tolerance 4.25: none beyond");
    is_int(r.verdict, RAYO_VERDICT_CONSISTENT, "square, tolerance 4.25: consistent");
    rayo_image_free(&a);
    rayo_image_free(&b);
}

/* Brute force: the largest distance from a mismatch to a reference pixel
 * of the other colour. */
static double brute_max(const rayo_image *a, const rayo_image *b,
                        double tol, uint64_t *beyond)
{
    uint32_t w = a->info.width, h = a->info.height, x, y, i, j;
    double worst = 0;
    *beyond = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            double best = HUGE_VAL;
            int c = bitmap_get(a, x, y);
            if (c == bitmap_get(b, x, y))
                continue;
            for (j = 0; j < h; j++)
                for (i = 0; i < w; i++)
                    if (bitmap_get(a, i, j) != c) {
                        double d = hypot((double)i - x, (double)j - y);
                        if (d < best)
                            best = d;
                    }
            if (best > tol)
                (*beyond)++;
            if (best > worst)
                worst = best;
        }
    return worst;
}

static void test_random_distances(void)
{
    unsigned long seed = 12345;
    int round;
    for (round = 0; round < 6; round++) {
        uint32_t w = 13 + 7 * (uint32_t)round, h = 29 - 3 * (uint32_t)round;
        rayo_image a = bitmap_make(w, h), b = bitmap_make(w, h);
        rayo_compare_report r;
        uint64_t beyond, n = 0;
        uint32_t x, y;
        double want;
        /* a: a few blobs; b: a with sparse pixels flipped */
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++) {
                int black;
                seed = seed * 6364136223846793005ul + 1442695040888963407ul;
                black = ((x / 5 + y / 4 + round) % 3) == 0;
                bitmap_put(&a, x, y, black);
                bitmap_put(&b, x, y, ((seed >> 33) % 9 == 0) ? !black : black);
                n += ((seed >> 33) % 9 == 0);
            }
        want = brute_max(&a, &b, 1.5, &beyond);
        r = compare(&a, &b, 1.5);
        is_int(r.mismatches, n, "random %d (%ux%u): mismatches", round, w, h);
        is_double(r.max_distance, want, 1e-9, "random %d: largest distance as brute force", round);
        is_int(r.beyond_tolerance, beyond, "random %d: beyond 1.5 px as brute force", round);
        rayo_image_free(&a);
        rayo_image_free(&b);
    }
}

static void test_shapes(void)
{
    /* A disk of radius 12 at (30, 20) in 64x48, and the same at
       (33, 18): offset (+3, -2), scale 1, and a shift diagnosis. */
    rayo_image a = bitmap_make(64, 48), b = bitmap_make(64, 48), c = bitmap_make(64, 48);
    rayo_compare_report r;
    uint32_t x, y;
    disk(&a, 30, 20, 12);
    disk(&b, 33, 18, 12);
    r = compare(&a, &b, 2);
    is_double(r.offset_x, 3, 1e-9, "disk moved: offset x +3");
    is_double(r.offset_y, -2, 1e-9, "disk moved: offset y -2");
    is_double(r.scale, 1, 1e-12, "disk moved: scale 1");
    is_int(r.diagnosis, RAYO_DIAGNOSIS_SHIFTED, "disk moved: shifted");
    is_int(r.shift_x * 100 + r.shift_y, 3 * 100 - 2, "disk moved: by (3, -2)");
    /* c = a upside down */
    for (y = 0; y < 48; y++)
        for (x = 0; x < 64; x++)
            bitmap_put(&c, x, 47 - y, bitmap_get(&a, x, y));
    r = compare(&a, &c, 2);
    is_int(r.diagnosis, RAYO_DIAGNOSIS_FLIPPED_VERTICALLY, "disk flipped: flipped vertically");
    is_int(r.diagnosis_exact, 1, "disk flipped: undoing it is exact");
    /* c = a inverted */
    for (y = 0; y < 48; y++)
        for (x = 0; x < 64; x++)
            bitmap_put(&c, x, y, !bitmap_get(&a, x, y));
    r = compare(&a, &c, 2);
    is_int(r.diagnosis, RAYO_DIAGNOSIS_INVERTED, "disk inverted: inverted");
    is_int(r.mismatches, 64 * 48, "disk inverted: every pixel differs");
    is_double(r.iou, 0, 0, "disk inverted: IoU 0");
    /* radius 12 vs radius 6 at the same place: area ratio 1/4, scale 1/2 */
    memset(b.pixels, 0, b.stride * 48);
    disk(&b, 30, 20, 6);
    r = compare(&a, &b, 2);
    is_double(r.scale, 0.5, 0.02, "smaller disk: scale about 1/2 (%.4f)", r.scale);
    is_int(r.diagnosis, RAYO_DIAGNOSIS_OTHER_SPHERE, "smaller disk in place: another sphere");
    memset(b.pixels, 0, b.stride * 48);
    r = compare(&a, &b, 2);
    is_int(r.diagnosis, RAYO_DIAGNOSIS_EMPTY, "white image: empty");
    is_int(r.shapes_measured, 0, "white image: no shape to measure");
    rayo_image_free(&a);
    rayo_image_free(&b);
    rayo_image_free(&c);
}

static void test_layouts_and_sizes(void)
{
    /* A gray image of black and white only is bilevel: compared as a
       mask; one with another level is compared by value. */
    rayo_image a = bitmap_make(4, 1), g;
    rayo_image_info info = rayo_image_info_gray8(4, 1);
    rayo_compare_report r;
    rayo_compare_options bad;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    unsigned char *row;
    memset(&g, 0, sizeof g);
    rayo_image_create(&g, &info, NULL);
    row = rayo_image_row(&g, 0);
    row[0] = 0;
    row[1] = 0;
    row[2] = 255;
    row[3] = 255;
    bitmap_put(&a, 0, 0, 1);
    bitmap_put(&a, 1, 0, 1);
    r = compare(&a, &g, 2);
    is_int(r.kind * 10 + r.verdict,
           RAYO_COMPARE_MASK * 10 + RAYO_VERDICT_IDENTICAL,
           "gray 0 0 255 255 = bits 1 1 0 0, as masks");
    row[1] = 127;
    r = compare(&a, &g, 2);
    is_int(r.kind, RAYO_COMPARE_TONE, "gray 0 127 255 255: compared by value");
    is_int(r.tone.differing, 1, "  one pixel differs (127 against 0)");
    is_int(r.tone.channel[0].max_difference, 127, "  by 127 levels");
    rayo_compare_options_init(&bad);
    bad.tolerance = -1;
    is_int(rayo_compare_images(&a, &g, &bad, &r, &err), RAYO_ERR_INVALID, "negative tolerance refused");
    rayo_image_free(&a);
    rayo_image_free(&g);
    /* Different sizes are inconsistent even when they agree where they
       overlap: 6x4 on 8x4, centres (3,2) and (4,2) aligned. */
    a = bitmap_make(8, 4);
    g = bitmap_make(6, 4);
    r = compare(&a, &g, 2);
    is_int(r.verdict * 100 + r.diagnosis,
           RAYO_VERDICT_INCONSISTENT * 100 + RAYO_DIAGNOSIS_DIFFERENT_SIZE,
           "6x4 against 8x4: inconsistent, different size");
    is_int(r.pixels, 32, "the reference's frame is compared");
    rayo_image_free(&a);
    rayo_image_free(&g);
}

static void test_format(void)
{
    rayo_image a = bitmap_make(9, 9), b = bitmap_make(9, 9);
    rayo_compare_report r;
    char small[16], text[2048], json_en[2048];
    size_t need;
    bitmap_put(&a, 4, 4, 1);
    bitmap_put(&b, 4, 4, 1);
    bitmap_put(&b, 4, 5, 1);
    r = compare(&a, &b, 2);
    need = rayo_compare_format_json(&r, small, sizeof small);
    ok(need > sizeof small, "JSON longer than a small buffer: full length returned (%zu)", need);
    is_int(strlen(small), sizeof small - 1, "the small buffer is filled and terminated");
    is_int(rayo_compare_format_json(&r, text, sizeof text), need, "the same length with room");
    ok(strstr(text, "\"mismatches\": 1,") != NULL, "JSON: mismatches 1");
    ok(strstr(text, "\"verdict\": \"consistent\"") != NULL, "JSON: consistent");
    rayo_compare_format_text(&r, text, sizeof text);
    ok(strstr(text, "\nverdict: consistent\n") != NULL, "text: verdict line");
    ok(strstr(text, "mismatched pixels: 1 of 81 (1.235%)") != NULL, "text: 1 of 81 = 1.235%%");
    /* The report's language: the text in Spanish with decimal commas,
       cut to a small buffer as snprintf would; the JSON unchanged. */
    rayo_compare_format_json(&r, json_en, sizeof json_en);
    r.lang = RAYO_LANG_ES;
    need = rayo_compare_format_text(&r, text, sizeof text);
    is_int(strlen(text), need, "Spanish text: its whole length returned");
    ok(strstr(text, "\nveredicto: coincide\n") != NULL, "Spanish text: verdict line");
    ok(strstr(text, "píxeles distintos: 1 de 81 (1,235 %)") != NULL, "Spanish text: 1 de 81 = 1,235 %%");
    is_int(rayo_compare_format_text(&r, small, sizeof small), need, "Spanish text into a small buffer: the same length");
    is_int(strlen(small), sizeof small - 1, "  the small buffer filled and terminated");
    ok(strncmp(small, text, sizeof small - 1) == 0, "  with the text's first bytes");
    rayo_compare_format_json(&r, text, sizeof text);
    is_string(text, json_en, "Spanish report: the JSON byte for byte the English one");
    is_string(rayo_compare_diagnosis_name(RAYO_DIAGNOSIS_FLIPPED_HORIZONTALLY), "flipped-horizontally", "diagnosis names");
    is_string(rayo_compare_verdict_name(RAYO_VERDICT_IDENTICAL), "identical", "verdict names");
    rayo_image_free(&a);
    rayo_image_free(&b);
}

int main(void)
{
    test_square();
    test_random_distances();
    test_shapes();
    test_layouts_and_sizes();
    test_format();
    return tap_done();
}
