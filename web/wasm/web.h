/*
 * web.h - what the page's WebAssembly glue declares: bytes the library
 * wrote into memory (rayo_output_open_memory), the image the page holds
 * and the functions web_api.c exports to the script.  Not part of the
 * library's interface.
 */
#ifndef RAYO_WEB_H
#define RAYO_WEB_H

#include <stddef.h>
#include <stdint.h>

#define WEB_EXPORT(name) __attribute__((export_name(name)))

typedef struct web_bytes {
    unsigned char *data; /* malloc'd; NULL when empty */
    size_t size;
} web_bytes;

/* What web_api.c exports to the script (docs/web.md): each function's
 * comment is at its definition. */
typedef struct web_image web_image;
void *web_alloc(size_t size);
void web_free(void *p);
const char *web_error(void);
void web_set_lang(int spanish);
int web_size_check(const char *name, uint32_t width, uint32_t height);
int web_error_is_png(void);
void web_image_free(web_image *im);
web_image *web_read(const unsigned char *data, size_t size, const char *name,
                    int clamp);
web_image *web_from_png(const unsigned char *png, size_t png_size,
                        const unsigned char *rgba, uint32_t w, uint32_t h);
unsigned web_info(const web_image *im, int field);
const unsigned char *web_rgba(web_image *im);
const char *web_compare(const web_image *reference, const web_image *image,
                        int reference_course, int spanish);
const char *web_compare_verdict(void);
const char *web_compare_diagnosis(void);
const unsigned char *web_compare_diff(void);
size_t web_compare_diff_size(void);
int web_course_count(void);
const char *web_course_name(int i);
int web_course_number(int i);
int web_course_of_kind(int bilevel, int channels);
unsigned web_scene_spheres(int scene_id, unsigned i, double *out);
web_image *web_render(int scene_id, const double *cam, const double *spheres,
                      size_t count);
int web_ray(const double *cam, const double *spheres, size_t count,
            double px, double py, double *out);

#endif
