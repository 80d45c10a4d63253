/*
 * writer_runs.h - rows as runs (image/row_runs.h), from the renderer to
 * the library's own writer.
 *
 * A caller's sink gets bits; but when the sink is rayo_writer_row_sink
 * and the writer is one that spells runs directly (plain PBM, which
 * copies each run from a row of black digits), render.c asks the span
 * renderer for runs and hands them over here, so the rows are neither
 * packed into bits nor scanned for their runs again.  The bytes written
 * are the same either way (tests/unit/t_render.c compares the two).
 * Private to the library.
 */
#ifndef RAYO_WRITER_RUNS_H
#define RAYO_WRITER_RUNS_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/render.h"
#include "rayo/writer.h"

#include "../image/row_runs.h"

/* The writer behind (sink, context) when sink is rayo_writer_row_sink and
 * the writer takes runs; else NULL. */
rayo_writer *rayo_writer_taking_runs(rayo_row_sink sink, void *context);

/* As rayo_writer_write_rows, each row r given by runs[r], or by its bits
 * where runs[r].count is RAYO_ROW_RUNS_BITS. */
rayo_status rayo_writer_write_runs(rayo_writer *writer,
                                   const unsigned char *rows, size_t stride,
                                   const rayo_row_runs *runs, uint32_t count,
                                   rayo_error *err);

#endif
