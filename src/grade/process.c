/*
 * process.c - running one program for the grader: in a given directory,
 * with no input, its output into files, under resource limits, with a
 * wall-clock timeout that kills its whole process group.
 *
 * Everything the child needs (paths, environment, the limits) is worked
 * out before fork(), so the child only calls async-signal-safe functions
 * (setpgid, prctl, open, dup2, chdir, setrlimit, execve, _exit) and is
 * safe to fork from a threaded program.  On Linux the child also dies
 * with the grader (PR_SET_PDEATHSIG).  The limits are resource limits, not a
 * sandbox: see grade.h.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include "grade_impl.h"

const char *grade_signal_name(int signal_number)
{
    switch (signal_number) {
    case SIGSEGV: return "segmentation fault (SIGSEGV)";
    case SIGBUS: return "bus error (SIGBUS)";
    case SIGFPE: return "arithmetic exception (SIGFPE)";
    case SIGILL: return "illegal instruction (SIGILL)";
    case SIGABRT: return "abort (SIGABRT), e.g. a failed assert or a "
                         "corrupted heap";
    case SIGKILL: return "killed (SIGKILL)";
    case SIGTERM: return "terminated (SIGTERM)";
    case SIGXCPU: return "CPU time limit exceeded (SIGXCPU)";
    case SIGXFSZ: return "file size limit exceeded (SIGXFSZ)";
    case SIGPIPE: return "broken pipe (SIGPIPE)";
    case SIGTRAP: return "trap (SIGTRAP)";
    }
    return "a signal";
}

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec / 1e9;
}

/* Resolves a command name on PATH in the parent (execvp is not
   async-signal-safe).  A name with a '/' is used as it is. */
static char *resolve(const char *name)
{
    const char *path = getenv("PATH");
    const char *p;
    if (strchr(name, '/') != NULL || path == NULL)
        return strdup(name);
    for (p = path;;) {
        const char *end = strchr(p, ':');
        size_t length = end != NULL ? (size_t)(end - p) : strlen(p);
        char *dir = strndup(length > 0 ? p : ".", length > 0 ? length : 1);
        char *candidate;
        if (dir == NULL)
            return NULL;
        candidate = grade_path_join(dir, name);
        free(dir);
        if (candidate == NULL)
            return NULL;
        if (access(candidate, X_OK) == 0)
            return candidate;
        free(candidate);
        if (end == NULL)
            return strdup(name);
        p = end + 1;
    }
}

char *grade_which(const char *name)
{
    char *path = resolve(name);
    if (path != NULL && (strchr(path, '/') == NULL || access(path, X_OK) != 0)) {
        free(path);
        return NULL;
    }
    return path;
}

static void set_limit(int resource, rlim_t soft, rlim_t hard)
{
    struct rlimit limit;
    limit.rlim_cur = soft;
    limit.rlim_max = hard;
    setrlimit(resource, &limit);
}

/* In the child, between fork and exec: async-signal-safe calls only. */
static void child(const char *program, char *const argv[],
                  char *const env[], const char *dir, const char *out,
                  const char *errpath, const grade_limits *limits,
                  long max_fd)
{
    int fd;
    long i;
    setpgid(0, 0);
#ifdef __linux__
    /* If the grader dies (killed, not cancelled), so does the program. */
    prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
    fd = open("/dev/null", O_RDONLY);
    if (fd < 0 || dup2(fd, 0) < 0)
        _exit(126);
    fd = open(out, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd < 0 || dup2(fd, 1) < 0)
        _exit(126);
    fd = open(errpath, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd < 0 || dup2(fd, 2) < 0)
        _exit(126);
    for (i = 3; i < max_fd; i++)
        close((int)i);
    if (chdir(dir) != 0)
        _exit(126);
    set_limit(RLIMIT_CORE, 0, 0);
    if (limits->cpu > 0) {
        rlim_t cpu = (rlim_t)limits->cpu;
        if ((double)cpu < limits->cpu)
            cpu++;
        set_limit(RLIMIT_CPU, cpu, cpu + 1);
    }
    if (limits->memory > 0)
        set_limit(RLIMIT_AS, (rlim_t)limits->memory,
                  (rlim_t)limits->memory);
    if (limits->file_size > 0)
        set_limit(RLIMIT_FSIZE, (rlim_t)limits->file_size,
                  (rlim_t)limits->file_size);
    if (limits->processes > 0)
        set_limit(RLIMIT_NPROC, (rlim_t)limits->processes,
                  (rlim_t)limits->processes);
    signal(SIGPIPE, SIG_DFL);
    signal(SIGXFSZ, SIG_DFL);
    execve(program, argv, env);
    _exit(127);
}

/* Waits for pid, killing its process group after limits->wall seconds
   or when limits->cancelled says so. */
static void wait_for(pid_t pid, const grade_limits *limits,
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
        {
            struct timespec pause = {0, 2000000};
            nanosleep(&pause, NULL);
        }
    }
    /* Whatever it left behind in its group goes too. */
    kill(-pid, SIGKILL);
    outcome->seconds = now_seconds() - start;
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

rayo_status grade_process_run(char *const argv[], char *const env[],
                              const char *dir, const char *stdout_path,
                              const char *stderr_path,
                              const grade_limits *limits, int search,
                              grade_outcome *outcome, rayo_error *err)
{
    char path_var[] = "PATH=/usr/local/bin:/usr/bin:/bin";
    char *home_var = grade_concat("HOME=", dir);
    char *tmp_var = grade_concat("TMPDIR=", dir);
    char *minimal[5];
    char *program = search ? resolve(argv[0]) : strdup(argv[0]);
    long max_fd = sysconf(_SC_OPEN_MAX);
    rayo_status status = RAYO_OK;
    pid_t pid;

    if (max_fd < 0 || max_fd > 65536)
        max_fd = 65536;
    minimal[0] = path_var;
    minimal[1] = home_var;
    minimal[2] = tmp_var;
    minimal[3] = "LANG=C";
    minimal[4] = NULL;
    if (home_var == NULL || tmp_var == NULL || program == NULL) {
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    } else {
        pid = fork();
        if (pid < 0) {
            status = rayo_error_set(err, RAYO_ERR_IO,
                                    "grade: cannot start %s: %s", argv[0],
                                    strerror(errno));
        } else if (pid == 0) {
            child(program, argv, env != NULL ? env : minimal, dir,
                  stdout_path, stderr_path, limits, max_fd);
        } else {
            setpgid(pid, pid);
            wait_for(pid, limits, outcome);
            if (outcome->ending == GRADE_CANCELLED)
                status = rayo_error_set(err, RAYO_ERR_CANCELLED,
                                        "grade: cancelled");
        }
    }
    free(home_var);
    free(tmp_var);
    free(program);
    return status;
}

char **grade_cc_argv(const grade_context *ctx, const char *const *words,
                     size_t count)
{
    char **argv;
    size_t i;
    if (count > ((size_t)-1) / sizeof *argv - ctx->cc_words - 1)
        return NULL;
    argv = malloc((ctx->cc_words + count + 1) * sizeof *argv);
    if (argv == NULL)
        return NULL;
    for (i = 0; i < ctx->cc_words; i++)
        argv[i] = ctx->cc[i];
    for (i = 0; i < count; i++)
        argv[ctx->cc_words + i] = (char *)words[i];
    argv[ctx->cc_words + count] = NULL;
    return argv;
}
