/*
 * writer_runs.h - rows as runs (image/row_runs.h), from the renderer to
 * the library's own writer.
 *
 * A caller's sink gets bits; but when the sink is rayo_writer_row_sink
 * and the writer is one that spells runs directly (plain PBM, which
 * copies each run from a row of black digits), render.c asks the span
 * renderer for runs and hands them over here, so the rows are neither
 * packed into bits nor scanned for their runs again.  The bytes written
 * are the same either way (tests/unit/t_render_runs.c compares the two).
 * Private to the library.
 */
#ifndef RAYO_WRITER_RUNS_H
#define RAYO_WRITER_RUNS_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/row_sink.h"
#include "rayo/writer.h"

#include "../image/row_runs.h"

/*
 * The writer behind (sink, context) when sink is rayo_writer_row_sink,
 * the writer takes runs, and the rows to come (layout `rows`) are
 * bilevel and exactly as wide as the writer's image, so that every run
 * fits its rows; else NULL.  (A caller may hand a writer wider rows than
 * its image; bits are then cut to the image, and runs would not be.)
 */
rayo_writer *rayo_writer_taking_runs(rayo_row_sink sink, void *context,
                                     const rayo_image_info *rows);

/* As rayo_writer_write_rows, each row r given by runs[r], or by its bits
 * where runs[r].count is RAYO_ROW_RUNS_BITS. */
rayo_status rayo_writer_write_runs(rayo_writer *writer,
                                   const unsigned char *rows, size_t stride,
                                   const rayo_row_runs *runs, uint32_t count,
                                   rayo_error *err);

#endif
