/*
 * render_stop.h - a render's stop, seen by every rendering thread within
 * one ray's time: the flag the rows poll, inside a band, so that a band
 * of slow pixels (thousands of lights, deep mirrors, 16 x 16 samples) is
 * abandoned mid-way instead of finished first.  Private to the library.
 *
 * The flag is set once and never cleared: by the caller's cancel
 * callback (rayo_render_options.cancel) when a poll finds it asking, and
 * by the scheduler (render.c) when the render ends early for any other
 * reason (the sink failed, the progress callback asked), so helpers stop
 * at once instead of finishing bands nobody will take.  A poll is one
 * relaxed atomic load and, while the flag is clear and there is a
 * callback, one call: nothing next to the ray it precedes.
 */
#ifndef RAYO_RENDER_STOP_H
#define RAYO_RENDER_STOP_H

#include <stdatomic.h>

#include "rayo/render.h"

typedef struct rayo_render_stop {
    atomic_int stopped;
    rayo_cancel_fn cancel; /* may be NULL */
    void *context;
} rayo_render_stop;

static inline void rayo_render_stop_init(rayo_render_stop *stop,
                                         const rayo_render_options *options)
{
    atomic_init(&stop->stopped, 0);
    stop->cancel = options->cancel;
    stop->context = options->cancel_context;
}

/* Sets the flag: every poll from now on answers 1. */
static inline void rayo_render_stop_now(rayo_render_stop *stop)
{
    atomic_store_explicit(&stop->stopped, 1, memory_order_relaxed);
}

/* 1 when the render is to stop: the flag, or the callback asking (which
 * then sets the flag for the other threads).  stop may be NULL (a row
 * rendered on its own, rayo_render_row): never. */
static inline int rayo_render_stopping(rayo_render_stop *stop)
{
    if (stop == NULL)
        return 0;
    if (atomic_load_explicit(&stop->stopped, memory_order_relaxed))
        return 1;
    if (stop->cancel != NULL && stop->cancel(stop->context)) {
        rayo_render_stop_now(stop);
        return 1;
    }
    return 0;
}

#endif
