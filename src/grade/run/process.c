/*
 * process.c - running one program for the grader: the compiler, the
 * functions' harness, the student's program or valgrind, with no input,
 * its output into unlinked files the grader holds, under resource limits,
 * inside the sandbox when there is one (sandbox.c builds bwrap's words;
 * this file runs them: one mechanism for every run).
 *
 * This file plans a run (the program's path, its environment, the
 * captures, the log's socket, the run's cgroup), forks, and reads back
 * what came of it; child.c is the child until exec, wait.c the waiting.
 * On Linux the child dies with the grader (PR_SET_PDEATHSIG) and bwrap's
 * --die-with-parent takes the whole sandbox with it; the run's cgroup
 * (cgroup.c) is emptied and removed when the run ends.
 */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include "spawn.h"

extern char **environ;

/* Marks a message for xgettext; the caller looks it up in its language. */
#define N_(text) text

const char *grade_signal_name(int signal_number)
{
    switch (signal_number) {
    case SIGSEGV: return N_("segmentation fault (SIGSEGV)");
    case SIGBUS: return N_("bus error (SIGBUS)");
    case SIGFPE: return N_("arithmetic exception (SIGFPE)");
    case SIGILL: return N_("illegal instruction (SIGILL)");
    case SIGABRT: return N_("abort (SIGABRT), e.g. a failed assert or a "
                         "corrupted heap");
    case SIGKILL: return N_("killed (SIGKILL)");
    case SIGTERM: return N_("terminated (SIGTERM)");
    case SIGXCPU: return N_("CPU time limit exceeded (SIGXCPU)");
    case SIGXFSZ: return N_("file size limit exceeded (SIGXFSZ)");
    case SIGPIPE: return N_("broken pipe (SIGPIPE)");
    case SIGTRAP: return N_("trap (SIGTRAP)");
    }
    return N_("a signal");
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

/* A number bwrap wrote on its --json-status-fd after key: the
   sandbox's first process ("child-pid":), its exit status
   ("exit-code":).  -1 when it never said (the sandbox could not be set
   up). */
static int sandbox_said(FILE *json, const char *key)
{
    char *text = NULL, *p;
    size_t size;
    int code = -1;
    rayo_error ignored = RAYO_ERROR_INIT(RAYO_LANG_EN);
    if (read_capture(json, 65536, &text, &size, &ignored) != RAYO_OK ||
        text == NULL)
        return -1;
    p = strstr(text, key);
    if (p != NULL)
        code = atoi(p + strlen(key));
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
    grade_limits here = grade_limits_here(limits, ctx->sandboxed);
    unsigned long uid = 0;
    int counted = 0, cg_version;
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
        status = grade_run_uid(ctx, &uid, err);
        if (status != RAYO_OK)
            goto done;
        words = grade_sandbox_argv(ctx, run, FD_JSON, here.processes,
                                   &counted);
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
    if (here.tree_memory > 0 || here.processes > 0) {
        status = grade_cgroup_create(&cg, here.tree_memory, here.processes,
                                     err);
        if (status != RAYO_OK)
            goto done;
    }
    fds.in = run->input > 0 ? run->input : -1;
    /* Counted inside the sandbox, the processes are not limited again
       on bwrap (there the count would be all the user's). */
    if (counted)
        here.processes = 0;
    pid = fork();
    if (pid < 0) {
        status = rayo_error_set(err, RAYO_ERR_IO, "grade: cannot start %s: %s",
                                run->argv[0], strerror(errno));
        goto done;
    }
    if (pid == 0) {
        child_plan plan;
        plan.program = program;
        plan.argv = full;
        plan.env = env != NULL ? env : environ;
        plan.dir = dir;
        plan.fds = &fds;
        plan.limits = &here;
        plan.cg = &cg;
        plan.uid = uid;
        plan.max_fd = max_fd;
        grade_child(&plan);
    }
    if (pipe_fds[1] >= 0) {
        close(pipe_fds[1]);
        pipe_fds[1] = -1;
    }
    grade_wait(pid, &here, &log, &got->outcome);
    /* What the kernel did in the group, then nothing left in it. */
    cg_version = cg.version;
    got->memory_exceeded = grade_cgroup_oom(&cg);
    got->memory_peak = grade_cgroup_peak(&cg);
    grade_cgroup_remove(&cg);
    /* Without a group to empty, the sandbox's first process, which the
       kernel makes take every other with it, is waited out. */
    if (ctx->sandboxed && cg_version == 0) {
        int first = sandbox_said(json, "\"child-pid\":");
        if (first > 1)
            grade_wait_gone((pid_t)first);
    }
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
        int code = sandbox_said(json, "\"exit-code\":");
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
