/*
 * t_compare_tone_cache.c - what makes the tone comparison fast without
 * changing a report (issue 16): the process's cache of maps, course
 * renders and mistake rows (tone_cache.c) gives back exactly what was
 * kept, misses an image one byte off, keeps at most its four entries
 * and frees them all; the scale search, which tries its candidates from
 * the middle out and stops a pass once it cannot win, picks the scale
 * that trying every candidate in order to the end picks (written out
 * here as it was), ties included; and a comparison made again in the
 * same process, from the cache, gives the same report, text and JSON,
 * as the first, for course scenes in gray and colour.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

#include "../../src/compare/tone/tone_impl.h"

/* A w x h tone image of `channels` with a smooth pattern and a disc. */
static tone_image pattern(uint32_t w, uint32_t h, unsigned channels,
                          unsigned seed)
{
    tone_image t;
    uint32_t x, y;
    unsigned c;
    memset(&t, 0, sizeof t);
    t.width = w;
    t.height = h;
    t.channels = channels;
    t.v = malloc((size_t)w * h * channels);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            for (c = 0; c < channels; c++) {
                double dx = (double)x - w / 2.0, dy = (double)y - h / 2.0;
                int in = dx * dx + dy * dy < (double)(h * h) / 9;
                t.v[((size_t)y * w + x) * channels + c] =
                    (unsigned char)(in ? 40 + (x * 3 + y * 2 + c * 17 + seed) %
                                                  180
                                       : (seed * 7 + c) % 3);
            }
    return t;
}

static int same_maps(const tone_image *a, const tone_image *b)
{
    size_t n = (size_t)a->width * a->height, m = n * a->channels;
    return a->near_radius == b->near_radius &&
           a->near_levels == b->near_levels &&
           memcmp(a->near, b->near, n) == 0 &&
           memcmp(a->slope, b->slope, n) == 0 &&
           memcmp(a->lo, b->lo, m) == 0 && memcmp(a->hi, b->hi, m) == 0;
}

static tone_image copy(const tone_image *t)
{
    tone_image c;
    size_t n = (size_t)t->width * t->height * t->channels;
    memset(&c, 0, sizeof c);
    c.width = t->width;
    c.height = t->height;
    c.channels = t->channels;
    c.v = malloc(n);
    memcpy(c.v, t->v, n);
    return c;
}

static void test_maps(void)
{
    tone_image a = pattern(61, 47, 3, 1), b = copy(&a), c = copy(&a);
    tone_image d = copy(&a);
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_compare_release_cache();
    ok(!tone_cache_find_maps(&b, 2, 1), "an empty cache has no maps");
    ok(tone_image_find_edges(&a, 2, 1, &err) == RAYO_OK, "maps made");
    ok(tone_image_find_edges_kept(&b, 2, 1, &err) == RAYO_OK &&
           same_maps(&a, &b),
       "find_edges_kept, a miss: the maps find_edges makes");
    ok(tone_cache_find_maps(&c, 2, 1) && same_maps(&a, &c),
       "then a copy of the same samples finds them: the same maps");
    ok(!tone_cache_find_maps(&d, 3, 1) && !tone_cache_find_maps(&d, 2, 0),
       "another radius or other levels: no maps");
    d.v[(size_t)30 * 61 * 3 + 7] ^= 1;
    ok(!tone_cache_find_maps(&d, 2, 1), "an image one byte off: no maps");
    tone_image_free(&a);
    tone_image_free(&b);
    tone_image_free(&c);
    tone_image_free(&d);
}

static void test_bounded(void)
{
    tone_image t[6];
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    unsigned i, found = 0;
    rayo_compare_release_cache();
    for (i = 0; i < 6; i++) {
        t[i] = pattern(40, 30, 1, 10 + i);
        tone_image_find_edges_kept(&t[i], 2, 1, &err);
    }
    for (i = 0; i < 6; i++) {
        tone_image c = copy(&t[i]);
        int hit = tone_cache_find_maps(&c, 2, 1);
        found += (unsigned)hit;
        if (i < 2)
            ok(!hit, "the oldest image %u was let go", i);
        tone_image_free(&c);
    }
    is_int(found, 4, "six images kept: four entries at most");
    rayo_compare_release_cache();
    for (i = 0; i < 6; i++) {
        tone_image c = copy(&t[i]);
        found = (unsigned)tone_cache_find_maps(&c, 2, 1);
        tone_image_free(&c);
        if (found)
            break;
        tone_image_free(&t[i]);
    }
    is_int(i, 6, "after rayo_compare_release_cache nothing is found");
    for (; i < 6; i++)
        tone_image_free(&t[i]);
}

static void test_course_and_rows(void)
{
    tone_image r = pattern(64, 48, 3, 3), got, part = pattern(64, 48, 3, 4);
    tone_image back = pattern(64, 48, 3, 0);
    size_t row = (size_t)64 * 3;
    rayo_compare_release_cache();
    ok(!tone_cache_find_course(RAYO_COURSE_EJ3, 3, &got), "no course render yet");
    tone_cache_keep_course(RAYO_COURSE_EJ3, &r);
    ok(tone_cache_find_course(RAYO_COURSE_EJ3, 3, &got) &&
           got.width == 64 && got.height == 48 &&
           memcmp(got.v, r.v, row * 48) == 0,
       "the course render kept is given back");
    tone_image_free(&got);
    ok(!tone_cache_find_course(RAYO_COURSE_EJ3, 1, &got) &&
           !tone_cache_find_course(RAYO_COURSE_EJ2, 3, &got),
       "not for other channels or another exercise");
    is_int(tone_cache_find_rows(RAYO_COURSE_EJ2, 1, &back), 0, "no rows yet");
    tone_cache_keep_rows(RAYO_COURSE_EJ2, 1, &part, 16);
    memset(back.v, 0, row * 48);
    is_int(tone_cache_find_rows(RAYO_COURSE_EJ2, 1, &back), 16,
           "sixteen rows kept, sixteen found");
    ok(memcmp(back.v, part.v, row * 16) == 0 && back.v[row * 16] == 0,
       "those rows, and nothing after them");
    tone_cache_keep_rows(RAYO_COURSE_EJ2, 1, &part, 48);
    is_int(tone_cache_find_rows(RAYO_COURSE_EJ2, 1, &back), 48,
           "then the whole render");
    ok(memcmp(back.v, part.v, row * 48) == 0, "all its rows");
    is_int(tone_cache_find_rows(RAYO_COURSE_EJ2, 2, &back), 0,
           "another mistake has none");
    rayo_compare_release_cache();
    is_int(tone_cache_find_rows(RAYO_COURSE_EJ2, 1, &back), 0,
           "cleared: none");
    tone_image_free(&r);
    tone_image_free(&part);
    tone_image_free(&back);
}

/* tone_best_scale as it was: every candidate in order, to the end. */
static double squares_of(const tone_counts *k)
{
    return k->sum_squares[0] + k->sum_squares[1] + k->sum_squares[2];
}

static double plain_best_scale(const tone_image *ref, const tone_image *image,
                               unsigned levels, double lo, double hi)
{
    double pixels = (double)ref->width * ref->height, best = 1, ratio;
    double fewest = HUGE_VAL;
    uint32_t step = (uint32_t)ceil(sqrt(pixels / 65536.0)), i;
    tone_xform t = tone_identity();
    tone_counts k;
    const uint32_t scan = 41, fine = 21;
    t.kind = TONE_SCALE;
    t.step = step > 0 ? step : 1;
    ratio = pow(hi / lo, 1.0 / (scan - 1));
    for (i = 0; i < scan; i++) {
        t.scale = lo * pow(ratio, i);
        tone_measure(ref, image, &t, 0, levels, -1, &k);
        if (squares_of(&k) < fewest) {
            fewest = squares_of(&k);
            best = t.scale;
        }
    }
    lo = best / ratio;
    hi = best * ratio;
    for (i = 0; i < fine; i++) {
        t.scale = lo + (hi - lo) * i / (fine - 1);
        tone_measure(ref, image, &t, 0, levels, -1, &k);
        if (squares_of(&k) < fewest) {
            fewest = squares_of(&k);
            best = t.scale;
        }
    }
    return best;
}

static void test_scale_search(void)
{
    static const double ranges[2][2] = {{0.98, 1.02}, {0.25, 4.0}};
    unsigned seed, r, channels;
    int all = 1, flat = 1;
    for (channels = 1; channels <= 3; channels += 2)
        for (seed = 0; seed < 4; seed++)
            for (r = 0; r < 2; r++) {
                tone_image a = pattern(90, 70, channels, seed);
                tone_image b = pattern(90, 70, channels, seed + r);
                uint64_t left;
                double squares;
                double want = plain_best_scale(&a, &b, 1, ranges[r][0],
                                               ranges[r][1]);
                double got = tone_best_scale(&a, &b, 1, ranges[r][0],
                                             ranges[r][1], &left, &squares);
                if (got != want)
                    all = 0;
                tone_image_free(&a);
                tone_image_free(&b);
            }
    ok(all, "the scale search picks what trying every scale in order picks");
    {
        /* flat images: every candidate ties, the first in order wins */
        tone_image a = pattern(50, 40, 1, 0), b = pattern(50, 40, 1, 0);
        uint64_t left;
        double squares;
        memset(a.v, 9, 50 * 40);
        memset(b.v, 9, 50 * 40);
        flat = tone_best_scale(&a, &b, 1, 0.98, 1.02, &left, &squares) ==
               plain_best_scale(&a, &b, 1, 0.98, 1.02);
        ok(flat, "all tied: the same first candidate");
        tone_image_free(&a);
        tone_image_free(&b);
    }
}

/* The course's render of exercise e as an image, values moved by add. */
static rayo_image course_image(rayo_course_exercise e, int add, int swap)
{
    rayo_image image, out;
    uint32_t y, x;
    size_t i, n;
    rayo_course_render(e, NULL, &image, NULL);
    rayo_image_create(&out, &image.info, NULL);
    n = (size_t)image.info.width * image.info.channels;
    for (y = 0; y < image.info.height; y++) {
        const unsigned char *a = rayo_image_row(&image, y);
        unsigned char *b = rayo_image_row(&out, y);
        for (i = 0; i < n; i++) {
            int v = a[i] + add;
            b[i] = (unsigned char)(v < 0 ? 0 : v > 255 ? 255 : v);
        }
        if (swap)
            for (x = 0; x < image.info.width; x++) {
                unsigned char t = b[3 * x];
                b[3 * x] = b[3 * x + 2];
                b[3 * x + 2] = t;
            }
    }
    rayo_image_free(&image);
    return out;
}

static char *report_of(const rayo_image *ref, const rayo_image *image)
{
    rayo_compare_options o;
    rayo_compare_report r;
    size_t a, b;
    char *text;
    rayo_compare_options_init(&o);
    if (rayo_compare_images(ref, image, &o, &r, NULL) != RAYO_OK)
        return NULL;
    a = rayo_compare_format_text(&r, NULL, 0);
    b = rayo_compare_format_json(&r, NULL, 0);
    text = malloc(a + b + 2);
    rayo_compare_format_text(&r, text, a + 1);
    rayo_compare_format_json(&r, text + a, b + 1);
    return text;
}

static void test_again(void)
{
    rayo_image ref2 = course_image(RAYO_COURSE_EJ2, 0, 0);
    rayo_image lighter = course_image(RAYO_COURSE_EJ2, 40, 0);
    rayo_image darker = course_image(RAYO_COURSE_EJ2, -7, 0);
    rayo_image ref3 = course_image(RAYO_COURSE_EJ3, 0, 0);
    rayo_image swapped = course_image(RAYO_COURSE_EJ3, 0, 1);
    char *first[3], *again[3];
    int k;
    rayo_compare_release_cache();
    first[0] = report_of(&ref2, &lighter);
    first[1] = report_of(&ref3, &swapped);
    first[2] = report_of(&ref2, &darker);
    again[0] = report_of(&ref2, &lighter);
    again[1] = report_of(&ref3, &swapped);
    again[2] = report_of(&ref2, &darker);
    for (k = 0; k < 3; k++)
        ok(first[k] != NULL && again[k] != NULL &&
               strcmp(first[k], again[k]) == 0,
           "pair %d compared again, from the cache: the same report", k);
    ok(first[0] != NULL && strstr(first[0], "+40 levels") != NULL,
       "  (the lighter EJ2: an offset of +40)");
    ok(first[1] != NULL && strstr(first[1], "channels-swapped") != NULL,
       "  (the swapped EJ3: channels swapped)");
    rayo_compare_release_cache();
    for (k = 0; k < 3; k++) {
        free(first[k]);
        free(again[k]);
    }
    rayo_image_free(&ref2);
    rayo_image_free(&lighter);
    rayo_image_free(&darker);
    rayo_image_free(&ref3);
    rayo_image_free(&swapped);
}

int main(void)
{
    test_maps();
    test_bounded();
    test_course_and_rows();
    test_scale_search();
    test_again();
    rayo_compare_release_cache();
    return tap_done();
}
