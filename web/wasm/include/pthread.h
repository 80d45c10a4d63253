/*
 * pthread.h - the few POSIX thread calls src/render/render.c makes, for
 * wasm32-wasi, which has no threads.
 *
 * The page renders on the browser's one thread: rayo_cpu_count answers 1
 * there (wasi-libc's sysconf), so rayo_render takes its serial path and
 * never starts a helper (and src/compare/tone_cache.c's lock, a static
 * one, guards nothing).  Should it try, pthread_create fails and the
 * renderer renders every band on the calling thread, as it does when a
 * system refuses a thread.  Locks and conditions have nothing to guard
 * against and do nothing.  Not a threads library: only what render.c
 * and tone_cache.c name, so the library's sources build unchanged.
 */
#ifndef RAYO_WEB_PTHREAD_H
#define RAYO_WEB_PTHREAD_H

#include <errno.h>
#include <stddef.h>

typedef int pthread_t;
typedef int pthread_attr_t;
typedef int pthread_mutex_t;
typedef int pthread_cond_t;
typedef int pthread_mutexattr_t;
typedef int pthread_condattr_t;
#define PTHREAD_MUTEX_INITIALIZER 0

static inline int pthread_create(pthread_t *thread,
                                 const pthread_attr_t *attr,
                                 void *(*body)(void *), void *argument)
{
    (void)thread, (void)attr, (void)body, (void)argument;
    return EAGAIN;
}
static inline int pthread_join(pthread_t thread, void **result)
{
    (void)thread, (void)result;
    return 0;
}
static inline int pthread_tryjoin_np(pthread_t thread, void **result)
{
    (void)thread, (void)result;
    return 0;
}
static inline pthread_t pthread_self(void) { return 0; }
static inline int pthread_attr_init(pthread_attr_t *attr)
{
    *attr = 0;
    return 0;
}
static inline int pthread_attr_destroy(pthread_attr_t *attr)
{
    (void)attr;
    return 0;
}
static inline int pthread_mutex_init(pthread_mutex_t *m,
                                     const pthread_mutexattr_t *a)
{
    (void)a;
    *m = 0;
    return 0;
}
static inline int pthread_mutex_destroy(pthread_mutex_t *m)
{
    (void)m;
    return 0;
}
static inline int pthread_mutex_lock(pthread_mutex_t *m)
{
    (void)m;
    return 0;
}
static inline int pthread_mutex_unlock(pthread_mutex_t *m)
{
    (void)m;
    return 0;
}
static inline int pthread_cond_init(pthread_cond_t *c,
                                    const pthread_condattr_t *a)
{
    (void)a;
    *c = 0;
    return 0;
}
static inline int pthread_cond_destroy(pthread_cond_t *c)
{
    (void)c;
    return 0;
}
static inline int pthread_cond_wait(pthread_cond_t *c, pthread_mutex_t *m)
{
    (void)c, (void)m;
    return 0;
}
static inline int pthread_cond_signal(pthread_cond_t *c)
{
    (void)c;
    return 0;
}
static inline int pthread_cond_broadcast(pthread_cond_t *c)
{
    (void)c;
    return 0;
}

#endif
