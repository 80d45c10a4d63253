/*
 * writer_impl.h - what a format must provide to stand behind rayo_writer.
 *
 * writer.c owns the public functions (argument checks, row counting);
 * pnm_write.c and png_write.c each fill in one of these tables.  Not a
 * public header.
 */
#ifndef RAYO_WRITER_IMPL_H
#define RAYO_WRITER_IMPL_H

#include "rayo/writer.h"

#include "../image/row_runs.h"

typedef struct rayo_writer_ops {
    /* Checks the layout, allocates state, writes the header. */
    rayo_status (*open)(rayo_writer *writer, rayo_error *err);
    rayo_status (*rows)(rayo_writer *writer, const unsigned char *rows,
                        size_t stride, uint32_t count, rayo_error *err);
    /* Rows as runs (writer_runs.h), for writers whose open set
     * takes_runs; NULL for formats that never do. */
    rayo_status (*runs)(rayo_writer *writer, const unsigned char *rows,
                        size_t stride, const rayo_row_runs *runs,
                        uint32_t count, rayo_error *err);
    rayo_status (*finish)(rayo_writer *writer, rayo_error *err);
    void (*discard)(rayo_writer *writer);
} rayo_writer_ops;

struct rayo_writer {
    const rayo_writer_ops *ops;
    rayo_output *out;
    rayo_image_info info;
    rayo_write_options options;
    uint32_t rows_written;
    int takes_runs; /* ops->runs applies to this image (set by open) */
    uint32_t rows_as_runs; /* rows that came as runs, not bits (a count
                              for tests/unit/t_render_runs.c) */
    uint32_t rows_referred; /* white rows of those, handed to the output
                               by reference (pnm_write.c; the same) */
    void *state;    /* the format's own */
};

extern const rayo_writer_ops rayo_pnm_writer_ops;
extern const rayo_writer_ops rayo_png_writer_ops;
extern const rayo_writer_ops rayo_bmp_writer_ops;
extern const rayo_writer_ops rayo_jpeg_writer_ops;

#endif
