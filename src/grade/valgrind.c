/*
 * valgrind.c - the last criterion: the program runs clean under
 * valgrind's memcheck: no invalid read, write or free, no use of
 * uninitialised memory, no leak (definitely, indirectly or possibly
 * lost).  Memory still reachable at exit is a warning: the course's
 * "pasa Valgrind" is about errors and lost blocks.
 *
 * Not where the program is run (run/) nor where the log's bytes are
 * split into lines (valgrind_log.c): this file says what the lines
 * mean.  How the program runs again, how far the log is trusted, and
 * the statement's terms for a frame are said after the includes.
 */
#define _POSIX_C_SOURCE 200809L

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "functions/table.h"
#include "grade_impl.h"
#include "valgrind_log.h"

/*
 * The program runs again, under the same limits except address space
 * (valgrind reserves far more than the program uses) and with ten times
 * the time (memcheck is that much slower); memcheck writes its log into
 * a socket the grader reads while it runs, at a descriptor in the range
 * valgrind keeps out of the program's reach (run/process.c), and this file
 * reads the log's lines as bytes (valgrind_log.c), not its exit status.
 * The log is read as if the program could still write into it: every
 * error line counts and the largest leak and error counts win, so added
 * lines can only add findings, and any sign of such a write, or of
 * valgrind's framing in the program's own output, is a finding of its
 * own.  Programs it executes run under valgrind too
 * (--trace-children=yes).  Skipped when valgrind is not installed.
 *
 * Where the frame valgrind names is a function an exercise's functions
 * table lists as an owner (functions/table.h: exercise 3's esfera_crear,
 * luz_crear, arreglo_agregar), the mistake is also said in the
 * statement's terms: which destructor was not called, or that
 * arreglo_agregar writes past the end of v.  By the frame's function
 * name, whichever exercise is graded.
 */

#define SLOWDOWN 10.0
#define SHOWN_ERRORS 4

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

/* The log, as bytes. */
typedef struct vg_text {
    const char *data;
    size_t size;
} vg_text;

/* The first stack frame in the lines after *pos that is not inside
   valgrind's own replacements (malloc, free, ...): "main (leak.c:20)". */
static void first_frame(const vg_text *log, size_t pos, char *out,
                        size_t room)
{
    int lines = 0;
    vg_line line;
    out[0] = '\0';
    while (lines++ < 12 && vg_next_line(log->data, log->size, &pos, &line)) {
        const char *colon;
        if (!vg_begins(&line, "at 0x") && !vg_begins(&line, "by 0x"))
            break;
        if (vg_find(&line, "vg_replace") != NULL ||
            vg_find(&line, "vgpreload") != NULL)
            continue;
        colon = vg_find(&line, ": ");
        if (colon != NULL)
            vg_copy(colon + 2,
                    line.body_length - (size_t)(colon + 2 - line.body), out,
                    room);
        else
            vg_copy(line.body, line.body_length, out, room);
        return;
    }
}

/* A number as valgrind writes it, digits grouped with commas; saturated. */
static unsigned long long number_at(const char *p, const char *end,
                                    const char **after)
{
    unsigned long long n = 0;
    while (p < end && ((*p >= '0' && *p <= '9') || *p == ',')) {
        if (*p != ',' && n < 1000000000000000000ull)
            n = n * 10 + (unsigned long long)(*p - '0');
        p++;
    }
    *after = p;
    return n;
}

/* The largest "KIND: N bytes in M blocks" in the log: a line the
   program forged into the log cannot hide a larger real one. */
static unsigned long long leak_bytes(const vg_text *log, const char *kind,
                                     unsigned long long *blocks)
{
    size_t pos = 0, length = strlen(kind);
    unsigned long long most = 0;
    vg_line line;
    *blocks = 0;
    while (vg_next_line(log->data, log->size, &pos, &line)) {
        const char *p, *end = line.body + line.body_length;
        unsigned long long bytes, count = 0;
        if (!vg_begins(&line, kind) || line.body_length == length ||
            line.body[length] != ':')
            continue;
        p = line.body + length;
        while (p < end && (*p == ' ' || *p == ':'))
            p++;
        bytes = number_at(p, end, &p);
        if ((size_t)(end - p) > 10 && memcmp(p, " bytes in ", 10) == 0)
            count = number_at(p + 10, end, &p);
        if (bytes > most) {
            most = bytes;
            *blocks = count;
        }
    }
    return most;
}

/* The largest count in an "ERROR SUMMARY: N errors" line; -1 when the
   log has none. */
static long long summary_errors(const vg_text *log)
{
    size_t pos = 0;
    long long most = -1;
    vg_line line;
    while (vg_next_line(log->data, log->size, &pos, &line)) {
        const char *p;
        long long n;
        if (!vg_begins(&line, "ERROR SUMMARY: "))
            continue;
        p = line.body + strlen("ERROR SUMMARY: ");
        n = (long long)number_at(p, line.body + line.body_length, &p);
        if (n > most)
            most = n;
    }
    return most;
}

static rayo_status report_errors(rayo_grade_item *item, const vg_text *log,
                                 unsigned *count, rayo_error *err)
{
    size_t pos = 0;
    rayo_status status = RAYO_OK;
    vg_line line;
    *count = 0;
    while (status == RAYO_OK &&
           vg_next_line(log->data, log->size, &pos, &line)) {
        size_t k;
        if (line.pid < 0)
            continue;
        for (k = 0; k < ERROR_KINDS; k++) {
            char text[512], frame[512];
            const functions_owner *owner;
            size_t o;
            if (!vg_begins(&line, error_kinds[k]))
                continue;
            if ((*count)++ >= SHOWN_ERRORS)
                break;
            vg_copy(line.body, line.body_length, text, sizeof text);
            first_frame(log, pos, frame, sizeof frame);
            if (frame[0] != '\0')
                status = grade_fail(item, err, "%s, at %s", text, frame);
            else
                status = grade_fail(item, err, "%s", text);
            for (o = 0; (owner = functions_owner_at(o)) != NULL &&
                        status == RAYO_OK;
                 o++)
                if (owner->write && frame_is(frame, owner->function) &&
                    strncmp(text, "Invalid write", 13) == 0)
                    status = grade_say(item, err, "%s", owner->explanation);
            break;
        }
    }
    if (status == RAYO_OK && *count > SHOWN_ERRORS)
        status = grade_say(item, err, "... and %u more errors",
                           *count - SHOWN_ERRORS);
    return status;
}

/* For each lost block made by one of the exercises' owners, once, what
   was not destroyed or freed. */
static rayo_status explain_constructor_leaks(rayo_grade_item *item,
                                             const vg_text *log,
                                             rayo_error *err)
{
    int said[3 * FUNCTIONS_MAX] = {0};
    size_t pos = 0;
    rayo_status status = RAYO_OK;
    vg_line line;
    while (status == RAYO_OK &&
           vg_next_line(log->data, log->size, &pos, &line)) {
        char frame[512];
        const functions_owner *owner;
        size_t k;
        if (vg_find(&line, " lost in loss record") == NULL)
            continue;
        first_frame(log, pos, frame, sizeof frame);
        for (k = 0; (owner = functions_owner_at(k)) != NULL &&
                    k < sizeof said / sizeof said[0] && status == RAYO_OK;
             k++) {
            if (said[k] || owner->write || !frame_is(frame, owner->function))
                continue;
            said[k] = 1;
            status = grade_say(item, err, "%s", owner->explanation);
        }
    }
    return status;
}

/* The position just after the first line that holds word; 0 when none
   does (a record's line is never the log's first). */
static size_t after_line_with(const vg_text *log, const char *word)
{
    size_t pos = 0;
    vg_line line;
    while (vg_next_line(log->data, log->size, &pos, &line))
        if (vg_find(&line, word) != NULL)
            return pos;
    return 0;
}

static rayo_status report_leaks(rayo_grade_item *item, const vg_text *log,
                                int *leaked, rayo_error *err)
{
    static const char *const kinds[] = {"definitely lost", "indirectly lost",
                                        "possibly lost"};
    unsigned long long blocks, bytes;
    char frame[512];
    size_t i, record;
    rayo_status status = RAYO_OK;
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
    record = after_line_with(log, "are definitely lost in loss record");
    if (record == 0)
        record = after_line_with(log, "lost in loss record");
    if (status == RAYO_OK && *leaked && record != 0) {
        first_frame(log, record, frame, sizeof frame);
        if (frame[0] != '\0')
            status = grade_say(item, err, "the biggest leak was allocated "
                                          "in %s",
                               frame);
        if (status == RAYO_OK)
            status = explain_constructor_leaks(item, log, err);
    }
    bytes = leak_bytes(log, "still reachable", &blocks);
    if (status == RAYO_OK && bytes > 0)
        status = grade_warn(item, err, "warning: %llu bytes in %llu blocks "
                                      "still reachable at exit (a file "
                                      "not closed, memory not freed before "
                                      "returning from main)",
                           bytes, blocks);
    return status;
}

/* The log's lines from byte at on, NUL bytes as spaces, for a quote. */
static rayo_status quote_log(rayo_grade_item *item, const vg_text *log,
                             size_t at, size_t lines, rayo_error *err)
{
    char text[4096];
    vg_copy(log->data + at, log->size - at, text, sizeof text);
    return grade_quote(item, text, lines, err);
}

/* What the program wrote where only valgrind writes: each a finding of
   its own, after valgrind's, so that the real errors come first. */
static rayo_status report_forgery(grade_context *ctx,
                                  const grade_captured *got,
                                  const vg_text *log, int log_fd,
                                  rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_VALGRIND];
    rayo_status status = RAYO_OK;
    vg_signs signs;
    vg_check(log->data, log->size, log_fd, &signs);
    if (signs.touched_fd >= 0)
        status = grade_fail(item, err, "the program wrote into the "
                                       "grader's channel: it tried to write "
                                       "to descriptor %d, where valgrind "
                                       "keeps its log, and valgrind "
                                       "refused",
                            signs.touched_fd);
    if (status == RAYO_OK && (signs.nul || signs.unframed || signs.duplicate))
        status = grade_fail(item, err, "the program wrote into the "
                                       "grader's channel: valgrind's log "
                                       "holds what valgrind does not write "
                                       "(a NUL byte, a line without its "
                                       "==PID== frame or a second error "
                                       "summary from one process)");
    if (status == RAYO_OK && (vg_framed_text(got->out, got->out_size) ||
                              vg_framed_text(got->errors, got->errors_size)))
        status = grade_fail(item, err, "the program wrote into the "
                                       "grader's channel: it printed lines "
                                       "framed like valgrind's log "
                                       "(==PID== ...) on its standard "
                                       "output or error; they were not "
                                       "taken for valgrind's");
    return status;
}

static rayo_status read_log(grade_context *ctx, const grade_captured *got,
                            int log_fd, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_VALGRIND];
    const grade_outcome *outcome = &got->outcome;
    vg_text log;
    vg_signs signs;
    unsigned errors;
    long long counted;
    int leaked;
    rayo_status status;
    log.data = got->log != NULL ? got->log : "";
    log.size = got->log != NULL ? got->log_size : 0;
    if (outcome->ending == GRADE_TIMED_OUT) {
        item->result = RAYO_GRADE_SKIPPED;
        return grade_say(item, err, "did not finish under valgrind within "
                                    "%g seconds",
                         ctx->options->timeout * SLOWDOWN);
    }
    if (got->log_overflow)
        return grade_fail(item, err, "valgrind's log grew past 16 MiB, far "
                                     "more than valgrind writes for one "
                                     "program; the rest was not read");
    if (outcome->ending == GRADE_SIGNALED && outcome->status == SIGKILL)
        return grade_fail(item, err, "the program was killed (SIGKILL) "
                                     "under valgrind before valgrind could "
                                     "check it");
    item->result = RAYO_GRADE_PASS;
    counted = summary_errors(&log);
    vg_check(log.data, log.size, log_fd, &signs);
    if (counted < 0 && signs.panic) {
        status = grade_fail(item, err, "valgrind stopped on an internal "
                                       "error while it ran the program, "
                                       "which was not checked (a program "
                                       "that writes into valgrind's own "
                                       "descriptors, by their /proc/self/fd "
                                       "names, does that); valgrind says:");
        if (status == RAYO_OK)
            status = quote_log(item, &log, signs.panic_at, 2, err);
        if (status == RAYO_OK)
            status = report_forgery(ctx, got, &log, log_fd, err);
        return status;
    }
    if (counted < 0) {
        item->result = RAYO_GRADE_SKIPPED;
        status = grade_say(item, err, "valgrind did not run to the end; its "
                                      "log says:");
        if (status == RAYO_OK)
            status = quote_log(item, &log, 0, 4, err);
        return status;
    }
    status = report_errors(item, &log, &errors, err);
    if (status == RAYO_OK)
        status = report_leaks(item, &log, &leaked, err);
    /* Leaks count as errors in valgrind's summary. */
    if (status == RAYO_OK && errors == 0 && !leaked && counted > 0)
        status = grade_fail(item, err, "valgrind counted %lld errors",
                            counted);
    if (status == RAYO_OK)
        status = report_forgery(ctx, got, &log, log_fd, err);
    if (status == RAYO_OK && item->result == RAYO_GRADE_PASS)
        status = grade_say(item, err, "no invalid access and no leak");
    return status;
}

rayo_status grade_step_valgrind(grade_context *ctx, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_VALGRIND];
    char *valgrind = grade_which("valgrind");
    int log_fd = grade_log_fd();
    char log_option[32];
    char *argv[8 + GRADE_ARGS];
    size_t a;
    grade_limits limits = grade_run_limits(ctx->options);
    grade_run run;
    grade_captured got;
    rayo_status status = RAYO_OK;
    memset(&got, 0, sizeof got);
    if (valgrind == NULL)
        return grade_say(item, err, "valgrind is not installed");
    if (log_fd < 0) {
        free(valgrind);
        return grade_say(item, err, "not run: the limit on open files is "
                                    "too low to give valgrind a log of its "
                                    "own");
    }
    snprintf(log_option, sizeof log_option, "--log-fd=%d", log_fd);
    argv[0] = valgrind;
    argv[1] = "--leak-check=full";
    argv[2] = "--show-leak-kinds=all";
    argv[3] = "--num-callers=12";
    argv[4] = "--trace-children=yes";
    argv[5] = log_option;
    argv[6] = ctx->program;
    for (a = 0; ctx->args != NULL && a < GRADE_ARGS && ctx->args[a] != NULL;
         a++)
        argv[7 + a] = ctx->args[a];
    argv[7 + a] = NULL;
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
    run.log_fd = log_fd;
    status = grade_spawn(ctx, &run, &limits, &got, err);
    if (status == RAYO_OK && got.memory_exceeded &&
        got.outcome.ending != GRADE_TIMED_OUT)
        status = grade_fail(item, err, "memory limit exceeded under "
                                       "valgrind: valgrind and the program "
                                       "together used more than %llu MiB",
                            (unsigned long long)(limits.tree_memory >> 20));
    else if (status == RAYO_OK)
        status = read_log(ctx, &got, log_fd, err);
    grade_captured_free(&got);
    free(valgrind);
    return status;
}
