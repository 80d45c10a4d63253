/*
 * output_reserve.h - writing in place into a rayo_output's buffer, for
 * the library's own formatters (pnm_write.c): a row formatted straight
 * into the buffer is not formatted elsewhere and copied.  Not a public
 * header: the buffer's size and the bookkeeping are output.c's business.
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

#endif
