/*
 * process.c - the benchmark's contact with the operating system: the
 * clock, pipes emptied by a reader thread (the far end of "rayo | cmd"),
 * and child processes, timed, or measured for peak memory.
 *
 * Peak memory cannot come from our own wait4: Linux folds the resident
 * size a process had before exec into its maximum, and a child forked
 * from this benchmark starts as a copy of it (tens of MiB by the time the
 * frames have been rendered).  So memory is measured by GNU time
 * (/usr/bin/time -f %M), whose children are copies of a small process.
 * Processor time has no such trap: wait4's resource usage counts the
 * child's own time and that of every descendant it waited for (the
 * command under `sh -c`), from the child's start.
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE

#include <fcntl.h>
#include <pthread.h>
#include <stdlib.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "bench.h"

double bench_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

struct bench_pipe {
    int read_fd;
    pthread_t reader;
};

static void *drain(void *argument)
{
    bench_pipe *p = argument;
    static char sink[1 << 16];
    while (read(p->read_fd, sink, sizeof sink) > 0)
        continue;
    return NULL;
}

int bench_pipe_open(bench_pipe **result, int *write_fd)
{
    int fds[2];
    bench_pipe *p = malloc(sizeof *p);
    if (p == NULL || pipe(fds) != 0) {
        free(p);
        return -1;
    }
    p->read_fd = fds[0];
    if (pthread_create(&p->reader, NULL, drain, p) != 0) {
        close(fds[0]);
        close(fds[1]);
        free(p);
        return -1;
    }
    *write_fd = fds[1];
    *result = p;
    return 0;
}

void bench_pipe_close(bench_pipe *p, int write_fd)
{
    if (write_fd >= 0)
        close(write_fd);
    pthread_join(p->reader, NULL);
    close(p->read_fd);
    free(p);
}

#define MAX_ARGS 64

/* The child's argv: the command (argv, or sh -c command), behind GNU
 * time writing %M to rss_file when rss_file is not NULL. */
static void build_argv(char *const argv[], const char *command,
                       const char *rss_file, char *out[MAX_ARGS])
{
    int n = 0, i;
    if (rss_file != NULL) {
        out[n++] = "/usr/bin/time";
        out[n++] = "-f";
        out[n++] = "%M";
        out[n++] = "-o";
        out[n++] = (char *)rss_file;
    }
    if (argv == NULL) {
        out[n++] = "/bin/sh";
        out[n++] = "-c";
        out[n++] = (char *)command;
    }
    for (i = 0; argv != NULL && argv[i] != NULL && n < MAX_ARGS - 1; i++)
        out[n++] = argv[i];
    out[n] = NULL;
}

double bench_read_number(const char *path)
{
    FILE *in = fopen(path, "r");
    double value = -1;
    if (in == NULL)
        return -1;
    if (fscanf(in, "%lf", &value) != 1)
        value = -1;
    fclose(in);
    return value;
}

double bench_run_child(char *const argv[], const char *command,
                       long *max_rss_kib)
{
    char rss_file[] = "/tmp/rayo-bench-rss.XXXXXX";
    char *child_argv[MAX_ARGS];
    int status, fd = -1;
    double start, seconds;
    pid_t pid;
    if (max_rss_kib != NULL) {
        fd = mkstemp(rss_file);
        if (fd < 0)
            return -1;
        close(fd);
    }
    build_argv(argv, command, max_rss_kib ? rss_file : NULL, child_argv);
    start = bench_now();
    pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        if (null >= 0)
            dup2(null, STDOUT_FILENO);
        execv(child_argv[0], child_argv);
        _exit(127);
    }
    if (waitpid(pid, &status, 0) != pid)
        return -1;
    seconds = bench_now() - start;
    if (max_rss_kib != NULL) {
        *max_rss_kib = (long)bench_read_number(rss_file);
        unlink(rss_file);
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return -1;
    return seconds;
}

static double timeval_seconds(struct timeval tv)
{
    return (double)tv.tv_sec + (double)tv.tv_usec * 1e-6;
}

double bench_run_measured(const char *command, char *capture,
                          size_t capture_size, double *cpu_seconds)
{
    int status, fds[2] = {-1, -1};
    size_t used = 0;
    double start, seconds;
    struct rusage usage;
    pid_t pid;
    if (capture != NULL && (capture_size == 0 || pipe(fds) != 0))
        return -1;
    start = bench_now();
    pid = fork();
    if (pid < 0) {
        if (fds[0] >= 0) {
            close(fds[0]);
            close(fds[1]);
        }
        return -1;
    }
    if (pid == 0) {
        int out = capture != NULL ? fds[1] : open("/dev/null", O_WRONLY);
        if (out >= 0)
            dup2(out, STDOUT_FILENO);
        if (capture != NULL)
            close(fds[0]);
        execl("/bin/sh", "sh", "-c", command, (char *)NULL);
        _exit(127);
    }
    if (capture != NULL) {
        char sink[4096]; /* what does not fit, read and dropped */
        close(fds[1]);
        for (;;) {
            int fits = used + 1 < capture_size;
            ssize_t got = read(fds[0], fits ? capture + used : sink,
                               fits ? capture_size - 1 - used : sizeof sink);
            if (got <= 0)
                break;
            if (fits)
                used += (size_t)got;
        }
        close(fds[0]);
        capture[used] = '\0';
    }
    memset(&usage, 0, sizeof usage);
    if (wait4(pid, &status, 0, &usage) != pid)
        return -1;
    seconds = bench_now() - start;
    if (cpu_seconds != NULL)
        *cpu_seconds = timeval_seconds(usage.ru_utime) +
                       timeval_seconds(usage.ru_stime);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return -1;
    return seconds;
}
