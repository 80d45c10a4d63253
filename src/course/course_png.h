/*
 * course_png.h - the course's reference images as the library holds them:
 * the bytes of data/course/referencia-catedra-ejN.png, which
 * scripts/embed.sh writes into a generated source at build time.
 *
 * Private to src/course/: course_reference.c is the one reader, and
 * rayo_course_reference_png (course.h) the public way to them.
 */
#ifndef RAYO_COURSE_PNG_H
#define RAYO_COURSE_PNG_H

#include <stddef.h>

extern const unsigned char course_png_ej1[];
extern const size_t course_png_ej1_size;
extern const unsigned char course_png_ej2[];
extern const size_t course_png_ej2_size;
extern const unsigned char course_png_ej3[];
extern const size_t course_png_ej3_size;

#endif
