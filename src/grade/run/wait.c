/*
 * wait.c - waiting for one run by the grader's own clock: its process
 * group killed after the wall-clock limit, or when the caller cancels,
 * and whatever it left in its group killed when it ends; valgrind's log
 * read from its socket meanwhile (kept up to a bound, the rest counted
 * as an overflow), so that a full socket never stalls the run.
 *
 * A run that ends after the limit by that clock (the grader was stopped
 * or starved meanwhile) counts as timed out.  Without a cgroup to empty,
 * the sandbox's first process is waited out too.  Not where the run
 * starts (process.c, child.c) nor what its log means (valgrind_log.c).
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "spawn.h"

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

/* Reads what the log holds now (it is non-blocking). */
static void drain(log_reader *log)
{
    char buffer[65536];
    for (;;) {
        ssize_t got;
        if (log->fd < 0)
            return;
        got = read(log->fd, buffer, sizeof buffer);
        if (got < 0 && errno == EINTR)
            continue;
        if (got <= 0)
            return;
        if (log->size + (size_t)got > GRADE_LOG_KEPT) {
            log->overflow = 1;
            continue;
        }
        if (log->size + (size_t)got + 1 > log->capacity) {
            size_t capacity = (log->size + (size_t)got + 1) * 2;
            char *grown = realloc(log->data, capacity);
            if (grown == NULL) {
                log->failed = 1;
                continue;
            }
            log->data = grown;
            log->capacity = capacity;
        }
        memcpy(log->data + log->size, buffer, (size_t)got);
        log->size += (size_t)got;
    }
}

void grade_wait(pid_t pid, const grade_limits *limits, log_reader *log,
                grade_outcome *outcome)
{
    double start = now_seconds();
    int status = 0;
    int timed_out = 0, cancelled = 0;
    for (;;) {
        pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid || (done < 0 && errno != EINTR))
            break;
        if (limits->cancelled != NULL &&
            limits->cancelled(limits->cancel_context))
            cancelled = 1;
        if (cancelled || now_seconds() - start > limits->wall) {
            kill(-pid, SIGKILL);
            kill(pid, SIGKILL);
            while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
                ;
            timed_out = 1;
            break;
        }
        if (log->fd >= 0) {
            struct pollfd ready;
            ready.fd = log->fd;
            ready.events = POLLIN;
            ready.revents = 0;
            if (poll(&ready, 1, 2) > 0)
                drain(log);
        } else {
            struct timespec pause = {0, 2000000};
            nanosleep(&pause, NULL);
        }
    }
    /* Whatever it left behind in its group goes too. */
    kill(-pid, SIGKILL);
    drain(log);
    outcome->seconds = now_seconds() - start;
    /* The grader's clock holds: a run that ended past the limit (the
       grader was stopped, or starved) did not end within it. */
    if (!cancelled && !timed_out && outcome->seconds > limits->wall)
        timed_out = 1;
    if (cancelled) {
        outcome->ending = GRADE_CANCELLED;
        outcome->status = SIGKILL;
    } else if (timed_out) {
        outcome->ending = GRADE_TIMED_OUT;
        outcome->status = SIGKILL;
    } else if (WIFSIGNALED(status)) {
        outcome->ending = GRADE_SIGNALED;
        outcome->status = WTERMSIG(status);
    } else {
        outcome->ending = GRADE_EXITED;
        outcome->status = WEXITSTATUS(status);
    }
}

/* Polls for at most GONE_TRIES * 2 ms. */
#define GONE_TRIES 2500

void grade_wait_gone(pid_t pid)
{
    char path[64], text[512];
    int i;
    snprintf(path, sizeof path, "/proc/%ld/stat", (long)pid);
    for (i = 0; i < GONE_TRIES; i++) {
        struct timespec pause = {0, 2000000};
        int fd = open(path, O_RDONLY | O_CLOEXEC);
        ssize_t n;
        const char *state;
        if (fd < 0)
            return;
        n = read(fd, text, sizeof text - 1);
        close(fd);
        if (n <= 0)
            return;
        text[n] = '\0';
        /* "PID (NAME) S ...": the state after the name's last ')'. */
        state = strrchr(text, ')');
        if (state == NULL || state[1] != ' ' || state[2] == 'Z' ||
            state[2] == 'X')
            return;
        nanosleep(&pause, NULL);
    }
}
