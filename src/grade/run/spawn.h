/*
 * spawn.h - what the three parts of one run share: process.c sets the
 * run up and reads back what came of it, child.c is the child between
 * fork and exec (descriptors, limits, exec), wait.c waits for it under
 * the wall clock while reading the log.
 *
 * Private to src/grade/run/; the steps use grade_spawn (grade_impl.h).
 */
#ifndef RAYO_GRADE_SPAWN_H
#define RAYO_GRADE_SPAWN_H

#include <stddef.h>
#include <sys/types.h>

#include "../grade_impl.h"

/* The descriptors the child gets, by number. */
#define FD_JSON 4    /* bwrap's --json-status-fd */
#define FD_NAME 5    /* the collected file's name (the wrapper writes) */
#define FD_FILE 6    /* and its bytes */

typedef struct child_fds {
    int out, err;            /* captures */
    int log, log_number;     /* the log socket's write end, its number */
    int json, name, file;    /* sandbox only; -1 when unused */
    int in;                  /* standard input; -1: /dev/null */
} child_fds;

/* How the child is to run: its program, words, environment and folder,
   its limits, its cgroup (version 0: none), and the uid it becomes
   (0: the grader's own); every descriptor from 3 to max_fd is closed
   but those in fds. */
typedef struct child_plan {
    const char *program;
    char *const *argv;
    char *const *env;
    const char *dir;
    const child_fds *fds;
    const grade_limits *limits;
    const grade_cgroup *cg;
    unsigned long uid;
    long max_fd;
} child_plan;

/* In the child, between fork and exec (async-signal-safe calls only);
   never returns. */
void grade_child(const child_plan *plan);

/* The log's reader: what it holds, kept up to GRADE_LOG_KEPT bytes. */
#define GRADE_LOG_KEPT ((size_t)16 << 20)

typedef struct log_reader {
    int fd;
    char *data;
    size_t size, capacity;
    int overflow, failed;
} log_reader;

/* Waits for pid, killing its process group after limits->wall seconds
   or when limits->cancelled says so, reading the log meanwhile. */
void grade_wait(pid_t pid, const grade_limits *limits, log_reader *log,
                grade_outcome *outcome);
/* Waits (a few seconds at most) until process pid, not a child, has
   ended: gone, or a zombie. */
void grade_wait_gone(pid_t pid);

#endif
