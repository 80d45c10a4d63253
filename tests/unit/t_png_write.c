/*
 * t_png_write.c - rayo's PNG writer, decoded by libpng itself.
 *
 * Renders the seed scene (and a few odd sizes) to a PNG file through
 * rayo_writer and reads it back with libpng's simplified API into 8-bit
 * gray, which must be 0 exactly where the rendered bit is 1 (a hit) and
 * 255 elsewhere.  Also checks the header: 1-bit grayscale.
 */
#define _POSIX_C_SOURCE 200809L

#include <png.h>
#include <stdlib.h>
#include <unistd.h>

#include "rayo.h"
#include "tap.h"

static int render_png(const char *path, const rayo_image *image)
{
    rayo_output *out;
    rayo_write_options options;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    options.format = RAYO_FORMAT_PNG;
    options.plain = 0;
    if (rayo_output_open(&out, path, &err) != RAYO_OK)
        return 0;
    if (rayo_image_write(image, out, &options, &err) != RAYO_OK) {
        rayo_output_abort(out);
        return 0;
    }
    return rayo_output_commit(out, &err) == RAYO_OK;
}

static void check_size(unsigned width, unsigned height)
{
    char path[] = "/tmp/rayo-t-png-XXXXXX";
    int fd = mkstemp(path);
    rayo_camera camera;
    rayo_scene *scene;
    rayo_render_options options;
    rayo_image image;
    png_image decoded;
    unsigned char *gray;
    long wrong = 0;
    unsigned i, j;

    close(fd);
    rayo_camera_init(&camera, width, height, 90, rayo_vec3_make(0, 0, 0),
                     NULL);
    rayo_scene_create(&scene, NULL);
    rayo_scene_add_sphere(scene, rayo_vec3_make(0.5, 0.75, 1.9), 0.8, NULL);
    rayo_render_options_init(&options);
    rayo_render_image(&camera, scene, &options, &image, NULL);
    ok(render_png(path, &image), "%ux%u: PNG written", width, height);

    memset(&decoded, 0, sizeof decoded);
    decoded.version = PNG_IMAGE_VERSION;
    ok(png_image_begin_read_from_file(&decoded, path) != 0,
       "%ux%u: libpng reads the header", width, height);
    is_int(decoded.width, width, "%ux%u: width", width, height);
    is_int(decoded.height, height, "%ux%u: height", width, height);
    ok((decoded.format & PNG_FORMAT_FLAG_COLOR) == 0,
       "%ux%u: grayscale", width, height);
    decoded.format = PNG_FORMAT_GRAY;
    gray = malloc(PNG_IMAGE_SIZE(decoded));
    ok(png_image_finish_read(&decoded, NULL, gray, 0, NULL) != 0,
       "%ux%u: libpng decodes the pixels", width, height);
    for (j = 0; j < height; j++)
        for (i = 0; i < width; i++) {
            int black = rayo_bit_get(rayo_image_row(&image, j), i);
            wrong += gray[(size_t)j * width + i] != (black ? 0 : 255);
        }
    is_int(wrong, 0, "%ux%u: every decoded pixel matches the render", width,
           height);
    free(gray);
    png_image_free(&decoded);
    rayo_image_free(&image);
    rayo_scene_free(scene);
    unlink(path);
}

/* The IHDR's bit depth and colour type, straight from the file's bytes. */
static void check_header(void)
{
    char path[] = "/tmp/rayo-t-png-XXXXXX";
    int fd = mkstemp(path);
    unsigned char bytes[26];
    rayo_image image;
    rayo_image_info info = rayo_image_info_bit(9, 2);
    FILE *file;
    close(fd);
    rayo_image_create(&image, &info, NULL);
    render_png(path, &image);
    file = fopen(path, "rb");
    ok(file != NULL && fread(bytes, 1, sizeof bytes, file) == sizeof bytes,
       "header bytes readable");
    if (file)
        fclose(file);
    is_int(bytes[24], 1, "IHDR bit depth 1");
    is_int(bytes[25], 0, "IHDR colour type 0 (grayscale)");
    rayo_image_free(&image);
    unlink(path);
}

int main(void)
{
    check_size(640, 480);
    check_size(641, 3);
    check_size(1, 1);
    check_size(13, 17);
    check_header();
    return tap_done();
}
