/*
 * valgrind.c - the last criterion: the program runs clean under
 * valgrind's memcheck: no invalid read, write or free, no use of
 * uninitialised memory, no leak (definitely, indirectly or possibly
 * lost).  Memory still reachable at exit is a warning: the course's
 * "pasa Valgrind" is about errors and lost blocks.
 *
 * The program runs again, under the same limits except address space
 * (valgrind reserves far more than the program uses) and with ten times
 * the time (memcheck is that much slower); memcheck writes its log into
 * the temporary directory and this file reads the log's words, not its
 * exit status.  Skipped when valgrind is not installed.
 *
 * Where the frame valgrind names is one of the constructors exercise 3's
 * statement gives (esfera_crear, luz_crear, arreglo_agregar), the
 * mistake is also said in the statement's terms: which destructor was
 * not called, or that arreglo_agregar writes past the end of v.  The
 * explanations go by the frame's function name, so they apply to any
 * exercise whose program has those functions (ej1's have none).
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grade_impl.h"

#define SLOWDOWN 10.0
#define SHOWN_ERRORS 4

/* A statement's constructor, and what a leak of its blocks means. */
typedef struct constructor_leak {
    const char *function;
    const char *explanation;
} constructor_leak;

static const constructor_leak constructor_leaks[] = {
    {"esfera_crear", "spheres made by esfera_crear are never destroyed: "
                     "call esfera_destruir on each before freeing the "
                     "array"},
    {"luz_crear", "lights made by luz_crear are never destroyed: call "
                  "luz_destruir on each before freeing the array"},
    {"arreglo_agregar", "the arrays' v is never freed: free each array's "
                        "v after destroying its elements"}};
#define CONSTRUCTOR_LEAKS \
    (sizeof constructor_leaks / sizeof constructor_leaks[0])

/* 1 when the frame "name (file.c:12)" is in the function called name. */
static int frame_is(const char *frame, const char *name)
{
    size_t n = strlen(name);
    return strncmp(frame, name, n) == 0 &&
           (frame[n] == ' ' || frame[n] == '\0');
}

static const char *const error_kinds[] = {
    "Invalid read of size", "Invalid write of size", "Invalid free",
    "Mismatched free", "Conditional jump or move depends on uninitialised",
    "Use of uninitialised value", "Syscall param",
    "Source and destination overlap",
    "Process terminating with default action of signal"};
#define ERROR_KINDS (sizeof error_kinds / sizeof error_kinds[0])

/* The log line at p without its "==PID== " prefix, into out. */
static void strip(const char *p, char *out, size_t room)
{
    size_t n = strcspn(p, "\n");
    const char *body = p;
    if (p[0] == '=' && p[1] == '=') {
        const char *end = strstr(p + 2, "== ");
        if (end != NULL && (size_t)(end - p) < n) {
            body = end + 3;
            n -= (size_t)(body - p);
        }
    }
    while (n > 0 && body[0] == ' ') {
        body++;
        n--;
    }
    snprintf(out, room, "%.*s", (int)n, body);
}

/* The first stack frame after p that is not inside valgrind's own
   replacements (malloc, free, ...): "main (leak.c:20)". */
static void first_frame(const char *p, char *out, size_t room)
{
    int lines = 0;
    out[0] = '\0';
    while ((p = strchr(p, '\n')) != NULL && lines++ < 12) {
        char line[512];
        const char *colon;
        p++;
        strip(p, line, sizeof line);
        if (strncmp(line, "at 0x", 5) != 0 && strncmp(line, "by 0x", 5) != 0)
            break;
        if (strstr(line, "vg_replace") != NULL ||
            strstr(line, "vgpreload") != NULL)
            continue;
        colon = strstr(line, ": ");
        snprintf(out, room, "%s", colon != NULL ? colon + 2 : line);
        return;
    }
}

static unsigned long long leak_bytes(const char *log, const char *kind,
                                     unsigned long long *blocks)
{
    const char *summary = strstr(log, "LEAK SUMMARY");
    const char *p = summary != NULL ? strstr(summary, kind) : NULL;
    unsigned long long bytes = 0;
    char number[64];
    size_t i, n = 0;
    *blocks = 0;
    if (p == NULL)
        return 0;
    p += strlen(kind);
    /* "   1,234 bytes in 5 blocks": valgrind groups digits with commas. */
    while (*p == ' ' || *p == ':')
        p++;
    for (i = 0; p[i] != '\0' && p[i] != ' ' && n + 1 < sizeof number; i++)
        if (p[i] != ',')
            number[n++] = p[i];
    number[n] = '\0';
    bytes = strtoull(number, NULL, 10);
    p = strstr(p, " in ");
    if (p != NULL)
        *blocks = strtoull(p + 4, NULL, 10);
    return bytes;
}

static rayo_status report_errors(rayo_grade_item *item, const char *log,
                                 unsigned *count, rayo_error *err)
{
    const char *p = log;
    rayo_status status = RAYO_OK;
    *count = 0;
    while (status == RAYO_OK && (p = strstr(p, "== ")) != NULL) {
        size_t k;
        p += 3;
        for (k = 0; k < ERROR_KINDS; k++) {
            char line[512], frame[512];
            if (strncmp(p, error_kinds[k], strlen(error_kinds[k])) != 0)
                continue;
            if ((*count)++ >= SHOWN_ERRORS)
                break;
            strip(p, line, sizeof line);
            first_frame(p, frame, sizeof frame);
            if (frame[0] != '\0')
                status = grade_fail(item, err, "%s, at %s", line, frame);
            else
                status = grade_fail(item, err, "%s", line);
            if (status == RAYO_OK && frame_is(frame, "arreglo_agregar") &&
                strncmp(line, "Invalid write", 13) == 0)
                status = grade_say(item, err, "a write past the end of v: "
                                              "grow it to n + 1 elements "
                                              "before writing v[n]");
            break;
        }
    }
    if (status == RAYO_OK && *count > SHOWN_ERRORS)
        status = grade_say(item, err, "... and %u more errors",
                           *count - SHOWN_ERRORS);
    return status;
}

/* For each lost block made by one of the statement's constructors,
   once, what was not destroyed or freed. */
static rayo_status explain_constructor_leaks(rayo_grade_item *item,
                                             const char *log,
                                             rayo_error *err)
{
    static const char record_words[] = " lost in loss record";
    int said[CONSTRUCTOR_LEAKS] = {0};
    const char *p = log;
    rayo_status status = RAYO_OK;
    while (status == RAYO_OK && (p = strstr(p, record_words)) != NULL) {
        char frame[512];
        size_t k;
        first_frame(p, frame, sizeof frame);
        p += sizeof record_words - 1;
        for (k = 0; k < CONSTRUCTOR_LEAKS && status == RAYO_OK; k++) {
            if (said[k] || !frame_is(frame, constructor_leaks[k].function))
                continue;
            said[k] = 1;
            status = grade_say(item, err, "%s",
                               constructor_leaks[k].explanation);
        }
    }
    return status;
}

static rayo_status report_leaks(rayo_grade_item *item, const char *log,
                                int *leaked, rayo_error *err)
{
    static const char *const kinds[] = {"definitely lost", "indirectly lost",
                                        "possibly lost"};
    unsigned long long blocks, bytes;
    char frame[512];
    size_t i;
    rayo_status status = RAYO_OK;
    const char *record;
    *leaked = 0;
    for (i = 0; i < 3 && status == RAYO_OK; i++) {
        bytes = leak_bytes(log, kinds[i], &blocks);
        if (bytes == 0)
            continue;
        *leaked = 1;
        status = grade_fail(item, err, "leak: %llu bytes in %llu blocks "
                                       "%s (allocated and never freed)",
                            bytes, blocks, kinds[i]);
    }
    record = strstr(log, "are definitely lost in loss record");
    if (record == NULL)
        record = strstr(log, "lost in loss record");
    if (status == RAYO_OK && *leaked && record != NULL) {
        first_frame(record, frame, sizeof frame);
        if (frame[0] != '\0')
            status = grade_say(item, err, "the biggest leak was allocated "
                                          "in %s",
                               frame);
        if (status == RAYO_OK)
            status = explain_constructor_leaks(item, log, err);
    }
    bytes = leak_bytes(log, "still reachable", &blocks);
    if (status == RAYO_OK && bytes > 0)
        status = grade_say(item, err, "warning: %llu bytes in %llu blocks "
                                      "still reachable at exit (a file "
                                      "not closed, memory not freed before "
                                      "returning from main)",
                           bytes, blocks);
    return status;
}

static rayo_status read_log(grade_context *ctx, const char *path,
                            const grade_outcome *outcome, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_VALGRIND];
    char *log = NULL;
    size_t size;
    unsigned errors;
    int leaked;
    rayo_status status;
    if (outcome->ending == GRADE_TIMED_OUT) {
        item->result = RAYO_GRADE_SKIPPED;
        return grade_say(item, err, "did not finish under valgrind within "
                                    "%g seconds",
                         ctx->options->timeout * SLOWDOWN);
    }
    status = grade_read_file(path, 1u << 24, &log, &size, err);
    if (status != RAYO_OK)
        return status;
    item->result = RAYO_GRADE_PASS;
    if (strstr(log, "ERROR SUMMARY") == NULL) {
        item->result = RAYO_GRADE_SKIPPED;
        status = grade_say(item, err, "valgrind did not run to the end; its "
                                      "log says:");
        if (status == RAYO_OK)
            status = grade_quote(item, log, 4, err);
        free(log);
        return status;
    }
    status = report_errors(item, log, &errors, err);
    if (status == RAYO_OK)
        status = report_leaks(item, log, &leaked, err);
    if (status == RAYO_OK && item->result == RAYO_GRADE_PASS)
        status = grade_say(item, err, "no invalid access and no leak");
    free(log);
    return status;
}

rayo_status grade_step_valgrind(grade_context *ctx, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_VALGRIND];
    char *valgrind = grade_which("valgrind");
    char *log = grade_path_join(ctx->dir, "valgrind.log");
    char *out = grade_path_join(ctx->dir, "valgrind.out");
    char *errpath = grade_path_join(ctx->dir, "valgrind.err");
    char *log_option = log != NULL ? grade_concat("--log-file=", log) : NULL;
    char *argv[7];
    grade_limits limits = grade_run_limits(ctx->options);
    grade_outcome outcome;
    rayo_status status = RAYO_OK;
    if (log == NULL || out == NULL || errpath == NULL || log_option == NULL)
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    else if (valgrind == NULL)
        status = grade_say(item, err, "valgrind is not installed");
    if (status != RAYO_OK || valgrind == NULL)
        goto done;
    argv[0] = valgrind;
    argv[1] = "--leak-check=full";
    argv[2] = "--show-leak-kinds=all";
    argv[3] = "--num-callers=12";
    argv[4] = log_option;
    argv[5] = ctx->program;
    argv[6] = NULL;
    limits.wall *= SLOWDOWN;
    limits.cpu *= SLOWDOWN;
    limits.memory = 0;
    status = grade_process_run(argv, NULL, ctx->dir, out, errpath, &limits, 0,
                               &outcome, err);
    if (status == RAYO_OK)
        status = read_log(ctx, log, &outcome, err);
done:
    free(valgrind);
    free(log);
    free(out);
    free(errpath);
    free(log_option);
    return status;
}
