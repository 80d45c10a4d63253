/*
 * t_build_without.c - what a build of rayo without files, libjpeg or
 * libpng's reader does (RAYO_NO_FILE_OUTPUT, RAYO_NO_JPEG,
 * RAYO_NO_PNG_READ: the page's configuration), checked on this machine:
 * the library's own files are compiled here with those switches, and
 * their definitions take the place of the full ones when linked with
 * librayo.a (an archive's member is pulled only for a symbol still
 * missing).  A JPEG and a PNG are recognised and refused by name, JPEG
 * is not written, and no output file is opened, but standard output
 * still is.  The expected messages are spelled out here.
 */
#define RAYO_NO_FILE_OUTPUT
#define RAYO_NO_JPEG
#define RAYO_NO_PNG_READ

#include "../../src/io/output_file.c"
#include "../../src/formats/jpeg_read.c"
#include "../../src/formats/jpeg_write.c"
#include "../../src/formats/png_read.c"

#include "rayo.h"
#include "tap.h"

int main(void)
{
    static const unsigned char jpeg[] = {0xff, 0xd8, 0xff, 0xe0, 0, 16};
    static const unsigned char png[] = {0x89, 'P', 'N', 'G', '\r', '\n',
                                        0x1a, '\n', 0, 0, 0, 13};
    rayo_write_options options = {RAYO_FORMAT_JPEG, 0, 90};
    rayo_image_info info = rayo_image_info_gray8(2, 2);
    rayo_read_report report;
    rayo_output *out = NULL;
    rayo_writer *writer = NULL;
    rayo_image image;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    unsigned char *data = NULL;
    size_t size = 0;
    memset(&err, 0, sizeof err); /* no failure yet; English */

    is_int(rayo_image_read_memory(jpeg, sizeof jpeg, "photo.jpg", &image,
                                  &report, &err),
           RAYO_ERR_FORMAT, "a JPEG is refused as malformed input");
    is_string(err.message,
              "photo.jpg: a JPEG, which this build of rayo does not read "
              "(it was built without libjpeg, RAYO_NO_JPEG); save the image "
              "as PNG, BMP or PBM/PGM/PPM",
              "saying why and what to do");
    is_int(report.format, RAYO_FORMAT_JPEG, "the report names it a JPEG");

    is_int(rayo_image_read_memory(png, sizeof png, "shot.png", &image,
                                  &report, &err),
           RAYO_ERR_FORMAT, "a PNG is refused as malformed input");
    is_string(err.message,
              "shot.png: a PNG, which this build of rayo does not read (it "
              "was built without libpng's reader, RAYO_NO_PNG_READ)",
              "saying why");
    is_int(report.format, RAYO_FORMAT_PNG, "the report names it a PNG");

    rayo_output_open_memory(&out, "x.jpg", &data, &size, &err);
    is_int(rayo_writer_open(&writer, out, &info, &options, &err),
           RAYO_ERR_INVALID, "writing JPEG is refused");
    is_string(err.message,
              "x.jpg: this build of rayo does not write JPEG (it was built "
              "without libjpeg, RAYO_NO_JPEG)",
              "naming the output");
    ok(writer == NULL, "and no writer is made");
    rayo_output_abort(out);

    out = (rayo_output *)&data;
    is_int(rayo_output_open(&out, "image.pbm", &err), RAYO_ERR_IO,
           "no output file is opened");
    is_string(err.message,
              "image.pbm: this build of rayo writes no files (it was built "
              "with RAYO_NO_FILE_OUTPUT)",
              "naming the file and why");
    ok(out == NULL, "and no output is made");
    is_int(rayo_output_open(&out, "-", &err), RAYO_OK,
           "standard output still opens");
    is_string(out != NULL ? rayo_output_name(out) : NULL, "standard output",
              "as standard output");
    rayo_output_abort(out);
    return tap_done();
}
