/*
 * process.c - the benchmark's contact with the operating system: the
 * clock, pipes emptied by a reader thread (the far end of "rayo | cmd"),
 * and child processes timed and measured for peak memory with wait4.
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE

#include <fcntl.h>
#include <pthread.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/time.h>
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

double bench_run_child(char *const argv[], const char *command,
                       long *max_rss_kib)
{
    struct rusage usage;
    int status;
    double start = bench_now(), seconds;
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        if (null >= 0)
            dup2(null, STDOUT_FILENO);
        if (argv != NULL)
            execv(argv[0], argv);
        else
            execl("/bin/sh", "sh", "-c", command, (char *)NULL);
        _exit(127);
    }
    if (wait4(pid, &status, 0, &usage) != pid)
        return -1;
    seconds = bench_now() - start;
    *max_rss_kib = usage.ru_maxrss;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return -1;
    return seconds;
}
