/*
 * sandbox.c - the grader's isolation: whether a bubblewrap sandbox can
 * be made here (tried once, for real), and the bwrap words that put one
 * run inside it.  process.c runs those words; nothing else knows them.
 *
 * Inside, a run sees a read-only system with almost nothing of /etc, a
 * /proc of its own PID namespace, a minimal /dev, no network, IPC or UTS
 * of the host, a new session, uid and gid 65534 with no capabilities.
 * The compiler (GRADE_ROLE_TOOL) also sees the sources' folders
 * read-only and the build folder; the student's code the one file it
 * runs and a fresh tmpfs folder.  docs/grading.md ("Isolation") lists
 * it all; this file is not where limits are chosen (limits.c, run.c).
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "../grade_impl.h"

/* A growing list of owned words, NULL-terminated. */
typedef struct words {
    char **v;
    size_t n, capacity;
    int failed;
} words;

static void add(words *w, const char *word)
{
    char *copy;
    if (w->failed)
        return;
    if (w->n + 2 > w->capacity) {
        size_t capacity = w->capacity * 2 + 32;
        char **grown = realloc(w->v, capacity * sizeof *grown);
        if (grown == NULL) {
            w->failed = 1;
            return;
        }
        w->v = grown;
        w->capacity = capacity;
    }
    copy = strdup(word);
    if (copy == NULL) {
        w->failed = 1;
        return;
    }
    w->v[w->n++] = copy;
    w->v[w->n] = NULL;
}

static void add2(words *w, const char *a, const char *b)
{
    add(w, a);
    add(w, b);
}

static void add3(words *w, const char *a, const char *b, const char *c)
{
    add(w, a);
    add(w, b);
    add(w, c);
}

void grade_words_free(char **v)
{
    size_t i;
    if (v == NULL)
        return;
    for (i = 0; v[i] != NULL; i++)
        free(v[i]);
    free(v);
}

/* The devices a run sees: the compiler none but /dev/null (an
   #include of /dev/zero or /dev/urandom finds nothing), the program the
   few a C program uses; each bound from the host into a small tmpfs,
   read-only once they are in. */
static void add_dev(words *w, int tool)
{
    static const char *const devices[] = {"/dev/null", "/dev/zero",
                                          "/dev/full", "/dev/random",
                                          "/dev/urandom"};
    size_t i, count = tool ? 1 : sizeof devices / sizeof devices[0];
    add2(w, "--size", "65536");
    add2(w, "--tmpfs", "/dev");
    for (i = 0; i < count; i++)
        add3(w, "--dev-bind", devices[i], devices[i]);
    add3(w, "--symlink", "/proc/self/fd", "/dev/fd");
    add3(w, "--symlink", "/proc/self/fd/0", "/dev/stdin");
    add3(w, "--symlink", "/proc/self/fd/1", "/dev/stdout");
    add3(w, "--symlink", "/proc/self/fd/2", "/dev/stderr");
    add2(w, "--remount-ro", "/dev");
}

/* The namespaces, the system read-only, /proc and /dev. */
static void add_system(words *w, int tool)
{
    static const char *const tops[] = {"/bin", "/lib", "/lib32", "/lib64",
                                       "/libx32", "/sbin"};
    static const char *const etc[] = {"/etc/alternatives", "/etc/ld.so.cache",
                                      "/etc/ld.so.conf",
                                      "/etc/ld.so.conf.d"};
    size_t i;
    add(w, "--unshare-user");
    add(w, "--unshare-pid");
    add(w, "--unshare-net");
    add(w, "--unshare-ipc");
    add(w, "--unshare-uts");
    add(w, "--unshare-cgroup-try");
    add(w, "--die-with-parent");
    add(w, "--new-session");
    add2(w, "--cap-drop", "ALL");
    add2(w, "--uid", "65534");
    add2(w, "--gid", "65534");
    add2(w, "--hostname", "rayo-grade");
    add3(w, "--ro-bind", "/usr", "/usr");
    for (i = 0; i < sizeof tops / sizeof tops[0]; i++) {
        struct stat st;
        char target[4096];
        ssize_t n;
        if (lstat(tops[i], &st) != 0)
            continue;
        if (S_ISLNK(st.st_mode)) {
            n = readlink(tops[i], target, sizeof target - 1);
            if (n <= 0)
                continue;
            target[n] = '\0';
            add3(w, "--symlink", target, tops[i]);
        } else if (S_ISDIR(st.st_mode))
            add3(w, "--ro-bind", tops[i], tops[i]);
    }
    for (i = 0; i < sizeof etc / sizeof etc[0]; i++)
        add3(w, "--ro-bind-try", etc[i], etc[i]);
    add2(w, "--proc", "/proc");
    add_dev(w, tool);
}

/* The environment inside: PATH, HOME and TMPDIR, LANG=C; the compiler
   keeps the caller's locale (its messages in the caller's language). */
static void add_env(words *w, const char *home, const char *tmp, int tool)
{
    static const char *const locale[] = {"LANG", "LC_ALL", "LC_MESSAGES",
                                         "LC_CTYPE"};
    size_t i;
    add(w, "--clearenv");
    add3(w, "--setenv", "PATH", "/usr/local/bin:/usr/bin:/bin");
    add3(w, "--setenv", "HOME", home);
    add3(w, "--setenv", "TMPDIR", tmp);
    add3(w, "--setenv", "LANG", "C");
    for (i = 0; tool && i < sizeof locale / sizeof locale[0]; i++) {
        const char *value = getenv(locale[i]);
        if (value != NULL && strlen(value) < 100)
            add3(w, "--setenv", locale[i], value);
    }
}

/* The wrapper that runs a student's program when its image file is to
   be brought back: the program (without the wrapper's descriptors),
   then everything else in the sandbox killed, then the one image file
   in the folder, if a regular file, written to descriptors 5 (its name)
   and 6 (its bytes); it ends as the program did. */
static const char collect_script[] =
    "\"$@\" 5>&- 6>&-\n"
    "s=$?\n"
    "kill -9 -1 2>/dev/null\n"
    "n=0\n"
    "for f in *.pbm *.pgm *.ppm *.pnm; do\n"
    "  if [ -e \"$f\" ] || [ -h \"$f\" ]; then n=$((n+1)); g=$f; fi\n"
    "done\n"
    "if [ $n -eq 1 ] && [ -f \"$g\" ] && [ ! -h \"$g\" ]; then\n"
    "  printf %s \"$g\" >&5; cat -- \"$g\" >&6\n"
    "fi\n"
    "if [ $s -gt 128 ] && [ $s -le 192 ]; then kill -$((s-128)) $$; fi\n"
    "exit $s\n";

char **grade_sandbox_argv(const grade_context *ctx, const grade_run *run,
                          int json_fd, unsigned long processes, int *counted)
{
    words w = {NULL, 0, 0, 0};
    char number[32];
    size_t i;
    add(&w, ctx->bwrap);
    add_system(&w, run->role == GRADE_ROLE_TOOL);
    snprintf(number, sizeof number, "%llu",
             (unsigned long long)ctx->options->disk);
    if (run->role == GRADE_ROLE_TOOL) {
        /* The compiler's temporary files (assembly, objects) go to a
           tmpfs of options->disk bytes, gone when it ends; only the
           files it is told to make (-o) reach the build folder, each
           bounded by the file size limit. */
        add2(&w, "--size", number);
        add2(&w, "--tmpfs", "/tmp");
        add2(&w, "--dir", ctx->cwd);
        for (i = 0; i < ctx->source_count; i++) {
            /* Under a uid of its own, a copy it can read (uid.c). */
            char *dir = grade_dir_of(ctx->absolute[i]);
            char *copy = ctx->run_uid != 0 ? grade_source_copy(ctx, i)
                                           : NULL;
            if (dir == NULL || (ctx->run_uid != 0 && copy == NULL)) {
                free(dir);
                w.failed = 1;
                break;
            }
            add3(&w, "--ro-bind", copy != NULL ? copy : dir, dir);
            free(dir);
            free(copy);
        }
        add3(&w, "--bind", ctx->dir, ctx->dir);
        add(&w, "--remount-ro");
        add(&w, "/");
        add_env(&w, ctx->dir, "/tmp", 1);
        add2(&w, "--chdir", ctx->cwd);
    } else {
        if (ctx->work_kept) {
            add3(&w, "--bind", ctx->work, ctx->work);
        } else {
            add2(&w, "--size", number);
            add2(&w, "--tmpfs", ctx->work);
        }
        if (run->program != NULL)
            add3(&w, "--ro-bind", run->program, run->program);
        add(&w, "--remount-ro");
        add(&w, "/");
        add_env(&w, ctx->work, ctx->work, 0);
        add2(&w, "--chdir", ctx->work);
    }
    snprintf(number, sizeof number, "%d", json_fd);
    add2(&w, "--json-status-fd", number);
    add(&w, "--");
    *counted = 0;
    if (processes > 0) {
        /* Set inside, the limit counts the processes of the sandbox's
           user namespace; set on bwrap, all those of the user. */
        char *prlimit = grade_which("prlimit"), nproc[64];
        if (prlimit != NULL) {
            snprintf(nproc, sizeof nproc, "--nproc=%lu:%lu", processes,
                     processes);
            add3(&w, prlimit, nproc, "--");
            *counted = 1;
        }
        free(prlimit);
    }
    if (run->role == GRADE_ROLE_STUDENT && run->collect) {
        add3(&w, "/bin/sh", "-c", collect_script);
        add(&w, "sh");
    }
    for (i = 0; run->argv[i] != NULL; i++) {
        if (i == 0 && run->search && strchr(run->argv[0], '/') == NULL) {
            /* The host's path: the same file inside (it is under /usr). */
            char *found = grade_which(run->argv[0]);
            add(&w, found != NULL ? found : run->argv[0]);
            free(found);
        } else
            add(&w, run->argv[i]);
    }
    if (w.failed) {
        grade_words_free(w.v);
        return NULL;
    }
    return w.v;
}

void grade_sandbox_describe(uint64_t disk, char *text, size_t room)
{
    snprintf(text, room, "sandbox: bubblewrap (user, pid, net, ipc, uts "
                         "namespaces; read-only system; %llu MiB disk; no "
                         "capabilities)",
             (unsigned long long)(disk >> 20));
}

/* The answer of the one trial, kept for the process's life; made once
   even when several gradings ask at once (rayo grade -j). */
static pthread_once_t tried = PTHREAD_ONCE_INIT;
static int works;
static char reason[200];

/* Runs bwrap once with the sandbox's namespaces and /bin/true inside;
   its message on failure. */
static void try_sandbox(void)
{
    char *bwrap = grade_which("bwrap");
    words w = {NULL, 0, 0, 0};
    int fds[2];
    pid_t pid;
    int status = 0;
    struct timespec start, now;
    if (bwrap == NULL) {
        snprintf(reason, sizeof reason, "bubblewrap (bwrap) is not "
                                        "installed");
        return;
    }
    add(&w, bwrap);
    add_system(&w, 0);
    add2(&w, "--size", "1048576");
    add2(&w, "--tmpfs", "/tmp");
    add(&w, "--remount-ro");
    add(&w, "/");
    add(&w, "--clearenv");
    add(&w, "--");
    add(&w, "/bin/true");
    free(bwrap);
    if (w.failed || pipe(fds) != 0) {
        grade_words_free(w.v);
        snprintf(reason, sizeof reason, "out of memory trying bubblewrap");
        return;
    }
    pid = fork();
    if (pid == 0) {
        int null = open("/dev/null", O_RDWR);
        dup2(null, 0);
        dup2(null, 1);
        dup2(fds[1], 2);
        close(fds[0]);
        execv(w.v[0], w.v);
        _exit(127);
    }
    close(fds[1]);
    grade_words_free(w.v);
    if (pid < 0) {
        close(fds[0]);
        snprintf(reason, sizeof reason, "cannot start bwrap: %s",
                 strerror(errno));
        return;
    }
    clock_gettime(CLOCK_MONOTONIC, &start);
    for (;;) {
        struct timespec pause = {0, 2000000};
        pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid)
            break;
        if (done < 0 && errno != EINTR) {
            status = -1;
            break;
        }
        clock_gettime(CLOCK_MONOTONIC, &now);
        if (now.tv_sec - start.tv_sec > 10) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            status = -1;
            break;
        }
        nanosleep(&pause, NULL);
    }
    if (status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 0) {
        works = 1;
    } else {
        char message[512];
        ssize_t got = read(fds[0], message, sizeof message - 1);
        size_t n;
        if (got < 0)
            got = 0;
        message[got] = '\0';
        n = strcspn(message, "\n");
        if (n > 120)
            n = 120;
        message[n] = '\0';
        snprintf(reason, sizeof reason, "bubblewrap cannot make a sandbox "
                                        "here (no user namespaces?): %.120s",
                 n > 0 ? message : "it failed");
    }
    close(fds[0]);
}

int grade_sandbox_available(char *why, size_t room)
{
    pthread_once(&tried, try_sandbox);
    if (!works && why != NULL && room > 0)
        snprintf(why, room, "%s", reason);
    return works;
}

/* Adds "; " and the limits that hold to text. */
static void add_limits(const rayo_grade_options *options, char *text,
                       size_t room)
{
    size_t n = strlen(text);
    if (n + 2 < room) {
        memcpy(text + n, "; ", 3);
        grade_limits_describe(options, text + n + 2, room - n - 2);
    }
}

int rayo_grade_sandbox_check(const rayo_grade_options *options, char *text,
                             size_t room)
{
    char why[200];
    int isolated = 0;
    if (options->sandbox == RAYO_GRADE_SANDBOX_OFF)
        snprintf(text, room, "not isolated: the sandbox is off "
                             "(--sandbox=off)");
    else if (grade_sandbox_available(why, sizeof why)) {
        grade_sandbox_describe(options->disk, text, room);
        isolated = 1;
    } else
        snprintf(text, room, "not isolated: %s; the submission runs with "
                             "your rights",
                 why);
    add_limits(options, text, room);
    return isolated;
}
