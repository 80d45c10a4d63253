/*
 * cpu.h - how many CPUs this process may use: the count every threaded
 * part of rayo (the scene file's reader, the hierarchy's builder, the
 * renderer, compare) starts from when told "one thread per CPU".
 */
#ifndef RAYO_CPU_H
#define RAYO_CPU_H

#include "rayo/export.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The number of CPUs this process may use (its affinity mask, else the
 * online CPUs), at least 1 and at most RAYO_MAX_THREADS. */
RAYO_API unsigned rayo_cpu_count(void);

#ifdef __cplusplus
}
#endif

#endif
