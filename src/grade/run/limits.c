/*
 * limits.c - which limits hold on a run here, and the sentence that
 * says so on the report's first line.
 *
 * With a cgroup (cgroup.c) the tree's memory and processes are the
 * kernel's to count.  Without one, the tree is bounded by a product:
 * each process's address space (RLIMIT_AS) times the processes the
 * tree may have (RLIMIT_NPROC, set inside the sandbox, where the kernel
 * counts the processes of the sandbox's own user namespace; as root,
 * under a uid of its own, uid.c, since root's are not counted).  The
 * sandbox's processes are then at most GRADE_PROCESSES_ALONE, so that
 * the product stays a few times the memory asked for; outside the
 * sandbox RLIMIT_NPROC counts all the user's processes.  Not where the
 * limits are set (child.c) nor chosen per step (run.c).
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "../grade_impl.h"

/* The processes of a run's tree without a cgroup: the compiler takes
   four at once (the sandbox's first process, the driver, collect2 and
   the linker), a course's program one. */
#define GRADE_PROCESSES_ALONE 8UL

/* 1 when RLIMIT_NPROC can be set inside the sandbox (sandbox.c runs
   the command through prlimit), where it counts the sandbox alone. */
static int counted_inside(int sandboxed)
{
    char *prlimit = sandboxed ? grade_which("prlimit") : NULL;
    free(prlimit);
    return prlimit != NULL;
}

/* The processes a tree may have without a cgroup. */
static unsigned long processes_alone(unsigned long processes)
{
    return processes == 0 || processes > GRADE_PROCESSES_ALONE
               ? GRADE_PROCESSES_ALONE
               : processes;
}

grade_limits grade_limits_here(const grade_limits *limits, int sandboxed)
{
    grade_limits here = *limits;
    if (grade_cgroup_kind(NULL, 0) > 0)
        return here;
    /* Outside the sandbox the user's own processes count too: fewer
       than theirs would stop the run from starting at all. */
    if (counted_inside(sandboxed))
        here.processes = processes_alone(limits->processes);
    /* valgrind, which has no address-space limit of its own where the
       cgroup bounds it, gets the tree's. */
    if (here.memory == 0)
        here.memory = limits->tree_memory;
    return here;
}

/* Whole MiB, as the options take them. */
static unsigned long long mib(uint64_t bytes)
{
    return (unsigned long long)(bytes >> 20);
}

void grade_limits_describe(const rayo_grade_options *o, char *text,
                           size_t room)
{
    char cpu[32];
    int version = grade_cgroup_kind(NULL, 0);
    int sandboxed = counted_inside(o->sandbox != RAYO_GRADE_SANDBOX_OFF &&
                                   grade_sandbox_available(NULL, 0));
    unsigned long processes = sandboxed ? processes_alone(o->processes)
                                        : o->processes;
    unsigned long long total = mib(o->memory) * processes;
    if (o->cpu > 0)
        snprintf(cpu, sizeof cpu, "%g s CPU", o->cpu);
    else
        snprintf(cpu, sizeof cpu, "no CPU limit");
    if (version > 0)
        snprintf(text, room, "limits: cgroup v%d on the whole tree (%llu MiB "
                             "memory, %lu processes); per process %s, "
                             "%llu MiB files, %d descriptors",
                 version, mib(o->memory), o->processes, cpu,
                 mib(o->output_limit), GRADE_OPEN_FILES);
    else if (sandboxed || geteuid() != 0)
        /* One sentence each, with the same numbers in the same order. */
        snprintf(text, room,
                 !sandboxed ? "limits: per process only, no cgroup here "
                              "(%llu MiB address space each, %lu processes "
                              "of the user: at most %llu MiB in all; %s, "
                              "%llu MiB files, %d descriptors)"
                 : geteuid() == 0
                     ? "limits: per process only, no cgroup here; the "
                       "sandbox runs as a uid of its own (%llu MiB address "
                       "space each, %lu processes in the sandbox: at most "
                       "%llu MiB in all; %s, %llu MiB files, %d descriptors)"
                     : "limits: per process only, no cgroup here (%llu MiB "
                       "address space each, %lu processes in the sandbox: "
                       "at most %llu MiB in all; %s, %llu MiB files, %d "
                       "descriptors)",
                 mib(o->memory), processes, total, cpu,
                 mib(o->output_limit), GRADE_OPEN_FILES);
    else
        /* RLIMIT_NPROC does not bind for root: nothing bounds the
           total outside the sandbox. */
        snprintf(text, room, "limits: per process only, no cgroup here "
                             "(%llu MiB address space each, no bound on "
                             "the processes of root nor on their total; "
                             "%s, %llu MiB files, %d descriptors)",
                 mib(o->memory), cpu, mib(o->output_limit),
                 GRADE_OPEN_FILES);
}
