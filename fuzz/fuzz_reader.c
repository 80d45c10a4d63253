/*
 * fuzz_reader.c - fuzz target: the image readers by content.
 *
 * The input is handed whole to rayo_image_read_memory, which picks the
 * reader (Netpbm P1-P6 or PNG) from the first bytes.  A refusal must be
 * one line; an image that is accepted must respect limits.h, and is then
 * converted to each of the three layouts (image_convert.h), which
 * exercises the code that trusts a reader's output.  Not a conformance
 * test: tests/unit/t_reader.c checks what is read.
 */
#include <stdlib.h>

#include "fuzz.h"

static void convert_all(const rayo_image *image)
{
    rayo_image out;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status (*const to[3])(const rayo_image *, rayo_image *,
                               rayo_error *) = {
        rayo_image_to_bit, rayo_image_to_gray, rayo_image_to_rgb};
    size_t i;
    for (i = 0; i < 3; i++) {
        rayo_status status = to[i](image, &out, &err);
        if (status != RAYO_OK) {
            fuzz_check_refusal(status, &err);
            continue;
        }
        rayo_image_free(&out);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    rayo_image image;
    rayo_read_report report;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    rayo_error_clear(&err);
    status = rayo_image_read_memory(data, size, "fuzz", &image, &report, &err);
    if (status != RAYO_OK) {
        fuzz_check_refusal(status, &err);
        return 0;
    }
    if (image.info.width == 0 || image.info.height == 0 ||
        image.info.width > RAYO_MAX_DIMENSION ||
        image.info.height > RAYO_MAX_DIMENSION ||
        (uint64_t)image.info.width * image.info.height > RAYO_MAX_PIXELS ||
        report.trailing_bytes > size)
        abort();
    convert_all(&image);
    rayo_image_free(&image);
    return 0;
}
