/*
 * row_sink.h - where finished rows of an image go: the one interface the
 * renderer (render.h) produces into and the writers (writer.h), the
 * preview and the page's memory consume, declared below all of them so
 * that none has to include another's header for it.
 */
#ifndef RAYO_ROW_SINK_H
#define RAYO_ROW_SINK_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Receives count finished rows starting at first_row, stride bytes apart.
 * A status other than RAYO_OK stops the producer, which returns it.
 */
typedef rayo_status (*rayo_row_sink)(void *context,
                                     const unsigned char *rows,
                                     size_t stride, uint32_t first_row,
                                     uint32_t count, rayo_error *err);

#ifdef __cplusplus
}
#endif

#endif
