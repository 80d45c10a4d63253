/*
 * t_reader_memory_options.c - rayo_image_read_memory_with reads from
 * memory as rayo_image_read_file_with reads a file: with clamp, a plain
 * PGM's samples out of range are taken into range and counted in the
 * report (how the page reads the image it checks); without options, or
 * with them zeroed, the same bytes are refused, as rayo_image_read_memory
 * refuses them.  The expected samples and counts are worked out here
 * from the text.
 */
#include <string.h>

#include "rayo.h"
#include "tap.h"

int main(void)
{
    static const char text[] = "P2\n4 2\n255\n260 -3 7 255\n"
                               "0 300 -12 1\n\n";
    rayo_read_options o;
    rayo_read_report rp;
    rayo_image image;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    memset(&o, 0, sizeof o);
    memset(&err, 0, sizeof err); /* no failure yet; English */
    is_int(rayo_image_read_memory(text, sizeof text - 1, "t.pgm", &image,
                                  NULL, &err),
           RAYO_ERR_FORMAT, "without options: 260 is refused");
    is_int(rayo_image_read_memory_with(text, sizeof text - 1, "t.pgm", NULL,
                                       &image, NULL, &err),
           RAYO_ERR_FORMAT, "options NULL: refused the same");
    ok(strncmp(err.message, "t.pgm: ", 7) == 0, "naming the file given");
    is_int(rayo_image_read_memory_with(text, sizeof text - 1, "t.pgm", &o,
                                       &image, NULL, &err),
           RAYO_ERR_FORMAT, "options zeroed: refused the same");
    ok(image.pixels == NULL, "and nothing is left allocated");
    o.clamp = 1;
    is_int(rayo_image_read_memory_with(text, sizeof text - 1, "t.pgm", &o,
                                       &image, &rp, &err),
           RAYO_OK, "with clamp: read");
    if (image.pixels != NULL) {
        const unsigned char *r0 = rayo_image_row(&image, 0);
        const unsigned char *r1 = rayo_image_row(&image, 1);
        is_int(r0[0] * 1000000 + r0[1] * 1000 + r0[2], 255000007,
               "260 -> 255, -3 -> 0, 7 kept");
        is_int(r1[1] * 1000 + r1[2], 255000, "300 -> 255, -12 -> 0");
    }
    is_int(rp.format, RAYO_FORMAT_PGM, "the report: a PGM");
    is_int(rp.clamped_high * 10 + rp.clamped_low, 22,
           "two above maxval, two negative");
    is_int(rp.first_high_line * 10 + rp.first_low_line, 44,
           "the first of each on line 4");
    is_int(rp.largest_found * 1000 + rp.smallest_found, 300000 - 12,
           "the largest found 300, the smallest -12");
    is_int(rp.trailing_bytes + rp.trailing_data, 0,
           "the blank line after the raster is no trailing byte");
    rayo_image_free(&image);
    return tap_done();
}
