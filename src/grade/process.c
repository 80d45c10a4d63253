/*
 * process.c - running one program for the grader: the compiler, the
 * functions' harness, the student's program or valgrind, with no input,
 * its output into unlinked files the grader holds, under resource limits,
 * with a wall-clock timeout by the grader's clock that kills its whole
 * process group, inside the sandbox when there is one (sandbox.c builds
 * bwrap's words; this file runs them: one mechanism for every run).
 *
 * Everything the child needs (paths, environment, descriptors, limits)
 * is worked out before fork(), so the child only calls async-signal-safe
 * functions (setsid, prctl, open, dup2, fcntl, chdir, setrlimit,
 * getrlimit, execve, _exit) and is safe to fork from a threaded
 * program.  On Linux the child also dies with the grader
 * (PR_SET_PDEATHSIG), and bwrap's
 * --die-with-parent takes the whole sandbox with it.  The limits are set
 * on bwrap and so hold inside; before them the child joins the run's
 * cgroup (cgroup.c), which bounds the memory and processes of the whole
 * tree and is emptied and removed when the run ends.
 */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include "grade_impl.h"

extern char **environ;

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

/* fd onto number, even when it already is that number (dup2 would
   then keep FD_CLOEXEC). */
static int place(int fd, int number)
{
    if (fd == number)
        return fcntl(fd, F_SETFD, 0);
    return dup2(fd, number) < 0 ? -1 : 0;
}

/*
 * valgrind keeps the descriptors from the soft RLIMIT_NOFILE it starts
 * with upwards for itself: the program under it gets EBADF there (and
 * valgrind logs "invalid file descriptor N"), while valgrind's own
 * --log-fd=N keeps working.  The log's descriptor is placed below the
 * inherited limit (grade_log_fd) and the limit then lowered to it, last,
 * after any other limit on descriptors, keeping the hard limit the child
 * has by then (getrlimit: not on POSIX's list of async-signal-safe
 * functions, but a bare system call that takes no lock).
 */
static void keep_log_out_of_reach(int log_number)
{
    struct rlimit limit;
    if (getrlimit(RLIMIT_NOFILE, &limit) == 0 &&
        limit.rlim_cur > (rlim_t)log_number)
        set_limit(RLIMIT_NOFILE, (rlim_t)log_number, limit.rlim_max);
}

int grade_log_fd(void)
{
    struct rlimit limit;
    rlim_t highest = 1023;
    if (getrlimit(RLIMIT_NOFILE, &limit) == 0 &&
        limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur <= highest)
        highest = limit.rlim_cur > 0 ? limit.rlim_cur - 1 : 0;
    /* Above the descriptors the child is given by number. */
    return highest > FD_FILE + 1 ? (int)highest : -1;
}

/* In the child, between fork and exec: async-signal-safe calls only. */
static void child(const char *program, char *const argv[],
                  char *const env[], const char *dir, const child_fds *fds,
                  const grade_limits *limits, const grade_cgroup *cg,
                  long max_fd)
{
    int fd, moved[6], in = -1, i;
    long k;
    /* Into the run's cgroup before anything else: all it starts is
       counted there. */
    if (grade_cgroup_enter(cg) != 0)
        _exit(126);
    /* A session of its own: its own process group (killed as one), and
       no controlling terminal to push input into (TIOCSTI). */
    setsid();
#ifdef __linux__
    /* If the grader dies (killed, not cancelled), so does the program. */
    prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
    /* Out of the way of the numbers they are going to, first. */
    {
        const int sources[6] = {fds->out, fds->err, fds->log, fds->json,
                                fds->name, fds->file};
        for (i = 0; i < 6; i++) {
            moved[i] = -1;
            if (sources[i] >= 0) {
                moved[i] = fcntl(sources[i], F_DUPFD, 20);
                if (moved[i] < 0)
                    _exit(126);
            }
        }
    }
    if (fds->in >= 0 && (in = fcntl(fds->in, F_DUPFD, 20)) < 0)
        _exit(126);
    fd = in >= 0 ? in : open("/dev/null", O_RDONLY);
    if (fd < 0 || dup2(fd, 0) < 0)
        _exit(126);
    if (place(moved[0], 1) != 0 || place(moved[1], 2) != 0)
        _exit(126);
    if (moved[2] >= 0 && place(moved[2], fds->log_number) != 0)
        _exit(126);
    if (moved[3] >= 0 && place(moved[3], FD_JSON) != 0)
        _exit(126);
    if (moved[4] >= 0 && place(moved[4], FD_NAME) != 0)
        _exit(126);
    if (moved[5] >= 0 && place(moved[5], FD_FILE) != 0)
        _exit(126);
    for (k = 3; k < max_fd; k++) {
        if ((moved[2] >= 0 && k == fds->log_number) ||
            (moved[3] >= 0 && k == FD_JSON) ||
            (moved[4] >= 0 && k == FD_NAME) ||
            (moved[5] >= 0 && k == FD_FILE))
            continue;
        close((int)k);
    }
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
    if (limits->open_files > 0)
        set_limit(RLIMIT_NOFILE, (rlim_t)limits->open_files,
                  (rlim_t)limits->open_files);
    if (moved[2] >= 0)
        keep_log_out_of_reach(fds->log_number);
    signal(SIGPIPE, SIG_DFL);
    signal(SIGXFSZ, SIG_DFL);
    execve(program, argv, env);
    _exit(127);
}

/* The log's reader: what it holds, kept up to LOG_KEPT bytes. */
#define LOG_KEPT ((size_t)16 << 20)

typedef struct log_reader {
    int fd;
    char *data;
    size_t size, capacity;
    int overflow, failed;
} log_reader;

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
        if (log->size + (size_t)got > LOG_KEPT) {
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

/* Waits for pid, killing its process group after limits->wall seconds
   or when limits->cancelled says so, reading the log meanwhile. */
static void wait_for(pid_t pid, const grade_limits *limits,
                     log_reader *log, grade_outcome *outcome)
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

/* An unlinked file for a capture (tmpfile: the program cannot reach it
   by name, swap it for a FIFO or a link). */
static FILE *capture(void)
{
    FILE *file = tmpfile();
    if (file != NULL)
        fcntl(fileno(file), F_SETFD, FD_CLOEXEC);
    return file;
}

static rayo_status read_capture(FILE *file, uint64_t limit, char **data,
                                size_t *size, rayo_error *err)
{
    int cut = 0;
    if (file == NULL) {
        *data = NULL;
        *size = 0;
        return RAYO_OK;
    }
    if (lseek(fileno(file), 0, SEEK_SET) != 0)
        return rayo_error_set(err, RAYO_ERR_IO, "grade: a capture: %s",
                              strerror(errno));
    return grade_read_fd(fileno(file), limit, data, size, &cut, err);
}

/* bwrap's exit status, from its --json-status-fd: "exit-code": N.
   -1 when it never said (the sandbox could not be set up). */
static int sandbox_exit_code(FILE *json)
{
    char *text = NULL, *p;
    size_t size;
    int code = -1;
    rayo_error ignored = RAYO_ERROR_INIT(RAYO_LANG_EN);
    if (read_capture(json, 65536, &text, &size, &ignored) != RAYO_OK ||
        text == NULL)
        return -1;
    p = strstr(text, "\"exit-code\":");
    if (p != NULL)
        code = atoi(p + strlen("\"exit-code\":"));
    free(text);
    return code;
}

/* The environment of a student's run, or of a tool in the sandbox. */
static char **minimal_env(const char *dir)
{
    char **env = calloc(5, sizeof *env);
    if (env == NULL)
        return NULL;
    env[0] = strdup("PATH=/usr/local/bin:/usr/bin:/bin");
    env[1] = grade_concat("HOME=", dir);
    env[2] = grade_concat("TMPDIR=", dir);
    env[3] = strdup("LANG=C");
    if (env[0] == NULL || env[1] == NULL || env[2] == NULL ||
        env[3] == NULL) {
        grade_words_free(env);
        return NULL;
    }
    return env;
}

/* The caller's environment for a tool run outside the sandbox, but for
   TMPDIR: the grade's own folder, so what the compiler leaves there (a
   crashing clang's reproducer files) goes with it. */
static char **tool_env(const char *dir)
{
    size_t n = 0, i, k = 0;
    char **env;
    while (environ[n] != NULL)
        n++;
    env = calloc(n + 2, sizeof *env);
    if (env == NULL)
        return NULL;
    for (i = 0; i < n; i++) {
        if (strncmp(environ[i], "TMPDIR=", 7) == 0)
            continue;
        env[k] = strdup(environ[i]);
        if (env[k++] == NULL) {
            grade_words_free(env);
            return NULL;
        }
    }
    env[k] = grade_concat("TMPDIR=", dir);
    if (env[k] == NULL) {
        grade_words_free(env);
        return NULL;
    }
    return env;
}

void grade_captured_free(grade_captured *got)
{
    free(got->out);
    free(got->errors);
    free(got->log);
    free(got->file_name);
    free(got->file);
    memset(got, 0, sizeof *got);
}

/* Unsandboxed: the one image file in the work folder, opened relative
   to the folder, without following links or blocking on a FIFO, and
   only when it is a regular file. */
static rayo_status collect_here(const grade_context *ctx, uint64_t limit,
                                grade_captured *got, rayo_error *err)
{
    static const char *const extensions[] = {".pbm", ".pgm", ".ppm", ".pnm"};
    int dir = open(ctx->work != NULL ? ctx->work : ctx->dir,
                   O_RDONLY | O_DIRECTORY | O_NOFOLLOW);
    DIR *d = dir >= 0 ? fdopendir(dir) : NULL;
    struct dirent *entry;
    char *found = NULL;
    int count = 0, fd;
    struct stat st;
    rayo_status status = RAYO_OK;
    int cut;
    if (d == NULL) {
        if (dir >= 0)
            close(dir);
        return RAYO_OK;
    }
    while ((entry = readdir(d)) != NULL) {
        size_t n = strlen(entry->d_name), i;
        if (n < 5 || entry->d_name[0] == '.')
            continue;
        for (i = 0; i < 4; i++)
            if (strcmp(entry->d_name + n - 4, extensions[i]) == 0)
                break;
        if (i < 4 && count++ == 0)
            found = strdup(entry->d_name);
    }
    if (count == 1 && found != NULL) {
        fd = openat(dirfd(d), found, O_RDONLY | O_NOFOLLOW | O_NONBLOCK);
        if (fd >= 0 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode)) {
            status = grade_read_fd(fd, limit, &got->file, &got->file_size,
                                   &cut, err);
            if (status == RAYO_OK) {
                got->file_name = found;
                found = NULL;
            }
        }
        if (fd >= 0)
            close(fd);
    }
    free(found);
    closedir(d);
    return status;
}

rayo_status grade_spawn(grade_context *ctx, const grade_run *run,
                        const grade_limits *limits, grade_captured *got,
                        rayo_error *err)
{
    int student = run->role == GRADE_ROLE_STUDENT;
    /* A context without a work folder (a test's) runs in dir. */
    const char *work = ctx->work != NULL ? ctx->work : ctx->dir;
    const char *dir = student ? work : ".";
    char **env = NULL, **words = NULL, **full = NULL;
    char *program = NULL;
    FILE *out = capture(), *errf = capture();
    FILE *json = NULL, *name = NULL, *file = NULL;
    int pipe_fds[2] = {-1, -1};
    log_reader log;
    child_fds fds;
    grade_cgroup cg;
    long max_fd = sysconf(_SC_OPEN_MAX);
    rayo_status status = RAYO_OK;
    pid_t pid;

    memset(got, 0, sizeof *got);
    memset(&log, 0, sizeof log);
    memset(&cg, 0, sizeof cg);
    cg.procs[0] = cg.procs[1] = -1;
    log.fd = -1;
    if (max_fd < 0 || max_fd > 65536)
        max_fd = 65536;
    if (out == NULL || errf == NULL) {
        status = rayo_error_set(err, RAYO_ERR_IO, "grade: cannot create a "
                                                  "capture file: %s",
                                strerror(errno));
        goto done;
    }
    if (run->log_fd >= 3) {
        /* A socket, not a pipe: a pipe can be opened again by its
           /proc/self/fd name, which valgrind does not guard. */
        if (socketpair(AF_UNIX, SOCK_STREAM, 0, pipe_fds) != 0) {
            status = rayo_error_set(err, RAYO_ERR_IO, "grade: socketpair: "
                                                      "%s",
                                    strerror(errno));
            goto done;
        }
        shutdown(pipe_fds[0], SHUT_WR);
        shutdown(pipe_fds[1], SHUT_RD);
        fcntl(pipe_fds[0], F_SETFD, FD_CLOEXEC);
        fcntl(pipe_fds[1], F_SETFD, FD_CLOEXEC);
        fcntl(pipe_fds[0], F_SETFL, O_NONBLOCK);
        log.fd = pipe_fds[0];
    }
    if (ctx->sandboxed) {
        json = capture();
        if (student && run->collect) {
            name = capture();
            file = capture();
        }
        if (json == NULL || (student && run->collect &&
                             (name == NULL || file == NULL))) {
            status = rayo_error_set(err, RAYO_ERR_IO, "grade: cannot create "
                                                      "a capture file: %s",
                                    strerror(errno));
            goto done;
        }
        words = grade_sandbox_argv(ctx, run, FD_JSON);
        program = ctx->bwrap != NULL ? strdup(ctx->bwrap) : NULL;
        env = minimal_env(work);
        full = words;
        dir = "/";
    } else {
        program = run->search ? resolve(run->argv[0]) : strdup(run->argv[0]);
        env = student ? minimal_env(work) : tool_env(ctx->dir);
        full = (char **)run->argv;
    }
    if (program == NULL || full == NULL || env == NULL) {
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
        goto done;
    }
    fds.out = fileno(out);
    fds.err = fileno(errf);
    fds.log = pipe_fds[1];
    fds.log_number = run->log_fd;
    fds.json = json != NULL ? fileno(json) : -1;
    fds.name = name != NULL ? fileno(name) : -1;
    fds.file = file != NULL ? fileno(file) : -1;
    if (limits->tree_memory > 0 || limits->processes > 0) {
        status = grade_cgroup_create(&cg, limits->tree_memory,
                                     limits->processes, err);
        if (status != RAYO_OK)
            goto done;
    }
    fds.in = run->input > 0 ? run->input : -1;
    pid = fork();
    if (pid < 0) {
        status = rayo_error_set(err, RAYO_ERR_IO, "grade: cannot start %s: %s",
                                run->argv[0], strerror(errno));
        goto done;
    }
    if (pid == 0)
        child(program, full, env != NULL ? env : environ, dir, &fds, limits,
              &cg, max_fd);
    if (pipe_fds[1] >= 0) {
        close(pipe_fds[1]);
        pipe_fds[1] = -1;
    }
    wait_for(pid, limits, &log, &got->outcome);
    /* What the kernel did in the group, then nothing left in it. */
    got->memory_exceeded = grade_cgroup_oom(&cg);
    got->memory_peak = grade_cgroup_peak(&cg);
    grade_cgroup_remove(&cg);
    if (got->outcome.ending == GRADE_CANCELLED) {
        status = rayo_error_set(err, RAYO_ERR_CANCELLED, "grade: cancelled");
        goto done;
    }
    status = read_capture(out, run->out_limit, &got->out, &got->out_size,
                          err);
    if (status == RAYO_OK)
        status = read_capture(errf, 1u << 20, &got->errors,
                              &got->errors_size, err);
    if (status != RAYO_OK)
        goto done;
    got->log = log.data;
    got->log_size = log.size;
    got->log_overflow = log.overflow || log.failed;
    log.data = NULL;
    if (got->log == NULL && run->log_fd >= 3)
        got->log = calloc(1, 1);
    else if (got->log != NULL)
        got->log[got->log_size] = '\0';
    if (ctx->sandboxed && got->outcome.ending == GRADE_EXITED) {
        int code = sandbox_exit_code(json);
        if (code < 0) {
            /* bwrap never started the program: its own message. */
            size_t n = got->errors != NULL ? strcspn(got->errors, "\n") : 0;
            status = rayo_error_set(err, RAYO_ERR_IO, "grade: the sandbox "
                                                      "could not be set up: "
                                                      "%.*s",
                                    (int)(n > 200 ? 200 : n),
                                    n > 0 ? got->errors : "bwrap failed");
            goto done;
        }
        /* bwrap exits 128 + N for a program killed by signal N. */
        if (code > 128 && code <= 128 + 64) {
            got->outcome.ending = GRADE_SIGNALED;
            got->outcome.status = code - 128;
        } else
            got->outcome.status = code;
    }
    if (student && run->collect && got->out_size == 0) {
        if (ctx->sandboxed) {
            char *text = NULL;
            size_t size = 0;
            status = read_capture(name, 4096, &text, &size, err);
            if (status == RAYO_OK && text != NULL && size > 0) {
                got->file_name = text;
                text = NULL;
                status = read_capture(file, run->out_limit, &got->file,
                                      &got->file_size, err);
            }
            free(text);
        } else
            status = collect_here(ctx, run->out_limit, got, err);
    }
done:
    grade_cgroup_remove(&cg);
    if (status != RAYO_OK)
        grade_captured_free(got);
    if (pipe_fds[0] >= 0)
        close(pipe_fds[0]);
    if (pipe_fds[1] >= 0)
        close(pipe_fds[1]);
    free(log.data);
    if (out != NULL)
        fclose(out);
    if (errf != NULL)
        fclose(errf);
    if (json != NULL)
        fclose(json);
    if (name != NULL)
        fclose(name);
    if (file != NULL)
        fclose(file);
    grade_words_free(env);
    if (words != NULL)
        grade_words_free(words);
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
