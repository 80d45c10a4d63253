/*
 * t_course_reference.c - the course's reference images built into the
 * library (rayo_course_reference_png) are byte for byte the files in
 * data/course/, and read as the images the course published: 640x480,
 * all three saved as 8-bit RGB (even EJ1's black and white sphere).
 *
 * The files are found through $RAYO_SOURCE (make check sets it; "." when
 * run by hand from the repository).  Not a test of where the command
 * looks for them: tests/cli/course_builtin.t does that.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

/* The whole file into a new buffer (*size bytes); NULL on failure. */
static unsigned char *slurp(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    unsigned char *data = NULL;
    long n;
    if (f == NULL)
        return NULL;
    if (fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) > 0 &&
        fseek(f, 0, SEEK_SET) == 0 && (data = malloc((size_t)n)) != NULL &&
        fread(data, 1, (size_t)n, f) != (size_t)n) {
        free(data);
        data = NULL;
    }
    if (data != NULL)
        *size = (size_t)n;
    fclose(f);
    return data;
}

static void check(rayo_course_exercise e)
{
    const char *root = getenv("RAYO_SOURCE");
    const char *name = rayo_course_name(e);
    char path[4096];
    size_t size = 0, file_size = 0;
    const unsigned char *data = rayo_course_reference_png(e, &size);
    unsigned char *file;
    rayo_image image;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    snprintf(path, sizeof path, "%s/data/course/referencia-catedra-%s.png",
             root ? root : ".", name);
    file = slurp(path, &file_size);
    ok(file != NULL, "%s: data/course/ has its file", name);
    ok(data != NULL, "%s: the library holds its reference", name);
    is_int(size, file_size, "%s: as many bytes as the file", name);
    ok(data != NULL && file != NULL && size == file_size &&
           memcmp(data, file, size) == 0,
       "%s: the same bytes as the file", name);
    free(file);
    memset(&image, 0, sizeof image);
    ok(data != NULL && rayo_image_read_memory(data, size, name, &image, NULL,
                                              &err) == RAYO_OK,
       "%s: the bytes read as an image", name);
    is_int(image.info.width, 640, "%s: 640 wide", name);
    is_int(image.info.height, 480, "%s: 480 high", name);
    is_int(image.info.sample, RAYO_SAMPLE_U8, "%s: 8-bit samples", name);
    is_int(image.info.channels, 3, "%s: RGB", name);
    rayo_image_free(&image);
}

int main(void)
{
    size_t size = 12345;
    check(RAYO_COURSE_EJ1);
    check(RAYO_COURSE_EJ2);
    check(RAYO_COURSE_EJ3);
    ok(rayo_course_reference_png(RAYO_COURSE_EXERCISES, &size) == NULL,
       "no reference past the last exercise");
    is_int(size, 0, "and its size is 0");
    ok(rayo_course_reference_png(RAYO_COURSE_EJ1, NULL) != NULL,
       "size may be NULL");
    return tap_done();
}
