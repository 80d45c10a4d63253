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
 * a pipe the grader reads while it runs (descriptor 3: no file the
 * program could replace or point at /dev/null) and this file reads the
 * log's words, not its exit status.  The program shares valgrind's
 * process and so can write into that pipe too, but a pipe cannot be
 * rewound or truncated: what valgrind wrote stays, and the log is read
 * so that added lines can only add findings (every error line counts,
 * the largest leak and error counts win).  Programs it executes run
 * under valgrind too (--trace-children=yes).  Skipped when valgrind is
 * not installed.
 *
 * Where the frame valgrind names is one of the constructors exercise 3's
 * statement gives (esfera_crear, luz_crear, arreglo_agregar), the
 * mistake is also said in the statement's terms: which destructor was
 * not called, or that arreglo_agregar writes past the end of v.  The
 * explanations go by the frame's function name, so they apply to any
 * exercise whose program has those functions (ej1's have none).
 */
#define _POSIX_C_SOURCE 200809L

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grade_impl.h"

#define SLOWDOWN 10.0
#define LOG_FD 3 /* valgrind's log, a pipe the grader reads */
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

/* The largest "KIND: N bytes in M blocks" anywhere in the log: a line
   the program forged into the log cannot hide a larger real one. */
static unsigned long long leak_bytes(const char *log, const char *kind,
                                     unsigned long long *blocks)
{
    const char *p = log;
    unsigned long long most = 0;
    size_t length = strlen(kind);
    *blocks = 0;
    while ((p = strstr(p, kind)) != NULL) {
        unsigned long long bytes, count = 0;
        const char *q;
        char number[64];
        size_t i, n = 0;
        p += length;
        if (*p != ':')
            continue;
        /* "   1,234 bytes in 5 blocks": valgrind groups digits with
           commas. */
        while (*p == ' ' || *p == ':')
            p++;
        for (i = 0; p[i] != '\0' && p[i] != ' ' && n + 1 < sizeof number;
             i++)
            if (p[i] != ',')
                number[n++] = p[i];
        number[n] = '\0';
        bytes = strtoull(number, NULL, 10);
        q = strstr(p, " in ");
        if (q != NULL && q - p < 40)
            count = strtoull(q + 4, NULL, 10);
        if (bytes > most) {
            most = bytes;
            *blocks = count;
        }
    }
    return most;
}

/* The largest count in an "ERROR SUMMARY: N errors" line; -1 when the
   log has none. */
static long long summary_errors(const char *log)
{
    const char *p = log;
    long long most = -1;
    while ((p = strstr(p, "ERROR SUMMARY: ")) != NULL) {
        long long n;
        p += strlen("ERROR SUMMARY: ");
        n = strtoll(p, NULL, 10);
        if (n > most)
            most = n;
    }
    return most;
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
        if (status == RAYO_OK && i == 2)
            status = grade_say(item, err, "possibly lost: at exit valgrind "
                                          "saw only a pointer into the "
                                          "middle of the memory, not to its "
                                          "start; a leak all the same");
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

static rayo_status read_log(grade_context *ctx, const grade_captured *got,
                            rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_VALGRIND];
    const grade_outcome *outcome = &got->outcome;
    const char *log = got->log != NULL ? got->log : "";
    unsigned errors;
    long long counted;
    int leaked;
    rayo_status status;
    if (outcome->ending == GRADE_TIMED_OUT) {
        item->result = RAYO_GRADE_SKIPPED;
        return grade_say(item, err, "did not finish under valgrind within "
                                    "%g seconds",
                         ctx->options->timeout * SLOWDOWN);
    }
    if (got->log_overflow)
        return grade_fail(item, err, "valgrind's log grew past 16 MiB, far "
                                     "more than valgrind writes: the "
                                     "program wrote into it");
    if (outcome->ending == GRADE_SIGNALED && outcome->status == SIGKILL)
        return grade_fail(item, err, "the program was killed (SIGKILL) "
                                     "under valgrind before valgrind could "
                                     "check it");
    item->result = RAYO_GRADE_PASS;
    counted = summary_errors(log);
    if (counted < 0) {
        item->result = RAYO_GRADE_SKIPPED;
        status = grade_say(item, err, "valgrind did not run to the end; its "
                                      "log says:");
        if (status == RAYO_OK)
            status = grade_quote(item, log, 4, err);
        return status;
    }
    status = report_errors(item, log, &errors, err);
    if (status == RAYO_OK)
        status = report_leaks(item, log, &leaked, err);
    /* Leaks count as errors in valgrind's summary. */
    if (status == RAYO_OK && errors == 0 && !leaked && counted > 0)
        status = grade_fail(item, err, "valgrind counted %lld errors",
                            counted);
    if (status == RAYO_OK && item->result == RAYO_GRADE_PASS)
        status = grade_say(item, err, "no invalid access and no leak");
    return status;
}

rayo_status grade_step_valgrind(grade_context *ctx, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_VALGRIND];
    char *valgrind = grade_which("valgrind");
    char log_option[32];
    char *argv[8];
    grade_limits limits = grade_run_limits(ctx->options);
    grade_run run;
    grade_captured got;
    rayo_status status = RAYO_OK;
    memset(&got, 0, sizeof got);
    if (valgrind == NULL)
        return grade_say(item, err, "valgrind is not installed");
    snprintf(log_option, sizeof log_option, "--log-fd=%d", LOG_FD);
    argv[0] = valgrind;
    argv[1] = "--leak-check=full";
    argv[2] = "--show-leak-kinds=all";
    argv[3] = "--num-callers=12";
    argv[4] = "--trace-children=yes";
    argv[5] = log_option;
    argv[6] = ctx->program;
    argv[7] = NULL;
    limits.wall *= SLOWDOWN;
    limits.cpu *= SLOWDOWN;
    limits.memory = 0;
    /* memcheck keeps a shadow of the program's memory and its own
       tables: the tree gets twice the program's memory. */
    limits.tree_memory *= 2;
    memset(&run, 0, sizeof run);
    run.argv = argv;
    run.role = GRADE_ROLE_STUDENT;
    run.program = ctx->program;
    run.out_limit = 1u << 20;
    run.log_fd = LOG_FD;
    status = grade_spawn(ctx, &run, &limits, &got, err);
    if (status == RAYO_OK && got.memory_exceeded &&
        got.outcome.ending != GRADE_TIMED_OUT)
        status = grade_fail(item, err, "memory limit exceeded under "
                                       "valgrind: valgrind and the program "
                                       "together used more than %llu MiB",
                            (unsigned long long)(limits.tree_memory >> 20));
    else if (status == RAYO_OK)
        status = read_log(ctx, &got, err);
    grade_captured_free(&got);
    free(valgrind);
    return status;
}
