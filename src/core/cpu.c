/*
 * cpu.c - the CPUs this process may run on (cpu.h): its affinity mask
 * (taskset, cpusets), else the online ones.  One system call: sysconf
 * reads a file under /sys, which cost the seed job a tenth of its time.
 */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */

#include "rayo/cpu.h"

#include <sched.h>
#include <unistd.h>

#include "rayo/limits.h"

unsigned rayo_cpu_count(void)
{
    long n;
#ifdef CPU_COUNT
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0)
        n = CPU_COUNT(&set);
    else
#endif
        n = sysconf(_SC_NPROCESSORS_ONLN);
    if (n < 1)
        return 1;
    return n > (long)RAYO_MAX_THREADS ? RAYO_MAX_THREADS : (unsigned)n;
}
