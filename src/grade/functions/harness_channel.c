/*
 * harness_channel.c - the channel the functions' harness reports
 * through (harness.h): a per-run nonce from the system's random source,
 * given to the harness on its standard input with its calls (the
 * harness, harness/rayo_harness.h, reads both before any of the
 * student's code runs and frames each protocol line with it); and the
 * reading of what came back, where a line that poses as the harness's
 * results is dropped and becomes the finding "the program wrote into the
 * grader's channel".
 *
 * Not a sandbox: the student's code shares the harness's process, and
 * code that reads the process's memory or replaces C library functions
 * could still learn the nonce (docs/grading.md says what holds).
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/random.h>
#endif

#include "rayo/lang.h"

#include "harness.h"

#define LOG_LIMIT (1u << 20)
/* What the harness is given on its standard input, at most: less than
   a pipe's buffer, and what harness/rayo_harness.h reads. */
#define INPUT_LIMIT 60000

/* A per-run secret: 32 hexadecimal digits from the system's random
   source (getrandom, else /dev/urandom). */
static int make_nonce(char *out)
{
    static const char hex[] = "0123456789abcdef";
    unsigned char bytes[HARNESS_NONCE / 2];
    size_t got = 0, i;
#ifdef __linux__
    while (got < sizeof bytes) {
        ssize_t n = getrandom(bytes + got, sizeof bytes - got, 0);
        if (n <= 0)
            break;
        got += (size_t)n;
    }
#endif
    if (got < sizeof bytes) {
        int fd = open("/dev/urandom", O_RDONLY | O_CLOEXEC);
        got = 0;
        while (fd >= 0 && got < sizeof bytes) {
            ssize_t n = read(fd, bytes + got, sizeof bytes - got);
            if (n <= 0)
                break;
            got += (size_t)n;
        }
        if (fd >= 0)
            close(fd);
    }
    if (got < sizeof bytes)
        return -1;
    for (i = 0; i < sizeof bytes; i++) {
        out[2 * i] = hex[bytes[i] >> 4];
        out[2 * i + 1] = hex[bytes[i] & 15];
    }
    out[HARNESS_NONCE] = '\0';
    return 0;
}

/* The offset of the line of out (kept bytes) that begins with key, or
   -1. */
static long line_starting(const char *out, size_t kept, const char *key,
                          size_t n)
{
    size_t at = 0;
    while (at + n <= kept) {
        const char *nl;
        if (memcmp(out + at, key, n) == 0)
            return (long)at;
        nl = memchr(out + at, '\n', kept - at);
        if (nl == NULL)
            break;
        at = (size_t)(nl - out) + 1;
    }
    return -1;
}

/* The log as the judges read it, from what the harness printed: each
   line framed by the nonce without it (of each "result NAME K" only the
   last), and the other lines (the student's own output) as they were,
   except those that pose as the harness's results, which are dropped
   and counted in *forged (the first kept, cleaned, in first); a second
   framed result of one case counts too.  *done: the harness reached
   the end of its main. */
static char *read_channel(const char *raw, const char *nonce,
                          unsigned *forged, char *first, size_t room,
                          int *done)
{
    size_t n = strlen(nonce), kept = 0;
    char *out = malloc(strlen(raw) + 1);
    const char *p = raw;
    *forged = 0;
    *done = 0;
    first[0] = '\0';
    if (out == NULL)
        return NULL;
    while (*p != '\0') {
        size_t line = strcspn(p, "\n");
        const char *next = p + line + (p[line] == '\n');
        const char *body = p;
        size_t hexes = strspn(p, "0123456789abcdefABCDEF"), length;
        int framed = line > n && strncmp(p, nonce, n) == 0 && p[n] == ' ';
        if (framed)
            body = p + n + 1;
        else if (hexes >= 8 && p[hexes] == ' ')
            body = p + hexes + 1; /* another nonce, or a guess */
        length = line - (size_t)(body - p);
        if (!framed && (strncmp(body, "call ", 5) == 0 ||
                        strncmp(body, "missing ", 8) == 0 ||
                        strncmp(body, "out ", 4) == 0 ||
                        strncmp(body, "end ", 4) == 0)) {
            ; /* the other protocol words: dropped, they decide nothing */
        } else if (!framed && strncmp(body, "result ", 7) != 0) {
            memcpy(out + kept, p, (size_t)(next - p)); /* the student's */
            kept += (size_t)(next - p);
        } else if (!framed) {
            if ((*forged)++ == 0)
                harness_clean(p, line, first, room);
        } else if (length == 4 && strncmp(body, "done", 4) == 0) {
            *done = 1;
        } else {
            if (strncmp(body, "result ", 7) == 0) {
                /* "result NAME K ": the key of a case. */
                const char *end = body + 7 + strcspn(body + 7, " \n");
                long seen;
                if (*end == ' ')
                    end += 1 + strcspn(end + 1, " \n");
                seen = line_starting(out, kept, body,
                                     (size_t)(end - body) + 1);
                if (seen >= 0) {
                    size_t at = (size_t)seen;
                    size_t old = strcspn(out + at, "\n") + 1;
                    if ((*forged)++ == 0)
                        harness_clean(p, line, first, room);
                    memmove(out + at, out + at + old, kept - at - old);
                    kept -= old;
                }
            }
            memcpy(out + kept, body, length);
            kept += length;
            out[kept++] = '\n';
        }
        p = next;
    }
    out[kept] = '\0';
    return out;
}

rayo_status harness_run(grade_context *ctx, const char *calls, char **log,
                        grade_outcome *outcome, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_FUNCTIONS];
    char *argv[2], nonce[HARNESS_NONCE + 2], first[200];
    grade_limits limits = grade_run_limits(ctx->options);
    grade_run run;
    grade_captured got;
    int input[2] = {-1, -1}, done = 0;
    unsigned forged = 0;
    rayo_status status = RAYO_OK;
    *log = NULL;
    memset(&got, 0, sizeof got);
    argv[0] = grade_path_join(ctx->dir, "harness");
    argv[1] = NULL;
    memset(&run, 0, sizeof run);
    run.argv = argv;
    run.role = GRADE_ROLE_STUDENT;
    run.program = argv[0];
    run.out_limit = LOG_LIMIT;
    if (argv[0] == NULL)
        status = rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    else if (make_nonce(nonce) != 0)
        status = rayo_error_set(err, RAYO_ERR_IO, "grade: cannot read the "
                                                  "system's random source");
    else if (pipe(input) != 0)
        status = rayo_error_set(err, RAYO_ERR_IO, "grade: pipe: %s",
                                strerror(errno));
    if (status == RAYO_OK && HARNESS_NONCE + 1 + strlen(calls) > INPUT_LIMIT)
        status = rayo_error_set(err, RAYO_ERR_INVALID, "grade: the harness's "
                                "calls do not fit in its input");
    if (status == RAYO_OK) {
        /* The nonce, its newline and the calls fit in a pipe's buffer:
           written whole before the harness starts, read by it before
           any of the student's code runs. */
        size_t n = strlen(calls);
        fcntl(input[0], F_SETFD, FD_CLOEXEC);
        fcntl(input[1], F_SETFD, FD_CLOEXEC);
        strcat(nonce, "\n");
        if (write(input[1], nonce, HARNESS_NONCE + 1) !=
                HARNESS_NONCE + 1 ||
            write(input[1], calls, n) != (ssize_t)n)
            status = rayo_error_set(err, RAYO_ERR_IO, "grade: pipe: %s",
                                    strerror(errno));
        nonce[HARNESS_NONCE] = '\0';
        close(input[1]);
        run.input = input[0];
    }
    if (status == RAYO_OK)
        status = grade_spawn(ctx, &run, &limits, &got, err);
    if (input[0] >= 0)
        close(input[0]);
    if (status == RAYO_OK) {
        *outcome = got.outcome;
        *log = read_channel(got.out != NULL ? got.out : "", nonce, &forged,
                            first, sizeof first, &done);
        if (*log == NULL)
            status = rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    }
    /* exit(0) inside a student's function ends the harness with status
       0 before its calls are done: an ending of its own. */
    if (status == RAYO_OK && !done && outcome->ending == GRADE_EXITED &&
        outcome->status == 0)
        outcome->status = HARNESS_EXITED_EARLY;
    if (status == RAYO_OK && forged > 0)
        status = grade_fail(
            item, err,
            rayo_ngettext(rayo_error_lang(err),
                          "the program wrote into the grader's channel: %u "
                          "line posing as the harness's results (the "
                          "first: \"%s\"); a function's results come from "
                          "what it returns, never from what it prints",
                          "the program wrote into the grader's channel: %u "
                          "lines posing as the harness's results (the "
                          "first: \"%s\"); a function's results come from "
                          "what it returns, never from what it prints",
                          forged),
            forged, first);
    grade_captured_free(&got);
    free(argv[0]);
    return status;
}
