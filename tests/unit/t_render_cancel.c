/*
 * t_render_cancel.c - rayo_render_options.cancel stops a render from
 * inside its bands, on every thread, and never at the cost of a wrong
 * row: for each path a frame can take (shaded samples, the one-ray hit
 * loop, the hit fast path of spans) and one or three threads,
 *   - a cancel callback that never asks changes nothing: the same bytes
 *     as a render without one;
 *   - one that asks halfway through (by its count of polls) fails the
 *     render with RAYO_ERR_CANCELLED, after which it is called at most
 *     once more per thread (the others see the stop without it), and
 *     the rows that did reach the sink are the frame's first rows, in
 *     order, each as the uncancelled render made it;
 *   - one that asks at once lets no row through.
 */
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

typedef struct poll_counter {
    atomic_long polls;
    long stop_after; /* polls answered 0 before the first 1; <0: never */
} poll_counter;

static int cancel_after(void *context)
{
    poll_counter *c = context;
    long n = atomic_fetch_add(&c->polls, 1);
    return c->stop_after >= 0 && n >= c->stop_after;
}

/* Compares each delivered row with the reference frame. */
typedef struct row_check {
    const rayo_image *reference;
    uint32_t next_row; /* rows delivered, in order */
    int wrong;
} row_check;

static rayo_status check_rows(void *context, const unsigned char *rows,
                              size_t stride, uint32_t first_row,
                              uint32_t count, rayo_error *err)
{
    row_check *c = context;
    uint32_t r;
    (void)err;
    if (first_row != c->next_row)
        c->wrong++;
    for (r = 0; r < count; r++)
        if (memcmp(rows + r * stride,
                   rayo_image_row(c->reference, first_row + r),
                   c->reference->stride) != 0)
            c->wrong++;
    c->next_row = first_row + count;
    return RAYO_OK;
}

typedef struct render_case {
    const char *name;
    const char *text;
    rayo_shade_mode shade;
    unsigned samples;
} render_case;

static const render_case cases[] = {
    {"phong, 2x2 samples",
     "light point -2 3 -1\nmaterial m color 0.8 0.4 0.2 kd 0.9 reflect 0.3\n"
     "sphere 0 0 4 1.5 material m\nsphere 1 1 3 0.5\n"
     "plane 0 -1.5 0 0 1 0 material m\n",
     RAYO_SHADE_PHONG, 2},
    {"hit, one ray (spans)", "sphere 0 0 4 1.5\nsphere 1 1 3 0.5\n",
     RAYO_SHADE_HIT, 1},
    {"hit, one ray (per-pixel loop)",
     "triangle -2 -2 4 2 -2 4 0 2 5\nsphere 1 1 3 0.5\n", RAYO_SHADE_HIT, 1},
    {"hit, 3x3 samples", "sphere 0 0 4 1.5\n", RAYO_SHADE_HIT, 3},
};

static void run_case(const render_case *rc, unsigned threads)
{
    rayo_scene_file file;
    rayo_camera camera;
    rayo_render_options options;
    rayo_image reference;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    poll_counter counter;
    row_check check;
    rayo_status status;
    long total;
    if (rayo_scene_file_parse(&file, "t.scene", rc->text, strlen(rc->text),
                              &err) != RAYO_OK) {
        printf("# %.200s\n", err.message);
        ok(0, "%s: the scene", rc->name);
        return;
    }
    file.camera.width = 320;
    file.camera.height = 96;
    rayo_render_options_init(&options);
    options.shade = rc->shade;
    options.samples = rc->samples;
    options.threads = threads;
    if (rayo_camera_spec_build(&file.camera, &camera, &err) != RAYO_OK ||
        rayo_render_image(&camera, file.scene, &options, &reference, &err) !=
            RAYO_OK) {
        printf("# %.200s\n", err.message);
        ok(0, "%s: the reference render", rc->name);
        rayo_scene_file_free(&file);
        return;
    }

    options.cancel = cancel_after;
    options.cancel_context = &counter;
    atomic_init(&counter.polls, 0);
    counter.stop_after = -1;
    check.reference = &reference;
    check.next_row = 0;
    check.wrong = 0;
    status = rayo_render(&camera, file.scene, &options, check_rows, &check,
                         &err);
    total = atomic_load(&counter.polls);
    ok(status == RAYO_OK && check.wrong == 0 && check.next_row == 96,
       "%s, %u thread(s): a cancel that never asks: the same frame",
       rc->name, threads);
    ok(total > 0, "%s, %u thread(s): polled %ld times", rc->name, threads,
       total);

    atomic_init(&counter.polls, 0);
    counter.stop_after = total / 2;
    check.next_row = 0;
    check.wrong = 0;
    status = rayo_render(&camera, file.scene, &options, check_rows, &check,
                         &err);
    is_int(status, RAYO_ERR_CANCELLED, "%s, %u thread(s): asked halfway: "
                                       "cancelled",
           rc->name, threads);
    ok(atomic_load(&counter.polls) <= counter.stop_after + 1 + threads,
       "%s, %u thread(s): called at most once more per thread (%ld after "
       "%ld)",
       rc->name, threads, (long)atomic_load(&counter.polls),
       counter.stop_after);
    ok(check.wrong == 0 && check.next_row < 96,
       "%s, %u thread(s): the rows delivered (%u) are the frame's first, "
       "right",
       rc->name, threads, (unsigned)check.next_row);

    atomic_init(&counter.polls, 0);
    counter.stop_after = 0;
    check.next_row = 0;
    check.wrong = 0;
    status = rayo_render(&camera, file.scene, &options, check_rows, &check,
                         &err);
    ok(status == RAYO_ERR_CANCELLED && check.next_row == 0,
       "%s, %u thread(s): asked at once: no row delivered", rc->name,
       threads);
    rayo_image_free(&reference);
    rayo_scene_file_free(&file);
}

int main(void)
{
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        run_case(&cases[i], 1);
        run_case(&cases[i], 3);
    }
    return tap_done();
}
