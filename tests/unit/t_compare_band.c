/*
 * t_compare_band.c - the second half of "consistent": mismatches near
 * the outline must also be a minority of the pixels there and fewer than
 * chance.  A checkerboard against its inverse (every pixel wrong, each
 * one a pixel from the other colour) and a checkerboard against a white
 * image are inconsistent; a disk drawn a pixel larger and a disk with a
 * few wrong outline pixels stay consistent.  The band (pixels within the
 * tolerance of the other colour) is checked against a search of every
 * pixel pair, with the near test's tolerances and beyond them; the same
 * rule on gray images.  Also the transposed copy the transposition
 * candidate reads, against a transposition pixel by pixel.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "bitmap.h"
#include "tap.h"

#include "../../src/compare/compare_impl.h"

static rayo_compare_report compare(const rayo_image *a, const rayo_image *b,
                                   double tolerance)
{
    return bitmap_compare(a, b, tolerance);
}

static void checkerboard(rayo_image *m, int phase)
{
    uint32_t x, y;
    for (y = 0; y < m->info.height; y++)
        for (x = 0; x < m->info.width; x++)
            bitmap_put(m, x, y, (int)((x + y + (uint32_t)phase) % 2));
}

static void disk(rayo_image *m, double cx, double cy, double r)
{
    uint32_t x, y;
    for (y = 0; y < m->info.height; y++)
        for (x = 0; x < m->info.width; x++)
            bitmap_put(m, x, y,
                       (x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r);
}

/* Pixels with a pixel of the other colour within t, by brute force. */
static uint64_t brute_band(const rayo_image *m, double t)
{
    uint32_t w = m->info.width, h = m->info.height, x, y, i, j;
    uint64_t n = 0;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            int found = 0, c = bitmap_get(m, x, y);
            for (j = 0; j < h && !found; j++)
                for (i = 0; i < w && !found; i++) {
                    double dx = (double)i - x, dy = (double)j - y;
                    found = bitmap_get(m, i, j) != c &&
                            dx * dx + dy * dy <= t * t;
                }
            n += (uint64_t)found;
        }
    return n;
}

static void test_checkerboards(void)
{
    rayo_image a = bitmap_make(16, 12), b = bitmap_make(16, 12);
    rayo_image white = bitmap_make(16, 12);
    rayo_compare_report r;
    checkerboard(&a, 0);
    checkerboard(&b, 1);
    r = compare(&a, &b, 2);
    /* every pixel wrong, every one a pixel from the other colour */
    ok(r.mismatches == 192 && r.beyond_tolerance == 0,
       "checkerboard vs inverse: 192 mismatches, none beyond 2 px");
    ok(r.band == 192 && r.crowded, "the band is all 192 pixels: crowded");
    ok(r.verdict == RAYO_VERDICT_INCONSISTENT,
       "checkerboard vs inverse: inconsistent (was consistent)");
    ok(r.diagnosis == RAYO_DIAGNOSIS_INVERTED && r.diagnosis_exact,
       "and the diagnosis found is the inversion");
    r = compare(&a, &white, 1);
    /* 96 mismatches of 192 in the band, half: the band's limit lets them
       pass, chance does not (96 black pixels placed at random against no
       black mismatch 96 times) */
    ok(r.mismatches == 96 && r.beyond_tolerance == 0 && r.band == 192,
       "checkerboard vs white: 96 mismatches, all near, band 192");
    ok(fabs(cmp_chance_mismatches(192, 96, 0) - 96) < 1e-9,
       "chance: 96 mismatches expected");
    ok(r.crowded && r.verdict == RAYO_VERDICT_INCONSISTENT &&
           r.diagnosis == RAYO_DIAGNOSIS_EMPTY,
       "checkerboard vs white: inconsistent, the image empty");
    rayo_image_free(&a);
    rayo_image_free(&b);
    rayo_image_free(&white);
}

static void test_disks(void)
{
    rayo_image a = bitmap_make(61, 47), b = bitmap_make(61, 47);
    rayo_compare_report r;
    static const double tolerances[] = {1, 1.5, 2, 3, 8, 9.5, 12};
    size_t i;
    disk(&a, 30.3, 23.6, 14);
    disk(&b, 30.3, 23.6, 15); /* a ring a pixel wide, all within 1 px */
    for (i = 0; i < sizeof tolerances / sizeof tolerances[0]; i++) {
        double t = tolerances[i];
        uint64_t want = brute_band(&a, t);
        r = compare(&a, &b, t);
        if (r.beyond_tolerance != 0)
            continue;
        ok(r.band == want, "disk grown by a pixel, tolerance %g: band %llu "
                           "(brute force %llu)",
           t, (unsigned long long)r.band, (unsigned long long)want);
        ok(r.verdict == RAYO_VERDICT_CONSISTENT && !r.crowded,
           "tolerance %g: consistent, %.0f%% of the band", t,
           100.0 * (double)r.mismatches / (double)r.band);
    }
    /* a few wrong pixels on the outline: still consistent */
    disk(&b, 30.3, 23.6, 14);
    bitmap_put(&b, 30, 10, !bitmap_get(&b, 30, 10));
    bitmap_put(&b, 16, 23, !bitmap_get(&b, 16, 23));
    bitmap_put(&b, 44, 24, !bitmap_get(&b, 44, 24));
    r = compare(&a, &b, 2);
    ok(r.mismatches == 3 && r.beyond_tolerance == 0 && !r.crowded &&
           r.verdict == RAYO_VERDICT_CONSISTENT,
       "three wrong outline pixels: consistent, %llu mismatches",
       (unsigned long long)r.mismatches);
    rayo_image_free(&a);
    rayo_image_free(&b);
}

static rayo_image gray_blocks(uint32_t w, uint32_t h, uint32_t block,
                              int inverse)
{
    rayo_image image;
    rayo_image_info info = rayo_image_info_gray8(w, h);
    uint32_t x, y;
    rayo_image_create(&image, &info, NULL);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            int on = (int)((x / block + y / block) % 2) != inverse;
            rayo_image_row(&image, y)[x] = (unsigned char)(on ? 200 : 40);
        }
    return image;
}

static void test_tones(void)
{
    rayo_image a = gray_blocks(48, 36, 2, 0), b = gray_blocks(48, 36, 2, 1);
    rayo_compare_report r = compare(&a, &b, 2);
    ok(r.kind == RAYO_COMPARE_TONE && r.tone.differing == 48 * 36 &&
           r.tone.unexplained == 0,
       "gray checkerboard vs inverse: every pixel differs, all explained");
    ok(r.band == 48 * 36 && r.crowded &&
           r.verdict == RAYO_VERDICT_INCONSISTENT,
       "its band is every pixel: inconsistent (was consistent)");
    rayo_image_free(&b);
    /* one value off by 3 at an edge: consistent, a small share */
    b = gray_blocks(48, 36, 2, 0);
    rayo_image_row(&b, 10)[11] = (unsigned char)(rayo_image_row(&b, 10)[11] +
                                                 3);
    r = compare(&a, &b, 2);
    ok(r.tone.differing == 1 && !r.crowded &&
           r.verdict == RAYO_VERDICT_CONSISTENT,
       "one pixel off by 3 levels: consistent");
    rayo_image_free(&a);
    rayo_image_free(&b);
}

static void test_transpose(void)
{
    static const uint32_t sizes[][2] = {
        {13, 21}, {64, 3}, {100, 77}, {8, 8}, {1, 9}, {130, 65}};
    size_t s;
    unsigned seed = 7;
    for (s = 0; s < sizeof sizes / sizeof sizes[0]; s++) {
        uint32_t w = sizes[s][0], h = sizes[s][1], x, y;
        rayo_image m = bitmap_make(w, h);
        cmp_mask in, out;
        unsigned char *bits;
        int same = 1;
        for (y = 0; y < h; y++)
            for (x = 0; x < w; x++) {
                seed = seed * 1103515245u + 12345u;
                bitmap_put(&m, x, y, (seed >> 16) & 1u);
            }
        in.width = w;
        in.height = h;
        in.stride = m.stride;
        in.bits = rayo_image_row(&m, 0);
        if (cmp_mask_transpose(&in, &out, &bits, NULL) != RAYO_OK)
            abort();
        for (y = 0; y < out.height; y++)
            for (x = 0; x < out.width; x++)
                same &= rayo_bit_get(cmp_mask_row(&out, y), x) ==
                        bitmap_get(&m, y, x);
        for (y = 0; y < out.height; y++) /* padding clear */
            for (x = out.width; x < 8 * cmp_row_bytes(out.width); x++)
                same &= !rayo_bit_get(cmp_mask_row(&out, y), x);
        ok(same && out.width == h && out.height == w,
           "%ux%u transposed eight by eight: pixel (x, y) is (y, x)", w, h);
        free(bits);
        rayo_image_free(&m);
    }
}

int main(void)
{
    test_checkerboards();
    test_disks();
    test_tones();
    test_transpose();
    return tap_done();
}
