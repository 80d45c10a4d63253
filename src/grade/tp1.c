/*
 * tp1.c - grading a whole program built by the submission's own Makefile
 * (TP1, rayo_grade_exercise.program): the folder is copied into the work
 * folder, built there with `make` in the sandbox, and the course's flags
 * are checked on every compile command make echoed.  The other steps
 * follow: the statement's signatures (tp1_source.c), the runs and their
 * files (tp1_runs.c), and valgrind on one small run (valgrind.c).
 *
 * There is no reference image (each group renders a scene of its own):
 * the image criterion is skipped and says so.  Not the place for the
 * functions harness that would call the student's computar_intensidad;
 * docs/grading.md ("TP1") says what is checked and what is not.
 */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "grade_impl.h"
#include "tp1.h"

#define BUILD_SECONDS 120.0
#define COPY_FILES 256                  /* files of a submission, at most */
#define COPY_BYTES ((uint64_t)64 << 20) /* their bytes, at most */
#define QUOTED_LINES 8

static const char *const course_flags[] = {"-std=c99", "-Wall", "-Werror",
                                           "-pedantic"};
#define COURSE_FLAGS (sizeof course_flags / sizeof course_flags[0])

/* One regular file of the submission, copied with its bytes. */
static rayo_status copy_file(int from, const char *name, const char *to,
                             uint64_t *left, rayo_error *err)
{
    int in = openat(from, name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK);
    char *data = NULL, *path;
    size_t size = 0;
    int cut = 0, out;
    struct stat st;
    rayo_status status;
    if (in < 0)
        return RAYO_OK;
    if (fstat(in, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(in);
        return RAYO_OK;
    }
    status = grade_read_fd(in, *left, &data, &size, &cut, err);
    close(in);
    if (status != RAYO_OK)
        return status;
    if (cut) {
        free(data);
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "%s: the submission holds more than %llu MiB "
                              "of files; expected sources, a Makefile and "
                              "STL files",
                              name, (unsigned long long)(COPY_BYTES >> 20));
    }
    *left -= size;
    path = grade_path_join(to, name);
    out = path != NULL ? open(path, O_WRONLY | O_CREAT | O_EXCL, 0600) : -1;
    if (out < 0 || (size > 0 && write(out, data, size) != (ssize_t)size))
        status = path == NULL ? rayo_error_set(err, RAYO_ERR_NOMEM,
                                               "grade: out of memory")
                              : rayo_error_set(err, RAYO_ERR_IO, "%s: %s",
                                               path, strerror(errno));
    if (out >= 0 && close(out) != 0 && status == RAYO_OK)
        status = rayo_error_set(err, RAYO_ERR_IO, "%s: %s", path,
                                strerror(errno));
    free(path);
    free(data);
    return status;
}

/* The regular files directly in the submission's folder (no link, no
   subfolder) into the work folder. */
static rayo_status copy_submission(grade_context *ctx, const char *folder,
                                   rayo_error *err)
{
    int dir = open(folder, O_RDONLY | O_DIRECTORY);
    DIR *d = dir >= 0 ? fdopendir(dir) : NULL;
    struct dirent *entry;
    uint64_t left = COPY_BYTES;
    size_t files = 0;
    rayo_status status = RAYO_OK;
    if (d == NULL) {
        if (dir >= 0)
            close(dir);
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", folder,
                              strerror(errno));
    }
    while (status == RAYO_OK && (entry = readdir(d)) != NULL) {
        if (entry->d_name[0] == '.')
            continue;
        if (++files > COPY_FILES) {
            status = rayo_error_set(err, RAYO_ERR_INVALID,
                                    "%s: the submission holds more than %d "
                                    "files; expected sources, a Makefile "
                                    "and STL files",
                                    folder, COPY_FILES);
            break;
        }
        status = copy_file(dirfd(d), entry->d_name, ctx->work, &left, err);
    }
    closedir(d);
    ctx->work_kept = 1;
    return status;
}

/* The compiler command, as make is told it (CC=...). */
static char *cc_assignment(const grade_context *ctx)
{
    size_t i, n = 4;
    char *text;
    for (i = 0; i < ctx->cc_words; i++)
        n += strlen(ctx->cc[i]) + 1;
    text = malloc(n);
    if (text == NULL)
        return NULL;
    strcpy(text, "CC=");
    for (i = 0; i < ctx->cc_words; i++) {
        if (i > 0)
            strcat(text, " ");
        strcat(text, ctx->cc[i]);
    }
    return text;
}

/* Whether the line (length n) holds word as a word of its own. */
static int has_word(const char *line, size_t n, const char *word)
{
    size_t w = strlen(word), i;
    for (i = 0; i + w <= n; i++)
        if (memcmp(line + i, word, w) == 0 && (i == 0 || line[i - 1] == ' ') &&
            (i + w == n || line[i + w] == ' ' || line[i + w] == '\t'))
            return 1;
    return 0;
}

/* Whether a command line (length n) runs a C compiler: its first word
   is the grader's, or is named cc, c99, or *gcc* or *clang* (a Makefile
   that spells gcc itself). */
static int runs_compiler(const grade_context *ctx, const char *line,
                         size_t n)
{
    size_t w = strcspn(line, " \t"), b;
    char first[128];
    const char *base;
    if (w >= n || w == 0 || w >= sizeof first)
        return 0;
    memcpy(first, line, w);
    first[w] = '\0';
    if (strcmp(first, ctx->cc[0]) == 0)
        return 1;
    base = strrchr(first, '/') != NULL ? strrchr(first, '/') + 1 : first;
    b = strlen(base);
    return strcmp(base, "cc") == 0 || strcmp(base, "c99") == 0 ||
           strstr(base, "gcc") != NULL || strstr(base, "clang") != NULL ||
           (b > 3 && strcmp(base + b - 3, "-cc") == 0);
}

/* Whether the line (length n) names a .c file: a compile, not a link of
   objects alone (which needs no warning flags). */
static int names_source(const char *line, size_t n)
{
    size_t i;
    for (i = 2; i <= n; i++)
        if (line[i - 2] == '.' && line[i - 1] == 'c' &&
            (i == n || line[i] == ' ' || line[i] == '\t'))
            return 1;
    return 0;
}

/* Every compile command make echoed must carry the course's flags. */
static rayo_status check_flags(grade_context *ctx, const char *out,
                               rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_COMPILE];
    const char *line = out;
    size_t commands = 0, i;
    while (*line != '\0') {
        size_t n = strcspn(line, "\n");
        if (runs_compiler(ctx, line, n) && names_source(line, n)) {
            commands++;
            for (i = 0; i < COURSE_FLAGS; i++)
                if (!has_word(line, n, course_flags[i]))
                    return grade_fail(item, err,
                                      "the compile command '%.*s' lacks %s; "
                                      "the course builds with -std=c99 "
                                      "-Wall -Werror -pedantic",
                                      (int)(n > 200 ? 200 : n), line,
                                      course_flags[i]);
        }
        line += n + (line[n] == '\n');
    }
    if (commands == 0)
        return grade_fail(item, err,
                          "make echoed no command that compiles a .c file, "
                          "so the course's flags could not be checked; let "
                          "the Makefile show its commands (no @, no -s)");
    return grade_say(item, err,
                     "make ran %zu compile commands, each with -std=c99 "
                     "-Wall -Werror -pedantic",
                     commands);
}

/* The statement's executable, a regular file make left in the folder. */
static rayo_status find_program(grade_context *ctx, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_COMPILE];
    const char *name = ctx->options->exercise->program;
    char *path = grade_path_join(ctx->work, name);
    struct stat st;
    if (path == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    if (lstat(path, &st) != 0 || !S_ISREG(st.st_mode) ||
        !(st.st_mode & S_IXUSR)) {
        free(path);
        return grade_fail(item, err,
                          "make succeeded but left no executable '%s'; the "
                          "statement names the program %s",
                          name, name);
    }
    ctx->program = path;
    return RAYO_OK;
}

static int printed_warning(const char *text)
{
    return text != NULL && strstr(text, "warning:") != NULL;
}

/* make -B (every target rebuilt, whatever was handed in) in the work
   folder, the grader's compiler as CC. */
static rayo_status build(grade_context *ctx, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_COMPILE];
    grade_limits limits = grade_compiler_limits(ctx->options, BUILD_SECONDS);
    char *cc = cc_assignment(ctx);
    char *argv[] = {"make", "--no-print-directory", "-B", "-C", ctx->work,
                    cc, NULL};
    grade_run run;
    grade_captured got;
    rayo_status status;
    if (cc == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    run = grade_tool_run(argv);
    status = grade_spawn(ctx, &run, &limits, &got, err);
    free(cc);
    if (status != RAYO_OK)
        return status;
    if (got.outcome.ending != GRADE_EXITED || got.outcome.status != 0) {
        const char *said = got.errors_size > 0 ? got.errors : got.out;
        status = grade_fail(item, err, "make did not build the program; "
                                       "its first messages:");
        if (status == RAYO_OK)
            status = grade_quote(item, said != NULL ? said : "",
                                 QUOTED_LINES, err);
    } else {
        item->result = RAYO_GRADE_PASS;
        status = check_flags(ctx, got.out != NULL ? got.out : "", err);
        if (status == RAYO_OK &&
            (printed_warning(got.out) || printed_warning(got.errors))) {
            status = grade_fail(item, err, "the build printed warnings; the "
                                           "statement asks for none:");
            if (status == RAYO_OK)
                status = grade_quote(item,
                                     printed_warning(got.errors) ? got.errors
                                                                 : got.out,
                                     QUOTED_LINES, err);
        }
        if (status == RAYO_OK)
            status = find_program(ctx, err);
    }
    grade_captured_free(&got);
    return status;
}

rayo_status grade_tp1_steps(grade_context *ctx, rayo_error *err)
{
    rayo_grade_report *r = ctx->report;
    char *folder = grade_dir_of(ctx->absolute[0]);
    char *args[] = {"40", "30", "1", "valgrind.ppm", NULL};
    rayo_status status;
    if (folder == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    status = copy_submission(ctx, folder, err);
    free(folder);
    if (status == RAYO_OK)
        status = build(ctx, err);
    if (status != RAYO_OK || r->items[RAYO_GRADE_COMPILE].result !=
                                 RAYO_GRADE_PASS) {
        free(ctx->program);
        ctx->program = NULL;
        return status;
    }
    status = grade_tp1_sources(ctx, err);
    if (status == RAYO_OK)
        status = grade_tp1_runs(ctx, err);
    if (status == RAYO_OK)
        status = grade_say(&r->items[RAYO_GRADE_IMAGE], err,
                           "not compared: the course gives no reference "
                           "image for TP1, each group renders a scene of "
                           "its own");
    ctx->args = args;
    if (status == RAYO_OK && ctx->options->valgrind && !ctx->stopped)
        status = grade_step_valgrind(ctx, err);
    ctx->args = NULL;
    return status;
}
