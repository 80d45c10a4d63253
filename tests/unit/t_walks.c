/*
 * t_walks.c - the fast walks of the hierarchy change no byte of any
 * image.
 *
 * The bench's scenes (the field of 100,000 spheres from the level and
 * the above views, the cloud of 100,000, the field of 10, all lit as
 * bench/bvh.c lights them) and every scene file of examples/, small,
 * in hit and phong mode (and the file's own mode), are rendered with the
 * reference walk (src/accel/bvh.c's binary walk, one ray at a time, one
 * thread): the images of main before the fast walks.  Then again with
 * each fast path on its own (the wide walk in SSE2 lanes, in AVX2 lanes,
 * and AVX2 with packets of four rays: bvh_wide.h, bvh_packet.h), on one
 * thread and on two, and every byte must match.  A fast path this
 * processor lacks is skipped, and says so.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

#include "../../src/accel/bvh_packet.h"
#include "../../src/accel/bvh_wide.h"

typedef struct walk_setting {
    rayo_bvh_walk walk;
    int packets;
    const char *name;
} walk_setting;

static const walk_setting settings[] = {
    {RAYO_BVH_WALK_BINARY, 0, "binary"},
    {RAYO_BVH_WALK_SSE2, 0, "wide sse2"},
    {RAYO_BVH_WALK_AVX2, 0, "wide avx2"},
    {RAYO_BVH_WALK_AVX2, 1, "avx2 packets"},
};

static int render(const rayo_camera *camera, const rayo_scene *scene,
                  rayo_shade_mode shade, unsigned threads, rayo_image *image)
{
    rayo_render_options options;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_render_options_init(&options);
    options.shade = shade;
    options.threads = threads;
    if (rayo_render_image(camera, scene, &options, image, &err) != RAYO_OK) {
        printf("# render: %s\n", err.message);
        return 0;
    }
    return 1;
}

/* Byte-for-byte equality of two images of one layout; the count of rows
 * that differ. */
static long rows_differing(const rayo_image *a, const rayo_image *b)
{
    size_t bytes = rayo_image_info_row_bytes(&a->info);
    long bad = 0;
    uint32_t j;
    if (a->info.width != b->info.width || a->info.height != b->info.height)
        return -1;
    for (j = 0; j < a->info.height; j++)
        bad += memcmp(rayo_image_row(a, j), rayo_image_row(b, j), bytes) !=
               0;
    return bad;
}

/* Does the frame contain more than one colour?  (An image all background
 * proves nothing.) */
static int varied(const rayo_image *a)
{
    size_t bytes = rayo_image_info_row_bytes(&a->info), k;
    uint32_t j;
    for (j = 0; j < a->info.height; j++)
        for (k = 0; k < bytes; k++)
            if (rayo_image_row(a, j)[k] != rayo_image_row(a, 0)[0])
                return 1;
    return 0;
}

static void check_frame(const char *name, const rayo_camera *camera,
                        const rayo_scene *scene, rayo_shade_mode shade,
                        int must_vary)
{
    rayo_image want;
    size_t s;
    unsigned threads;
    rayo_bvh_walk_set(RAYO_BVH_WALK_BINARY);
    rayo_bvh_packets_set(0);
    if (!render(camera, scene, shade, 1, &want)) {
        ok(0, "%s: reference render", name);
        return;
    }
    if (must_vary)
        ok(varied(&want), "%s: the reference image is not uniform", name);
    else if (!varied(&want))
        printf("# %s: a uniform image\n", name);
    for (s = 0; s < sizeof settings / sizeof settings[0]; s++) {
        const walk_setting *w = &settings[s];
        if (!rayo_bvh_walk_available(w->walk)) {
            ok(1, "# skip %s, %s: not on this processor", name, w->name);
            continue;
        }
        rayo_bvh_walk_set(w->walk);
        rayo_bvh_packets_set(w->packets);
        for (threads = 1; threads <= 2; threads++) {
            rayo_image got;
            if (!render(camera, scene, shade, threads, &got)) {
                ok(0, "%s, %s, -j %u: render", name, w->name, threads);
                continue;
            }
            is_int(rows_differing(&want, &got), 0,
                   "%s, %s, -j %u: every byte as the reference walk's", name,
                   w->name, threads);
            rayo_image_free(&got);
        }
    }
    rayo_image_free(&want);
}

/* bench/bvh.c's scenes, lit as it lights them. */
static rayo_scene *bench_scene(int cloud, size_t count)
{
    rayo_scene *scene;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_light sun = {RAYO_LIGHT_DIRECTIONAL, {0.4, 1.0, -0.5},
                      {0.7, 0.7, 0.7}};
    rayo_light lamp = {RAYO_LIGHT_POINT, {-10.0, 20.0, 20.0},
                       {0.5, 0.5, 0.4}};
    rayo_status status;
    if (rayo_scene_create(&scene, &err) != RAYO_OK)
        return NULL;
    status = cloud ? rayo_scene_random_cloud(scene, count, 2026, &err)
                   : rayo_scene_random_spheres(scene, count, 2026, &err);
    if (status == RAYO_OK)
        status = rayo_scene_add_light(scene, &sun, &err);
    if (status == RAYO_OK)
        status = rayo_scene_add_light(scene, &lamp, &err);
    rayo_scene_set_ambient(scene, rayo_vec3_make(0.1, 0.1, 0.1));
    rayo_scene_set_background(scene, rayo_vec3_make(0.5, 0.7, 1.0));
    if (status == RAYO_OK)
        status = rayo_scene_prepare(scene, &err);
    if (status != RAYO_OK) {
        printf("# %s\n", err.message);
        rayo_scene_free(scene);
        return NULL;
    }
    return scene;
}

static void camera_level(rayo_camera *camera, uint32_t w, uint32_t h)
{
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_camera_init(camera, w, h, 90.0, rayo_vec3_make(0, 0, 0), &err);
}

static void camera_above(rayo_camera *camera, uint32_t w, uint32_t h)
{
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_camera_init(camera, w, h, 60.0, rayo_vec3_make(0, 5, -10), &err);
    rayo_camera_look_at(camera, rayo_vec3_make(0, -1, 35),
                        rayo_vec3_make(0, 1, 0), &err);
}

static void check_bench_scenes(void)
{
    rayo_scene *field = bench_scene(0, 100000), *few = bench_scene(0, 10);
    rayo_scene *cloud = bench_scene(1, 100000);
    rayo_camera level, above, small;
    camera_level(&level, 320, 180);
    camera_above(&above, 320, 180);
    camera_level(&small, 160, 90);
    if (field != NULL) {
        check_frame("field level, hit", &level, field, RAYO_SHADE_HIT, 1);
        check_frame("field level, phong", &level, field, RAYO_SHADE_PHONG, 1);
        check_frame("field above, hit", &above, field, RAYO_SHADE_HIT, 1);
        check_frame("field above, phong", &above, field, RAYO_SHADE_PHONG, 1);
    } else {
        ok(0, "the field of 100000 spheres");
    }
    if (cloud != NULL) {
        check_frame("cloud, hit", &small, cloud, RAYO_SHADE_HIT, 1);
        check_frame("cloud, phong", &small, cloud, RAYO_SHADE_PHONG, 1);
    } else {
        ok(0, "the cloud of 100000 spheres");
    }
    if (few != NULL) {
        check_frame("10 spheres, phong", &above, few, RAYO_SHADE_PHONG, 1);
    } else {
        ok(0, "the field of 10 spheres");
    }
    rayo_scene_free(field);
    rayo_scene_free(cloud);
    rayo_scene_free(few);
}

static void check_example(const char *file_name)
{
    const char *root = getenv("RAYO_SOURCE");
    char path[4096], name[128];
    rayo_scene_file file;
    rayo_camera camera;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    snprintf(path, sizeof path, "%s/examples/%s", root ? root : ".",
             file_name);
    if (rayo_scene_file_load(&file, path, &err) != RAYO_OK) {
        printf("# %s\n", err.message);
        ok(0, "%s: load", file_name);
        return;
    }
    file.camera.width /= 2;
    file.camera.height /= 2;
    if (rayo_camera_spec_build(&file.camera, &camera, &err) != RAYO_OK) {
        printf("# %s\n", err.message);
        ok(0, "%s: camera", file_name);
    } else {
        snprintf(name, sizeof name, "%s, its own mode", file_name);
        check_frame(name, &camera, file.scene, file.shade, 0);
        snprintf(name, sizeof name, "%s, hit", file_name);
        check_frame(name, &camera, file.scene, RAYO_SHADE_HIT, 0);
        if (file.shade != RAYO_SHADE_PHONG) {
            snprintf(name, sizeof name, "%s, phong", file_name);
            check_frame(name, &camera, file.scene, RAYO_SHADE_PHONG, 0);
        }
    }
    rayo_scene_file_free(&file);
}

int main(void)
{
    check_bench_scenes();
    check_example("ej1.scene");
    check_example("ej2.scene");
    check_example("ej3.scene");
    check_example("room.scene");
    check_example("showcase.scene");
    return tap_done();
}
