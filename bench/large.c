/*
 * large.c - large frames of the seed's scene: 16384x12288 to raw PBM with
 * one thread and with all, to PNG against libpng alone encoding the same
 * rows, and the peak memory of 16384x16384 renders by the `rayo` command.
 *
 * Output goes to /dev/null (through rayo_output, as `-o /dev/null`
 * would), so the figures measure rendering, formatting and compression,
 * not the disk.  With the span fast path the hit-mode P4 frame takes
 * about half a millisecond, mostly memset.  Its thread scaling is
 * bounded by how late a helper starts (thread_start.c; the table gives
 * the bound next to the speed-up) and by how well the CPUs store bytes
 * at the same time (band_fill.c: the frame's bytes zeroed in bands, no
 * rendering, 1 thread against all).  Thread scaling is also measured on
 * the per-pixel loop, arithmetic rather than memory, by adding to the
 * scene a plane behind the camera (it changes no pixel, but spans only
 * take sphere-only scenes).  "libpng alone" is the rows already rendered
 * in memory and handed to libpng with the settings png_write.c uses;
 * keep the two in step when either changes.
 */
#include <png.h>
#include <stdio.h>
#include <sys/resource.h>
#include <zlib.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"

#define LARGE_WIDTH 16384u
#define LARGE_HEIGHT 12288u
#define RSS_SIDE "16384"
#define LOOP_WIDTH 4096u /* the per-pixel loop's frame */
#define LOOP_HEIGHT 3072u

typedef struct large_setup {
    rayo_camera camera;
    rayo_scene *scene;
} large_setup;

/* The seed's sphere; with plane_behind, also the plane z = -1000. */
static int large_init(large_setup *setup, uint32_t width, uint32_t height,
                      int plane_behind)
{
    rayo_error err;
    if (rayo_camera_init(&setup->camera, width, height, RAYO_SEED_FOV,
                         rayo_vec3_make(0, 0, 0), &err) != RAYO_OK ||
        rayo_scene_create(&setup->scene, &err) != RAYO_OK)
        return -1;
    if (plane_behind &&
        rayo_scene_add_plane(setup->scene, rayo_vec3_make(0, 0, -1000),
                             rayo_vec3_make(0, 0, 1), 0, &err) != RAYO_OK)
        return -1;
    return rayo_scene_add_sphere(setup->scene,
                                 rayo_vec3_make(RAYO_SEED_CENTER_X,
                                                RAYO_SEED_CENTER_Y,
                                                RAYO_SEED_CENTER_Z),
                                 RAYO_SEED_RADIUS, &err) == RAYO_OK
               ? 0
               : -1;
}

/* One render to /dev/null; seconds, or -1. */
static double render_to_null(const large_setup *setup, rayo_format format,
                             unsigned threads)
{
    rayo_render_options options;
    rayo_output *out;
    rayo_error err;
    double start = bench_now();
    rayo_render_options_init(&options);
    options.threads = threads;
    if (rayo_output_open(&out, "/dev/null", &err) != RAYO_OK ||
        bench_render_into(out, &setup->camera, setup->scene, &options,
                          format, 0) != 0)
        return -1;
    return bench_now() - start;
}

/* libpng alone: the frame's rows, already rendered, to /dev/null. */
static double libpng_alone(const rayo_image *image)
{
    FILE *null = fopen("/dev/null", "wb");
    png_structp png;
    png_infop info;
    uint32_t j;
    double start;
    if (null == NULL)
        return -1;
    start = bench_now();
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png == NULL ? NULL : png_create_info_struct(png);
    if (info == NULL || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        fclose(null);
        return -1;
    }
    png_init_io(png, null);
    png_set_compression_strategy(png, Z_RLE); /* as png_write.c */
    png_set_IHDR(png, info, image->info.width, image->info.height, 1,
                 PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    png_set_invert_mono(png);
    for (j = 0; j < image->info.height; j++)
        png_write_row(png, rayo_image_row(image, j));
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    fclose(null);
    return bench_now() - start;
}

static void throughput(bench_table *table, const large_setup *setup)
{
    unsigned all = rayo_cpu_count();
    double pixels = (double)LARGE_WIDTH * LARGE_HEIGHT;
    double one = -1, many = -1, png = -1, alone = -1;
    double fill_one = -1, fill_many = -1;
    size_t frame_bytes = (size_t)LARGE_WIDTH / 8 * LARGE_HEIGHT;
    rayo_render_options options;
    rayo_image image;
    rayo_error err;
    int r;
    rayo_render_options_init(&options);
    if (rayo_render_image(&setup->camera, setup->scene, &options, &image,
                          &err) != RAYO_OK) {
        bench_add(table, "large_error", "large frame could not render", -1,
                  "");
        return;
    }
    for (r = 0; r < bench_repeats(table); r++) {
        one = bench_best(one, render_to_null(setup, RAYO_FORMAT_PBM, 1));
        many = bench_best(many, render_to_null(setup, RAYO_FORMAT_PBM, all));
        png = bench_best(png, render_to_null(setup, RAYO_FORMAT_PNG, all));
        alone = bench_best(alone, libpng_alone(&image));
        fill_one =
            bench_best(fill_one, bench_band_fill_seconds(frame_bytes, 1));
        fill_many =
            bench_best(fill_many, bench_band_fill_seconds(frame_bytes, all));
    }
    rayo_image_free(&image);
    bench_add(table, "p4_1thread_gpps", "16384x12288 P4, 1 thread",
              pixels / one * 1e-9, "Gpixel/s");
    bench_add(table, "p4_all_gpps", "16384x12288 P4, all threads",
              pixels / many * 1e-9, "Gpixel/s");
    bench_add(table, "p4_all_s", "16384x12288 P4, all threads, time",
              many * 1e3, "ms");
    bench_add(table, "png_all_s", "16384x12288 PNG, all threads", png * 1e3,
              "ms");
    bench_add(table, "png_libpng_s", "libpng alone, same rows", alone * 1e3,
              "ms");
    bench_target(table, "P4 all threads (Gpixel/s)", pixels / many * 1e-9,
                 2.0, 0);
    bench_add(table, "p4_speedup", "16384x12288 P4, time 1 thread / all",
              one / many, "x");
    bench_target(table, "16384x12288 P4 speed-up, 1 to all threads",
                 one / many, 1.8, 0);
    if (all >= 2) {
        /* With n threads, helpers that start `late` seconds in leave the
         * caller T1 alone until then: at best n T1 / (T1 + (n - 1) late). */
        double late = bench_thread_start_seconds();
        bench_add(table, "thread_start_us",
                  "a new thread starts running after (median)", late * 1e6,
                  "us");
        bench_add(table, "p4_speedup_bound",
                  "16384x12288 P4, best speed-up, 1 to all, with that start",
                  late < 0 ? -1
                           : all * one / (one + (all - 1) * late),
                  "x");
        /* The machine's own scaling on the frame's bytes (band_fill.c). */
        int filled = fill_one > 0 && fill_many > 0; /* -1: no memory */
        bench_add(table, "fill_1thread_ms",
                  "the frame's bytes zeroed in bands, 1 thread",
                  filled ? fill_one * 1e3 : -1, "ms");
        bench_add(table, "fill_all_ms",
                  "the frame's bytes zeroed in bands, all threads",
                  filled ? fill_many * 1e3 : -1, "ms");
        bench_add(table, "fill_speedup",
                  "zeroing the frame's bytes, speed-up, 1 to all",
                  filled ? fill_one / fill_many : -1, "x");
    }
    bench_target(table, "PNG / libpng alone", png / alone, 1.2, 1);
}

static void peak_memory(bench_table *table, const char *rayo)
{
    static const char *const formats[2] = {"pbm", "png"};
    static const char *const keys[2] = {"rss_p4_kib", "rss_png_kib"};
    static const char *const labels[2] = {
        "16384x16384 P4, peak RSS of rayo", "16384x16384 PNG, peak RSS of rayo"};
    int f;
    for (f = 0; f < 2; f++) {
        char *argv[] = {(char *)rayo, "render", "-W", RSS_SIDE, "-H",
                        RSS_SIDE, "--format", (char *)formats[f], "--raw",
                        "-o", "/dev/null", NULL};
        long rss = -1;
        if (f == 1)
            argv[8] = NULL; /* no --raw for PNG */
        if (bench_run_child(argv, NULL, &rss) < 0)
            rss = -1;
        bench_add(table, keys[f], labels[f], (double)rss / 1024.0, "MiB");
        bench_target(table, labels[f], (double)rss / 1024.0, 64.0, 1);
    }
}

/* Processor time of this process (all its threads) so far, seconds. */
static double cpu_seconds(void)
{
    struct rusage usage;
    if (getrusage(RUSAGE_SELF, &usage) != 0)
        return 0;
    return (double)usage.ru_utime.tv_sec + (double)usage.ru_stime.tv_sec +
           ((double)usage.ru_utime.tv_usec + (double)usage.ru_stime.tv_usec) *
               1e-6;
}

/* A render's wall time, and in *cpu its processor time. */
static double timed_render(const large_setup *setup, unsigned threads,
                           double *cpu)
{
    double before = cpu_seconds();
    double wall = render_to_null(setup, RAYO_FORMAT_PBM, threads);
    *cpu = cpu_seconds() - before;
    return wall;
}

/*
 * Thread scaling where rendering is arithmetic: the per-pixel loop.
 * Processor time is reported too: on a shared virtual machine the wall
 * time also says how much of the second CPU the others left us.
 */
static void loop_scaling(bench_table *table)
{
    large_setup setup;
    unsigned all = rayo_cpu_count();
    double pixels = (double)LOOP_WIDTH * LOOP_HEIGHT, one = -1, many = -1;
    double cpu_one = -1, cpu_many = -1, cores = 0;
    int r;
    if (large_init(&setup, LOOP_WIDTH, LOOP_HEIGHT, 1) != 0) {
        bench_add(table, "loop_error", "per-pixel setup failed", -1, "");
        return;
    }
    for (r = 0; r < bench_repeats(table); r++) {
        double cpu, wall = timed_render(&setup, 1, &cpu);
        if (wall > 0 && (one < 0 || wall < one))
            one = wall;
        cpu_one = bench_best(cpu_one, cpu);
        wall = timed_render(&setup, all, &cpu);
        if (wall > 0 && (many < 0 || wall < many)) {
            many = wall;
            cores = cpu / wall;
        }
        cpu_many = bench_best(cpu_many, cpu);
    }
    rayo_scene_free(setup.scene);
    bench_add(table, "loop_cpu_ratio",
              "per-pixel loop, processor time all / 1 thread",
              cpu_many / cpu_one, "x");
    bench_add(table, "loop_cores", "per-pixel loop, CPUs busy, all threads",
              cores, "");
    bench_add(table, "loop_1thread_gpps",
              "4096x3072 P4, per-pixel loop, 1 thread", pixels / one * 1e-9,
              "Gpixel/s");
    bench_add(table, "loop_all_gpps",
              "4096x3072 P4, per-pixel loop, all threads",
              pixels / many * 1e-9, "Gpixel/s");
    bench_target(table, "per-pixel loop speed-up, 1 to all threads",
                 one / many, 1.8, 0);
}

void bench_large(bench_table *table, const char *rayo)
{
    large_setup setup;
    if (large_init(&setup, LARGE_WIDTH, LARGE_HEIGHT, 0) != 0) {
        bench_add(table, "large_error", "large frame setup failed", -1, "");
        return;
    }
    throughput(table, &setup);
    rayo_scene_free(setup.scene);
    loop_scaling(table);
    if (rayo != NULL)
        peak_memory(table, rayo);
}
