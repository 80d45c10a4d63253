/*
 * t_output_memory.c - an output into memory (rayo_output_open_memory,
 * the page's seam) hands over, on commit, exactly the bytes written:
 * small and large writes, bytes formatted in place and bytes by
 * reference, and a whole image through rayo_writer (a raw PBM whose
 * bytes are spelled out here).  Nothing is handed over when nothing was
 * written (NULL, 0), when the output is aborted, or when an image on it
 * was abandoned (the commit then fails), and the caller's pointer keeps
 * what it held.  The expected bytes are generated here, from a formula,
 * not by the library.
 */
#include <stdlib.h>
#include <string.h>

#include "../../src/io/output_reserve.h"
#include "rayo.h"
#include "tap.h"

static unsigned char stream_byte(size_t i)
{
    return (unsigned char)((i * 2654435761u) >> 11);
}

/* Writes a stream of total bytes in pieces of every kind; 0 on success. */
static int write_stream(rayo_output *out, unsigned char *stream,
                        size_t total)
{
    static const size_t sizes[] = {1, 651, 65535, 65536, 65537, 3, 200000,
                                   7, 4096};
    size_t at = 0, k = 0;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    while (at < total) {
        size_t n = sizes[k % (sizeof sizes / sizeof sizes[0])];
        rayo_status s;
        if (n > total - at)
            n = total - at;
        if (k % 3 == 1) {
            s = rayo_output_refer(out, stream + at, n, &err);
        } else if (k % 3 == 2 && n < 4096) {
            unsigned char *room;
            size_t available;
            s = rayo_output_reserve(out, n, &room, &available, &err);
            if (s == RAYO_OK && room != NULL && available >= n) {
                memcpy(room, stream + at, n);
                rayo_output_advance(out, n);
            } else if (s == RAYO_OK) {
                s = rayo_output_write(out, stream + at, n, &err);
            }
        } else {
            s = rayo_output_write(out, stream + at, n, &err);
        }
        if (s != RAYO_OK)
            return -1;
        at += n;
        k++;
    }
    return 0;
}

int main(void)
{
    const size_t total = 3u << 20;
    unsigned char *stream = malloc(total), *data = NULL;
    unsigned char sentinel = 0;
    size_t size = 0, i, wrong = 0;
    rayo_output *out = NULL;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status s;
    if (stream == NULL)
        return 1;
    memset(&err, 0, sizeof err); /* no failure yet; English */
    for (i = 0; i < total; i++)
        stream[i] = stream_byte(i);

    s = rayo_output_open_memory(&out, "memory", &data, &size, &err);
    is_int(s, RAYO_OK, "an output into memory opens");
    is_string(rayo_output_name(out), "memory", "its name is the one given");
    ok(!rayo_output_is_terminal(out), "it is not a terminal");
    is_int(write_stream(out, stream, total), 0,
           "3 MiB in writes, references and reservations are taken");
    ok(data == NULL && size == 0, "nothing is handed over before commit");
    is_int(rayo_output_commit(out, &err), RAYO_OK, "the commit succeeds");
    is_int((long)size, (long)total, "every byte is handed over");
    for (i = 0; data != NULL && i < size && i < total; i++)
        wrong += data[i] != stream[i];
    ok(data != NULL && wrong == 0, "in order, each the byte written");
    free(data);

    data = &sentinel;
    size = 7;
    rayo_output_open_memory(&out, "empty", &data, &size, &err);
    is_int(rayo_output_commit(out, &err), RAYO_OK, "an empty output commits");
    ok(data == NULL && size == 0, "and hands over nothing (NULL, 0)");

    data = &sentinel;
    size = 7;
    rayo_output_open_memory(&out, "aborted", &data, &size, &err);
    rayo_output_write(out, "P1\n", 3, &err);
    rayo_output_abort(out);
    ok(data == &sentinel && size == 7, "an aborted output hands over nothing");

    {
        /* A 10x2 bilevel image, raw: "P4\n10 2\n", then two rows of two
           bytes each (1 = black, the first pixel the high bit). */
        static const unsigned char want[] = {'P', '4', '\n', '1', '0', ' ',
                                             '2', '\n', 0x80, 0x40, 0x01,
                                             0xC0};
        rayo_image image;
        rayo_write_options options = {RAYO_FORMAT_PBM, 0, 0};
        rayo_image_info info = rayo_image_info_bit(10, 2);
        rayo_writer *writer;
        data = NULL;
        size = 0;
        rayo_image_create(&image, &info, &err);
        memset(image.pixels, 0, image.stride * 2);
        image.pixels[0] = 0x80;
        image.pixels[1] = 0x40;
        image.pixels[image.stride] = 0x01;
        image.pixels[image.stride + 1] = 0xC0;
        rayo_output_open_memory(&out, "image.pbm", &data, &size, &err);
        is_int(rayo_image_write(&image, out, &options, &err), RAYO_OK,
               "a PBM is written into memory");
        is_int(rayo_output_commit(out, &err), RAYO_OK, "and committed");
        ok(size == sizeof want && data != NULL &&
               memcmp(data, want, sizeof want) == 0,
           "its bytes are the raw PBM's, header and rows");
        free(data);

        data = &sentinel;
        size = 7;
        rayo_output_open_memory(&out, "abandoned.pbm", &data, &size, &err);
        rayo_writer_open(&writer, out, &info, &options, &err);
        rayo_writer_write_rows(writer, image.pixels, image.stride, 1, &err);
        rayo_writer_discard(writer);
        s = rayo_output_commit(out, &err);
        is_int(s, RAYO_ERR_INVALID, "an abandoned image fails the commit");
        is_string(err.message,
                  "abandoned.pbm: incomplete: an image written to it was "
                  "abandoned",
                  "naming the output");
        ok(data == &sentinel && size == 7, "and hands over nothing");
        rayo_image_free(&image);
    }
    free(stream);
    return tap_done();
}
