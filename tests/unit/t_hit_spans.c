/*
 * t_hit_spans.c - the span fast path against the per-pixel loop, bit for
 * bit, on many seeded random scenes and cameras.
 *
 * The reference is the loop row.c ran before the fast path existed:
 * rayo_camera_ray for every pixel, then rayo_sphere_hit on each sphere
 * (and, separately, rayo_scene_hit_any).  Each frame is checked row by
 * row and also rendered in bands of consecutive rows, as render.c does,
 * where each span is followed from the row before; half of those bands
 * ask for rows as runs of black pixels (image/row_runs.h), which must be
 * in normal form and, packed into bits, give the same pixels.  The cases
 * aim at the places
 * where spans could go wrong: spheres tangent to some pixel's ray (delta
 * within rounding of zero), the camera inside a sphere or on its surface,
 * spheres behind, beside and across the camera plane, odd widths, every
 * field of view from a microdegree to almost 180, turned cameras.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/render/hit_spans.h"
#include "rayo.h"
#include "tap.h"

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;

/* splitmix64 */
static uint64_t next_u64(void)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static double uniform(double lo, double hi)
{
    return lo + (hi - lo) * ((double)(next_u64() >> 11) / 9007199254740992.0);
}

static unsigned below(unsigned n)
{
    return (unsigned)(next_u64() % n);
}

static rayo_vec3 random_point(double spread)
{
    return rayo_vec3_make(uniform(-spread, spread), uniform(-spread, spread),
                          uniform(-spread, spread));
}

static double random_fov(void)
{
    static const double extremes[] = {1e-6, 0.01, 1.0, 179.0, 179.999999};
    if (below(8) == 0)
        return extremes[below(5)];
    return uniform(1.0, 175.0);
}

static void random_camera(rayo_camera *camera)
{
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    uint32_t w = 1 + below(below(4) == 0 ? 9 : 160);
    uint32_t h = 1 + below(below(4) == 0 ? 9 : 120);
    rayo_vec3 origin = below(3) == 0 ? rayo_vec3_make(0, 0, 0)
                                     : random_point(3.0);
    if (rayo_camera_init(camera, w, h, random_fov(), origin, &err) !=
        RAYO_OK)
        abort();
    if (below(3) == 0) {
        rayo_vec3 target = rayo_vec3_add(origin, random_point(1.0));
        rayo_vec3 up = random_point(1.0);
        /* A degenerate choice leaves the default basis: still a case. */
        (void)rayo_camera_look_at(camera, target, up, &err);
    }
}

/* A sphere whose surface just touches the ray of pixel (i, j). */
static int tangent_sphere(const rayo_camera *camera, rayo_vec3 *center,
                          double *radius)
{
    uint32_t i = below(camera->width), j = below(camera->height);
    rayo_ray ray = rayo_camera_ray(camera, (double)i, (double)j);
    double t = uniform(0.5, 6.0);
    rayo_vec3 on_ray = rayo_vec3_add(ray.origin,
                                     rayo_vec3_scale(ray.direction, t));
    rayo_vec3 off = random_point(1.0);
    rayo_vec3 l;
    /* Move off the ray perpendicularly; the radius is that distance. */
    off = rayo_vec3_sub(off, rayo_vec3_scale(ray.direction,
                                             rayo_vec3_dot(off,
                                                           ray.direction)));
    if (rayo_vec3_length(off) == 0.0)
        return 0;
    *center = rayo_vec3_add(on_ray, off);
    l = rayo_vec3_sub(*center, ray.origin);
    /* The radius the exact test sees as tangent: sqrt(L.L - beta^2). */
    *radius = sqrt(rayo_vec3_dot(l, l) - pow(rayo_vec3_dot(l, ray.direction),
                                             2.0));
    return *radius > 0.0;
}

static void add_random_sphere(const rayo_camera *camera, rayo_scene *scene)
{
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_vec3 c = rayo_vec3_add(camera->origin, random_point(4.0));
    double r = uniform(0.01, 2.0);
    switch (below(7)) {
    case 0: /* camera inside */
        r = rayo_vec3_length(rayo_vec3_sub(c, camera->origin)) * 1.5 + 0.01;
        break;
    case 1: /* camera on the surface, up to rounding */
        r = rayo_vec3_length(rayo_vec3_sub(c, camera->origin));
        if (!(r > 0.0))
            r = 1.0;
        break;
    case 2:
    case 3:
        if (!tangent_sphere(camera, &c, &r))
            r = 1.0;
        break;
    case 4: /* across the camera plane, close to the camera */
        c = rayo_vec3_add(camera->origin,
                          rayo_vec3_add(rayo_vec3_scale(camera->right,
                                                        uniform(-2, 2)),
                                        rayo_vec3_scale(camera->forward,
                                                        uniform(-0.3, 0.3))));
        r = uniform(0.2, 1.0);
        break;
    default:
        break;
    }
    if (rayo_scene_add_sphere(scene, c, r, &err) != RAYO_OK)
        abort();
}

static int bit_of(const unsigned char *row, uint32_t i)
{
    return (row[i >> 3] >> (7 - (i & 7))) & 1;
}

typedef struct tally {
    long rows, wrong_plain, wrong_scene, black, white, padding, refused;
    long wrong_bands, tracked_rows;
    long rows_as_runs, rows_as_bits, bad_form;
} tally;

/* 1 when runs are in normal form for a row of width pixels: in order,
 * apart, not touching, inside the row. */
static int normal_form(const rayo_row_runs *runs, uint32_t width)
{
    uint32_t i;
    if (runs->count > RAYO_ROW_RUNS_MAX)
        return 0;
    for (i = 0; i < runs->count; i++) {
        if (runs->first[i] > runs->last[i] || runs->last[i] >= width)
            return 0;
        if (i > 0 && runs->first[i] <= runs->last[i - 1] + 1)
            return 0;
    }
    return 1;
}

/*
 * The frame rendered the way render.c does it, in bands of consecutive
 * rows that follow each span from the row before, the bands of random
 * heights (one row up to the whole frame), half of them asking for rows
 * as runs, which are checked and packed into the frame's bits; NULL when
 * spans decline.
 */
static unsigned char *render_in_bands(const rayo_camera *camera,
                                     const rayo_scene *scene, size_t bytes,
                                     tally *t)
{
    rayo_hit_spans *plan = rayo_hit_spans_plan(camera, scene);
    unsigned char *frame;
    rayo_row_runs *runs;
    uint32_t j = 0, r;
    if (plan == NULL)
        return NULL;
    frame = malloc(bytes * camera->height);
    runs = malloc(64 * sizeof *runs);
    if (frame == NULL || runs == NULL)
        abort();
    while (j < camera->height) {
        uint32_t left = camera->height - j;
        uint32_t band = below(4) == 0 ? left : 1 + below(64);
        int as_runs = below(2) == 0;
        if (band > left)
            band = left;
        if (as_runs && band > 64)
            band = 64;
        rayo_hit_spans_render_rows(plan, j, band, frame + bytes * j, bytes,
                                   as_runs ? runs : NULL);
        for (r = 0; as_runs && r < band; r++) {
            if (runs[r].count == RAYO_ROW_RUNS_BITS) {
                t->rows_as_bits++;
                continue;
            }
            t->rows_as_runs++;
            t->bad_form += !normal_form(&runs[r], camera->width);
            rayo_row_runs_to_bits(&runs[r], camera->width,
                                  frame + bytes * (j + r));
        }
        j += band;
    }
    rayo_hit_spans_free(plan);
    free(runs);
    return frame;
}

static void check_frame(const rayo_camera *camera, const rayo_scene *scene,
                        tally *t)
{
    size_t bytes = ((size_t)camera->width + 7) / 8;
    unsigned char *row = malloc(bytes);
    unsigned char *banded = render_in_bands(camera, scene, bytes, t);
    rayo_hit_spans *plan = rayo_hit_spans_plan(camera, scene);
    uint32_t i, j;
    size_t k;
    if (row == NULL)
        abort();
    for (j = 0; j < camera->height; j++) {
        t->rows++;
        if (plan == NULL) {
            t->refused++;
            continue;
        }
        memset(row, 0xA5, bytes);
        rayo_hit_spans_render(plan, j, row);
        if (camera->width % 8 != 0 &&
            (row[bytes - 1] & (0xFFu >> (camera->width % 8))) != 0)
            t->padding++;
        for (i = 0; i < camera->width; i++) {
            rayo_ray ray = rayo_camera_ray(camera, (double)i, (double)j);
            int plain = 0, got = bit_of(row, i);
            for (k = 0; k < rayo_scene_sphere_count(scene); k++)
                plain |= rayo_sphere_hit(rayo_scene_sphere(scene, k), &ray,
                                         0.0);
            t->wrong_plain += got != plain;
            t->wrong_scene += got != rayo_scene_hit_any(scene, &ray, 0.0);
            if (banded != NULL)
                t->wrong_bands += bit_of(banded + bytes * j, i) != plain;
            if (plain)
                t->black++;
            else
                t->white++;
        }
    }
    if (banded != NULL)
        t->tracked_rows += camera->height;
    rayo_hit_spans_free(plan);
    free(banded);
    free(row);
}

static void random_scenes(int count, tally *t)
{
    int n;
    for (n = 0; n < count; n++) {
        rayo_camera camera;
        rayo_scene *scene;
        rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
        unsigned spheres = 1 + below(5), s;
        random_camera(&camera);
        if (rayo_scene_create(&scene, &err) != RAYO_OK)
            abort();
        for (s = 0; s < spheres; s++)
            add_random_sphere(&camera, scene);
        if (below(2) == 0 && rayo_scene_prepare(scene, &err) != RAYO_OK)
            abort();
        check_frame(&camera, scene, t);
        rayo_scene_free(scene);
    }
}

/* The seed frame and a few large, thin frames with many tangent rows. */
static void fixed_scenes(tally *t)
{
    static const struct {
        uint32_t w, h;
        double fov, cx, cy, cz, r;
    } cases[] = {
        {640, 480, 90, 0.5, 0.75, 1.9, 0.8},
        {4097, 3, 90, 0.5, 0.75, 1.9, 0.8},
        {3, 4097, 90, 0.5, 0.75, 1.9, 0.8},
        {2001, 7, 0.001, 0.0, 0.0, 1e4, 0.05},
        {1001, 9, 179.9999, 0.0, -1.0, 0.0, 0.5},
        {999, 5, 90, 5.0, 0.0, 0.0, 1.0}, /* on the right axis */
        {999, 5, 90, 0.0, 0.0, -3.0, 1.0}, /* behind */
        {999, 5, 90, 0.0, 0.0, 0.0, 1.0},  /* centred on the camera */
        {301, 7, 90, 0.0, 0.0, 0.0, 1e-300}, /* a point at the camera */
        {301, 7, 90, 1e150, 1e150, 3e150, 2e150}, /* huge */
        {301, 7, 90, 1e160, 0.0, 1e160, 1.0}, /* past the error bounds */
        {301, 7, 90, 1e-150, 1e-150, 3e-150, 2e-150}, /* tiny */
        {257, 257, 90, 0.0, 0.0, 5.0, 1e-9}, /* smaller than a pixel */
        /* The widest rows: the span's ends hardly moving from row to
         * row (the middle of a sphere), and moving by hundreds of pixels
         * (its top, at the middle row), past what tracking follows. */
        {65536, 24, 90, 0.0, 0.0, 3.0, 2.9},
        {65536, 24, 90, 0.0, -1.0, 3.0, 1.0005},
    };
    size_t c;
    for (c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        rayo_camera camera;
        rayo_scene *scene;
        rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
        if (rayo_camera_init(&camera, cases[c].w, cases[c].h, cases[c].fov,
                             rayo_vec3_make(0, 0, 0), &err) != RAYO_OK ||
            rayo_scene_create(&scene, &err) != RAYO_OK ||
            rayo_scene_add_sphere(scene,
                                  rayo_vec3_make(cases[c].cx, cases[c].cy,
                                                 cases[c].cz),
                                  cases[c].r, &err) != RAYO_OK)
            abort();
        check_frame(&camera, scene, t);
        rayo_scene_free(scene);
    }
}

/* rayo_render_image goes through row.c, and so through the spans. */
static long render_differences(void)
{
    rayo_camera camera;
    rayo_scene *scene;
    rayo_render_options options;
    rayo_image image;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    long wrong = 0;
    uint32_t i, j;
    if (rayo_camera_init(&camera, 333, 211, 70, rayo_vec3_make(0, 0, 0),
                         &err) != RAYO_OK ||
        rayo_scene_create(&scene, &err) != RAYO_OK ||
        rayo_scene_add_sphere(scene, rayo_vec3_make(0.5, 0.75, 1.9), 0.8,
                              &err) != RAYO_OK ||
        rayo_scene_add_sphere(scene, rayo_vec3_make(-1, -0.5, 3), 1.2,
                              &err) != RAYO_OK)
        abort();
    rayo_render_options_init(&options);
    options.threads = 3;
    if (rayo_render_image(&camera, scene, &options, &image, &err) != RAYO_OK)
        abort();
    for (j = 0; j < camera.height; j++)
        for (i = 0; i < camera.width; i++) {
            rayo_ray ray = rayo_camera_ray(&camera, (double)i, (double)j);
            wrong += bit_of(rayo_image_row(&image, j), i) !=
                     rayo_scene_hit_any(scene, &ray, 0.0);
        }
    rayo_image_free(&image);
    rayo_scene_free(scene);
    return wrong;
}

/* With a plane in the scene, spans decline: there is no plan. */
static int declines_planes(void)
{
    rayo_camera camera;
    rayo_scene *scene;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_hit_spans *plan;
    if (rayo_camera_init(&camera, 64, 4, 90, rayo_vec3_make(0, 0, 0),
                         &err) != RAYO_OK ||
        rayo_scene_create(&scene, &err) != RAYO_OK ||
        rayo_scene_add_sphere(scene, rayo_vec3_make(0, 0, 3), 1, &err) !=
            RAYO_OK ||
        rayo_scene_add_plane(scene, rayo_vec3_make(0, -1, 0),
                             rayo_vec3_make(0, 1, 0), 0, &err) != RAYO_OK)
        abort();
    plan = rayo_hit_spans_plan(&camera, scene);
    rayo_hit_spans_free(plan);
    rayo_scene_free(scene);
    return plan == NULL;
}

/* An optional argument runs that many random scenes (default 600). */
int main(int argc, char **argv)
{
    tally t;
    int scenes = argc > 1 ? atoi(argv[1]) : 600;
    memset(&t, 0, sizeof t);
    fixed_scenes(&t);
    random_scenes(scenes, &t);
    is_int(t.refused, 0, "spans render every sphere-only row (%ld rows)",
           t.rows);
    is_int(t.wrong_plain, 0,
           "spans equal rayo_sphere_hit per pixel (%ld black, %ld white)",
           t.black, t.white);
    is_int(t.wrong_scene, 0, "spans equal rayo_scene_hit_any per pixel");
    is_int(t.wrong_bands, 0,
           "rows rendered in bands, each span followed from the row before, "
           "equal the per-pixel test (%ld rows)",
           t.tracked_rows);
    is_int(t.bad_form, 0,
           "rows asked for as runs are in normal form (%ld rows as runs, "
           "%ld as bits)",
           t.rows_as_runs, t.rows_as_bits);
    ok(t.rows_as_runs > 5000 && t.rows_as_bits > 1000,
       "rows asked for as runs come both ways");
    is_int(t.padding, 0, "padding bits are zero");
    ok(t.black > 100000 && t.white > 100000,
       "the cases hold both hits and misses");
    ok(declines_planes(), "a scene with a plane goes to the per-pixel loop");
    is_int(render_differences(), 0,
           "rayo_render_image (3 threads) equals the per-pixel test");
    return tap_done();
}
