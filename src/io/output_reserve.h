/*
 * output_reserve.h - writing in place into a rayo_output's buffer, and
 * handing it bytes by reference, for the library's own formatters
 * (pnm_write.c): a row formatted straight into the buffer is not
 * formatted elsewhere and copied, and a template's bytes are not copied
 * at all.  Not a public header: the buffer's size and the bookkeeping
 * are output.c's business.
 */
#ifndef RAYO_OUTPUT_RESERVE_H
#define RAYO_OUTPUT_RESERVE_H

#include <stddef.h>

#include "rayo/output.h"

/*
 * Sets *room to at least size writable bytes inside out's buffer (written
 * out first if it lacks the room) and *available to how many there are,
 * valid until the next call on out; rayo_output_advance(out, n) then adds
 * the first n of them to the output.  *room is NULL and *available 0 when
 * size is larger than the buffer (write through rayo_output_write then)
 * and when an error is returned.
 */
rayo_status rayo_output_reserve(rayo_output *out, size_t size,
                                unsigned char **room, size_t *available,
                                rayo_error *err);

/* Adds n bytes written at the room to the output; n must not exceed the
 * room available (more is cut to it). */
void rayo_output_advance(rayo_output *out, size_t n);

/*
 * Adds size bytes at data to the output, after everything added before,
 * without copying them: they are written from data by the next write,
 * so they must stay as they are until the output writes them out, which
 * rayo_output_release makes happen at once (rayo_output_commit too), or
 * until rayo_output_abandon drops them.  The output also drops them when
 * a write fails and on rayo_output_abort.
 * Errors are those of rayo_output_write.
 */
rayo_status rayo_output_refer(rayo_output *out, const void *data,
                              size_t size, rayo_error *err);

/* Writes out whatever is pending when any of it is held by reference,
 * so that the memory referred to may change or go. */
rayo_status rayo_output_release(rayo_output *out, rayo_error *err);

/* For rayo_writer_discard: drops whatever is pending, unwritten (the
 * memory referred to may go), and marks out as holding an incomplete
 * image, so that its commit fails from then on. */
void rayo_output_abandon(rayo_output *out);

#endif
