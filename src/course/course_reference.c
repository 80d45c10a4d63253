/*
 * course_reference.c - the course's own reference images, built in: the
 * PNG bytes the course published for each exercise, so that a command
 * copied or installed without its data files still knows course:ej1.
 *
 * The bytes come from data/course/ at build time (course_png.h).  Where a
 * caller looks for a file of the same name first, and in what order, is
 * the caller's business: the library only hands out the bytes, to be
 * read with rayo_image_read_memory.  Not the exercise's render either:
 * rayo_course_render draws rayo's image, this is the course's file.
 */
#include "rayo/course.h"

#include "course_png.h"

const unsigned char *rayo_course_reference_png(rayo_course_exercise exercise,
                                               size_t *size)
{
    const unsigned char *data = NULL;
    size_t n = 0;
    switch (exercise) {
    case RAYO_COURSE_EJ1:
        data = course_png_ej1;
        n = course_png_ej1_size;
        break;
    case RAYO_COURSE_EJ2:
        data = course_png_ej2;
        n = course_png_ej2_size;
        break;
    case RAYO_COURSE_EJ3:
        data = course_png_ej3;
        n = course_png_ej3_size;
        break;
    case RAYO_COURSE_EXERCISES:
        break;
    }
    if (size != NULL)
        *size = n;
    return data;
}
