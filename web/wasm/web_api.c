/*
 * web_api.c - the functions the page's script calls in rayo's
 * WebAssembly build: read an image, compare two, render a scene, trace
 * one ray.  Everything here calls the library; nothing renders, compares
 * or parses Netpbm itself, so the page shows what `rayo` would.
 *
 * The script passes bytes in memory it got from web_alloc and reads
 * results back through pointers and lengths these functions return.
 * Failures leave one line, as the command would print it ("rayo: ..."),
 * for web_error.  Images the script holds are web_image pointers, freed
 * with web_image_free.  One thread, no files: reading is from memory,
 * writing into memory (rayo_output_open_memory), through the library's
 * public headers only, built without files, libjpeg or libpng's reader
 * (the Makefile's RAYO_NO_* switches; the browser decodes PNG).
 *
 * Sizes: size_t is 32 bits here, and the module's memory at most 4 GiB,
 * so every image the page takes in is first held to WEB_MAX_PIXELS
 * pixels (web_size_check), which keeps every size the library and this
 * file compute for it under 2^32 (the static assertion below).
 */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/camera_spec.h"
#include "rayo/compare.h"
#include "rayo/course/course.h"
#include "rayo/course/course_scene.h"
#include "rayo/lang.h"
#include "rayo/limits.h"
#include "rayo/output.h"
#include "rayo/reader.h"
#include "rayo/render.h"
#include "rayo/scene.h"
#include "rayo/seed.h"
#include "rayo/sphere.h"

#include "web.h"

struct web_image {
    rayo_image image;
    rayo_read_report read;
    unsigned char *rgba; /* for the canvas, made on demand */
};

static char last_error[RAYO_ERROR_MESSAGE_SIZE + 8];
static int last_was_png;
/* The language of web_error's lines: English until the page gives its
   own (web_set_lang), as the library has no language of its own. */
static rayo_lang page_lang = RAYO_LANG_EN;

/* The largest image the page takes (2^25 pixels, e.g. 8192x4096), and the
 * most bytes one pixel can hold in the module at once while two such
 * images are compared: two 16-bit colour images as read (12), compare's
 * own copies and maps (docs/limits.md: about 30 in all with the images),
 * each image's RGBA for the canvas (8), the difference PNG (3, stored
 * uncompressed) and the files' bytes while they are read (a plain PPM of
 * 16-bit samples: up to 18 a pixel each, 36): 96 with room.  Their
 * product must fit the module's 32-bit size_t and memory. */
#define WEB_MAX_PIXELS (UINT64_C(1) << 25)
#define WEB_PIXEL_BYTES 96
_Static_assert(WEB_MAX_PIXELS * WEB_PIXEL_BYTES <= SIZE_MAX,
               "the page's largest image fits the module's size_t");

static void keep_error(const rayo_error *err)
{
    snprintf(last_error, sizeof last_error, "rayo: %s", err->message);
}

/* web_error's line from one of the page's own messages, in its language. */
static void say_error(const char *format, ...)
    __attribute__((format(printf, 1, 2)));
static void say_error(const char *format, ...)
{
    va_list args;
    memcpy(last_error, "rayo: ", 7);
    va_start(args, format);
    rayo_lang_vformat(page_lang, last_error + 6, sizeof last_error - 6,
                      format, args);
    va_end(args);
}

/* The language of the lines web_error gives from now on, the page's:
   1 for Spanish, 0 for English (compare's report takes its own). */
WEB_EXPORT("web_set_lang") void web_set_lang(int spanish)
{
    page_lang = spanish ? RAYO_LANG_ES : RAYO_LANG_EN;
}

WEB_EXPORT("web_alloc") void *web_alloc(size_t size)
{
    return malloc(size ? size : 1);
}

WEB_EXPORT("web_free") void web_free(void *p) { free(p); }

/* The last failure's line, "rayo: FILE: byte N: found X; expected Y". */
WEB_EXPORT("web_error") const char *web_error(void) { return last_error; }

/* 1 when the last web_read found a PNG, for the browser to decode. */
WEB_EXPORT("web_error_is_png") int web_error_is_png(void)
{
    return last_was_png;
}

WEB_EXPORT("web_image_free") void web_image_free(web_image *im)
{
    if (im == NULL)
        return;
    rayo_image_free(&im->image);
    free(im->rgba);
    free(im);
}

/*
 * 0 when a width x height image fits the page, else -1 with web_error
 * saying so (name: the file).  The script calls it with a PNG's header
 * before the browser decodes it; the functions below before they build
 * or keep an image.
 */
WEB_EXPORT("web_size_check")
int web_size_check(const char *name, uint32_t width, uint32_t height)
{
    uint64_t pixels = (uint64_t)width * height;
    if (pixels <= WEB_MAX_PIXELS)
        return 0;
    say_error(rayo_gettext(page_lang,
                           "%s: the image is %lux%lu, %llu pixels; the page "
                           "takes at most %llu (e.g. 8192x4096): compare it "
                           "with the command, rayo compare"),
              name, (unsigned long)width, (unsigned long)height,
             (unsigned long long)pixels, (unsigned long long)WEB_MAX_PIXELS);
    return -1;
}

static web_image *new_image(void)
{
    web_image *im = calloc(1, sizeof *im);
    if (im == NULL)
        say_error("%s", rayo_gettext(page_lang, "out of memory"));
    return im;
}

/*
 * Reads a PBM, PGM or PPM file (plain or raw) held in memory, as the
 * library reads files: with clamp, plain samples out of range are
 * clamped and counted (how `rayo compare` reads the image it checks).
 * NULL on failure (web_error; web_error_is_png for a PNG).
 */
WEB_EXPORT("web_read")
web_image *web_read(const unsigned char *data, size_t size, const char *name,
                    int clamp)
{
    web_image *im = new_image();
    rayo_read_options options;
    rayo_error err = RAYO_ERROR_INIT(page_lang);
    rayo_status s;
    last_was_png = 0;
    if (im == NULL)
        return NULL;
    rayo_error_clear(&err);
    memset(&options, 0, sizeof options);
    options.clamp = clamp;
    s = rayo_image_read_memory_with(data, size, name, &options, &im->image,
                                    &im->read, &err);
    if (s != RAYO_OK) {
        last_was_png = im->read.format == RAYO_FORMAT_PNG && size >= 8 &&
                       data[0] == 0x89;
        keep_error(&err);
        /* This build reads no JPEG (RAYO_NO_JPEG): said in the page's
           words rather than the build's. */
        if (im->read.format == RAYO_FORMAT_JPEG)
            say_error(rayo_gettext(page_lang,
                                   "%s: a JPEG, which the page does not "
                                   "read; save the image as PNG or "
                                   "PBM/PGM/PPM"),
                      name);
        web_image_free(im);
        return NULL;
    }
    /* The reader computes in 64 bits and allocates with calloc, which
       refuses a product past size_t: a larger image is refused here,
       before anything else computes with its size. */
    if (web_size_check(name, im->image.info.width,
                       im->image.info.height) != 0) {
        web_image_free(im);
        return NULL;
    }
    return im;
}

/* The PNG's IHDR colour type and depth, and whether it has tRNS. */
static void png_header(const unsigned char *png, size_t size, int *color,
                       int *depth, int *trns)
{
    size_t at = 8;
    *color = 2;
    *depth = 8;
    *trns = 0;
    if (size >= 33 && memcmp(png + 12, "IHDR", 4) == 0) {
        *depth = png[24];
        *color = png[25];
    }
    while (at + 8 <= size) {
        size_t n = (size_t)png[at] << 24 | (size_t)png[at + 1] << 16 |
                   (size_t)png[at + 2] << 8 | png[at + 3];
        if (memcmp(png + at + 4, "tRNS", 4) == 0)
            *trns = 1;
        if (memcmp(png + at + 4, "IDAT", 4) == 0 || n > size - at - 8)
            break;
        at += 12 + n;
    }
}

/*
 * An image from a PNG the browser decoded to 8-bit RGBA (w x h), laid
 * out as the library's PNG reader lays that file out (reader.h): gray
 * types one channel (1-bit gray without tRNS bilevel), the others RGB,
 * alpha composited over white with the reader's formula.  png is the
 * file, for its header.  The browser gives 8 bits: a 16-bit PNG becomes
 * 8-bit, which compare takes it as anyway.
 */
WEB_EXPORT("web_from_png")
web_image *web_from_png(const unsigned char *png, size_t png_size,
                        const unsigned char *rgba, uint32_t w, uint32_t h)
{
    web_image *im = new_image();
    rayo_image_info info;
    rayo_error err = RAYO_ERROR_INIT(page_lang);
    int color, depth, trns;
    uint32_t x, y;
    if (web_size_check(rayo_gettext(page_lang, "the PNG"), w, h) != 0)
        return NULL;
    if (im == NULL)
        return NULL;
    png_header(png, png_size, &color, &depth, &trns);
    if ((color == 0 && depth == 1 && !trns))
        info = rayo_image_info_bit(w, h);
    else if (color == 0 || color == 4)
        info = rayo_image_info_gray8(w, h);
    else
        info = rayo_image_info_rgb8(w, h);
    rayo_error_clear(&err);
    if (rayo_image_info_check(&info, &err) != RAYO_OK ||
        rayo_image_create(&im->image, &info, &err) != RAYO_OK) {
        keep_error(&err);
        web_image_free(im);
        return NULL;
    }
    im->read.format = RAYO_FORMAT_PNG;
    for (y = 0; y < h; y++) {
        unsigned char *row = rayo_image_row(&im->image, y);
        for (x = 0; x < w; x++) {
            const unsigned char *p = rgba + ((size_t)y * w + x) * 4;
            unsigned a = p[3], c, v[3];
            for (c = 0; c < 3; c++)
                v[c] = (p[c] * a + 255u * (255u - a) + 127u) / 255u;
            if (info.sample == RAYO_SAMPLE_BIT)
                rayo_bit_set(row, x, v[0] < 128);
            else if (info.channels == 1)
                row[x] = (unsigned char)v[0];
            else
                for (c = 0; c < 3; c++)
                    row[3 * (size_t)x + c] = (unsigned char)v[c];
        }
    }
    return im;
}

/* 0 width, 1 height, 2 channels, 3 maxval, 4 sample (rayo_sample_type),
   5 format (rayo_format), 6 plain. */
WEB_EXPORT("web_info") unsigned web_info(const web_image *im, int field)
{
    const rayo_image_info *i = &im->image.info;
    switch (field) {
    case 0: return i->width;
    case 1: return i->height;
    case 2: return i->channels;
    case 3: return i->maxval;
    case 4: return (unsigned)i->sample;
    case 5: return (unsigned)im->read.format;
    case 6: return (unsigned)im->read.plain;
    default: return 0;
    }
}

/* The image as 8-bit RGBA for a canvas (width x height x 4 bytes, kept
   with the image). */
WEB_EXPORT("web_rgba") const unsigned char *web_rgba(web_image *im)
{
    const rayo_image_info *i = &im->image.info;
    uint32_t x, y;
    unsigned c;
    if (im->rgba != NULL)
        return im->rgba;
    /* every image here passed web_size_check: no overflow */
    if (web_size_check(rayo_gettext(page_lang, "the picture"), i->width, i->height) != 0)
        return NULL;
    im->rgba = malloc((size_t)i->width * i->height * 4 + 1);
    if (im->rgba == NULL) {
        say_error(rayo_gettext(page_lang, "out of memory for the "
                                          "picture's %lux%lu pixels"),
                  (unsigned long)i->width, (unsigned long)i->height);
        return NULL;
    }
    for (y = 0; y < i->height; y++) {
        const unsigned char *row = rayo_image_row(&im->image, y);
        unsigned char *out = im->rgba + (size_t)y * i->width * 4;
        for (x = 0; x < i->width; x++, out += 4) {
            for (c = 0; c < 3; c++) {
                unsigned long v, m = i->maxval;
                size_t k = (size_t)x * i->channels +
                           (i->channels == 3 ? c : 0);
                if (i->sample == RAYO_SAMPLE_BIT)
                    v = rayo_bit_get(row, x) ? 0 : 1;
                else if (i->sample == RAYO_SAMPLE_U8)
                    v = row[k];
                else {
                    uint16_t s;
                    memcpy(&s, row + 2 * k, 2);
                    v = s;
                }
                out[c] = (unsigned char)((v * 255u + m / 2) / m);
            }
            out[3] = 255;
        }
    }
    return im->rgba;
}

/* What the last web_compare found, and its difference picture. */
static char *compare_text, *compare_diagnosis;
static rayo_compare_report compare_report;
static web_bytes compare_diff;

static uint64_t surplus_pixels(const web_image *im)
{
    unsigned per = im->image.info.channels ? im->image.info.channels : 1;
    return (im->read.trailing_samples + per - 1) / per;
}

static char *format(size_t (*fn)(const rayo_compare_report *, char *,
                                 size_t))
{
    size_t need = fn(&compare_report, NULL, 0);
    char *text = malloc(need + 1);
    if (text != NULL)
        fn(&compare_report, text, need + 1);
    return text;
}

/*
 * `rayo compare REFERENCE IMAGE`: returns the text report (the command's
 * standard output, word for word), NULL on failure (web_error).
 * web_compare_verdict, web_compare_diagnosis and web_compare_diff then
 * say more.  The image should come from web_read with clamp 1.
 */
/* reference_course: the course's exercise (web_course_name) whose image the
   reference is, or -1 for a file of the student's; as the command, the
   report then notes pictures of different kinds.  spanish: 1 for the
   report in Spanish (`rayo compare --lang es`), 0 for English. */
WEB_EXPORT("web_compare")
const char *web_compare(const web_image *reference, const web_image *image,
                        int reference_course, int spanish)
{
    rayo_compare_options options;
    rayo_output *out = NULL;
    rayo_error err = RAYO_ERROR_INIT(page_lang);
    free(compare_text);
    free(compare_diagnosis);
    free(compare_diff.data);
    compare_text = compare_diagnosis = NULL;
    memset(&compare_diff, 0, sizeof compare_diff);
    rayo_error_clear(&err);
    if (web_size_check(rayo_gettext(page_lang, "the reference"),
                       reference->image.info.width,
                       reference->image.info.height) != 0 ||
        web_size_check(rayo_gettext(page_lang, "the image"),
                       image->image.info.width,
                       image->image.info.height) != 0)
        return NULL;
    rayo_compare_options_init(&options);
    options.lang = spanish ? RAYO_LANG_ES : RAYO_LANG_EN;
    if (rayo_compare_images(&reference->image, &image->image, &options,
                            &compare_report, &err) != RAYO_OK) {
        keep_error(&err);
        return NULL;
    }
    compare_report.reference_surplus = surplus_pixels(reference);
    compare_report.image_surplus = surplus_pixels(image);
    rayo_compare_note_clamped(&compare_report, &image->read);
    rayo_compare_note_kinds(&compare_report, &reference->image, &image->image,
                            reference_course >= 0 &&
                                    reference_course < RAYO_COURSE_EXERCISES
                                ? (rayo_course_exercise)reference_course
                                : RAYO_COURSE_EXERCISES);
    if (rayo_output_open_memory(&out, "diff.png", &compare_diff.data,
                                &compare_diff.size, &err) == RAYO_OK) {
        if (rayo_compare_write_diff(&reference->image, &image->image,
                                    &options, out, &err) == RAYO_OK)
            rayo_output_commit(out, &err);
        else
            rayo_output_abort(out);
    }
    compare_text = format(rayo_compare_format_text);
    if (compare_report.diagnosis != RAYO_DIAGNOSIS_NONE)
        compare_diagnosis = format(rayo_compare_format_diagnosis);
    return compare_text;
}

WEB_EXPORT("web_compare_verdict") const char *web_compare_verdict(void)
{
    return rayo_compare_verdict_name(compare_report.verdict);
}

/* The diagnosis sentence, "" when there is none. */
WEB_EXPORT("web_compare_diagnosis") const char *web_compare_diagnosis(void)
{
    return compare_diagnosis != NULL ? compare_diagnosis : "";
}

/* The difference picture, a PNG (rayo_compare_write_diff), and its size. */
WEB_EXPORT("web_compare_diff") const unsigned char *web_compare_diff(void)
{
    return compare_diff.data;
}

WEB_EXPORT("web_compare_diff_size") size_t web_compare_diff_size(void)
{
    return compare_diff.size;
}

/*
 * The course's registry for the page, which asks it and never spells an
 * exercise: how many there are, each one's name ("" past the last) and
 * number, and the exercise whose pictures are of an image's kind
 * (bilevel, else gray for one channel and colour for more), -1 none.
 */
WEB_EXPORT("web_course_count") int web_course_count(void)
{
    return RAYO_COURSE_EXERCISES;
}

WEB_EXPORT("web_course_name") const char *web_course_name(int i)
{
    const rayo_course_info *info =
        i < 0 ? NULL : rayo_course_info_of((rayo_course_exercise)i);
    return info != NULL ? info->name : "";
}

WEB_EXPORT("web_course_number") int web_course_number(int i)
{
    const rayo_course_info *info =
        i < 0 ? NULL : rayo_course_info_of((rayo_course_exercise)i);
    return info != NULL ? info->number : 0;
}

WEB_EXPORT("web_course_of_kind") int web_course_of_kind(int bilevel,
                                                        int channels)
{
    rayo_course_exercise e = rayo_course_of_kind(
        bilevel ? RAYO_COURSE_BILEVEL
                : channels == 1 ? RAYO_COURSE_GRAY : RAYO_COURSE_COLOUR);
    return e < RAYO_COURSE_EXERCISES ? (int)e : -1;
}

/* The course's exercise scene_id, NULL for the seed (-1). */
static const rayo_course_data *course_data(int scene_id)
{
    return scene_id < 0 ? NULL
                        : rayo_course_data_of((rayo_course_exercise)scene_id);
}

/*
 * A scene for web_render: `scene` is -1 for the seed (the
 * command's default: spheres without material, hit shading) or a
 * rayo_course_exercise (its materials, lights and shading); spheres
 * holds count x (cx, cy, cz, r), replacing the scene's own in order.
 */
static rayo_status build_scene(int scene_id, const double *spheres,
                               size_t count, rayo_scene **scene,
                               rayo_shade_mode *shade, rayo_error *err)
{
    const rayo_course_data *data = course_data(scene_id);
    rayo_status s;
    size_t i;
    *shade = RAYO_SHADE_HIT;
    if (scene_id >= 0 && data == NULL)
        return rayo_error_set(err, RAYO_ERR_INVALID, "no scene %d", scene_id);
    if (data != NULL) {
        /* the course's scene (one source: course_scenes.c), the balls'
           centres and radii taken from spheres */
        *shade = data->shade;
        return rayo_course_scene_build_moved(
            (rayo_course_exercise)scene_id, spheres, count, scene, err);
    }
    if ((s = rayo_scene_create(scene, err)) != RAYO_OK)
        return s;
    for (i = 0; s == RAYO_OK && i < count; i++)
        s = rayo_scene_add_sphere(*scene,
                                  rayo_vec3_make(spheres[4 * i],
                                                 spheres[4 * i + 1],
                                                 spheres[4 * i + 2]),
                                  spheres[4 * i + 3], err);
    return s;
}

/* How many spheres scene_id has, and the i-th's centre and radius into
   out[4] (the script's starting values). */
WEB_EXPORT("web_scene_spheres")
unsigned web_scene_spheres(int scene_id, unsigned i, double *out)
{
    const rayo_course_data *data = course_data(scene_id);
    if (data == NULL) {
        out[0] = RAYO_SEED_CENTER_X;
        out[1] = RAYO_SEED_CENTER_Y;
        out[2] = RAYO_SEED_CENTER_Z;
        out[3] = RAYO_SEED_RADIUS;
        return 1;
    }
    if (i < data->ball_count) {
        memcpy(out, data->balls[i].center, 3 * sizeof *out);
        out[3] = data->balls[i].radius;
    }
    return (unsigned)data->ball_count;
}

static rayo_status build_camera(const double *cam, rayo_camera *camera,
                                rayo_error *err)
{
    rayo_camera_spec spec;
    rayo_camera_spec_init(&spec);
    if (!(cam[0] >= 1 && cam[0] <= 65535 && cam[1] >= 1 && cam[1] <= 65535))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "width and height: expected 1 to %u",
                              RAYO_MAX_DIMENSION);
    spec.width = (uint32_t)cam[0];
    spec.height = (uint32_t)cam[1];
    spec.fov_degrees = cam[2];
    spec.origin = rayo_vec3_make(cam[3], cam[4], cam[5]);
    return rayo_camera_spec_build(&spec, camera, err);
}

/*
 * `rayo render` of a scene: cam holds width, height, field of view
 * (degrees) and the origin's x, y, z.  The seed with its own values is
 * the command's default image, pixel for pixel.
 */
WEB_EXPORT("web_render")
web_image *web_render(int scene_id, const double *cam, const double *spheres,
                      size_t count)
{
    web_image *im = new_image();
    rayo_camera camera;
    rayo_scene *scene = NULL;
    rayo_render_options options;
    rayo_error err = RAYO_ERROR_INIT(page_lang);
    rayo_status s;
    if (im == NULL)
        return NULL;
    rayo_error_clear(&err);
    rayo_render_options_init(&options);
    options.threads = 1;
    s = build_camera(cam, &camera, &err);
    if (s == RAYO_OK && web_size_check(rayo_gettext(page_lang, "the render"), camera.width,
                                       camera.height) != 0) {
        web_image_free(im);
        return NULL;
    }
    if (s == RAYO_OK)
        s = build_scene(scene_id, spheres, count, &scene, &options.shade,
                        &err);
    if (s == RAYO_OK)
        s = rayo_render_image(&camera, scene, &options, &im->image, &err);
    rayo_scene_free(scene);
    if (s != RAYO_OK) {
        keep_error(&err);
        web_image_free(im);
        return NULL;
    }
    im->read.format = rayo_format_netpbm_for(&im->image.info);
    return im;
}

/*
 * The assignment's arithmetic for the ray through pixel (px, py), for the
 * sphere it explains: the one with the nearest hit, or the first sphere
 * when the ray hits none.  Into out: d (x, y, z, unit), beta = L.d and
 * delta = beta^2 - L.L + R^2 of that sphere (L = C - O, sphere.h),
 * whether the ray hits any sphere of the scene, t of the nearest hit (or
 * -1), the camera's focal distance in pixels, and the index of the sphere
 * explained.  The page so never shows one sphere's delta beside another's
 * hit.  Returns 0, or -1 when the camera is invalid.
 */
WEB_EXPORT("web_ray")
int web_ray(const double *cam, const double *spheres, size_t count,
            double px, double py, double *out)
{
    rayo_camera camera;
    rayo_error err = RAYO_ERROR_INIT(page_lang);
    rayo_ray ray;
    rayo_vec3 l;
    double nearest = INFINITY;
    size_t i, which = 0;
    if (build_camera(cam, &camera, &err) != RAYO_OK || count == 0) {
        keep_error(&err);
        return -1;
    }
    ray = rayo_camera_ray(&camera, px, py);
    for (i = 0; i < count; i++) {
        rayo_sphere sphere;
        double t;
        sphere.center = rayo_vec3_make(spheres[4 * i], spheres[4 * i + 1],
                                       spheres[4 * i + 2]);
        sphere.radius = spheres[4 * i + 3];
        t = rayo_sphere_intersect(&sphere, &ray, 0.0);
        if (t < nearest) {
            nearest = t;
            which = i;
        }
    }
    l = rayo_vec3_sub(rayo_vec3_make(spheres[4 * which],
                                     spheres[4 * which + 1],
                                     spheres[4 * which + 2]),
                      ray.origin);
    out[0] = ray.direction.x;
    out[1] = ray.direction.y;
    out[2] = ray.direction.z;
    out[3] = rayo_vec3_dot(l, ray.direction);
    out[4] = out[3] * out[3] - rayo_vec3_dot(l, l) +
             spheres[4 * which + 3] * spheres[4 * which + 3];
    out[5] = nearest < INFINITY;
    out[6] = nearest < INFINITY ? nearest : -1;
    out[7] = camera.focal;
    out[8] = (double)which;
    return 0;
}
