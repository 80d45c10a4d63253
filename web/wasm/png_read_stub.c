/*
 * png_read_stub.c - the library's PNG reader for the page, where the
 * browser decodes PNG (createImageBitmap) instead of libpng.
 *
 * rayo_image_read_memory still recognises a PNG by its signature and
 * says so in its report (RAYO_FORMAT_PNG) before it calls this, which
 * declines: web_read (web_api.c) then tells the script to decode the
 * file and hand the pixels to web_from_png.
 */
#include "../../src/formats/reader_impl.h"

rayo_status rayo_png_read(rayo_source *src, rayo_image *image,
                          rayo_error *err)
{
    (void)image;
    return rayo_error_set(err, RAYO_ERR_FORMAT,
                          "%s: a PNG, which the browser decodes", src->name);
}
