/*
 * rayo_harness.h - what every functions harness (ej1.c, ej2.c, ej3.c
 * here) shares: the channel and the reading of its calls.  The grader
 * writes on the harness's standard input a per-run nonce, then one
 * record a line: "m NAME" (say "missing NAME" when the function is
 * absent), "c NAME K NUMBERS..." (call NAME as case K on the numbers),
 * "u NAME" (NAME's signature is the statement's).  All of it is read
 * from .preinit_array, before any of the student's code runs, and
 * standard input is closed.  Each protocol line is said by rayo_say,
 * framed by the nonce.  A harness defines rayo_present and rayo_call;
 * this file gives main.  Compiled with the student's objects by the
 * grader, and by `make check` with a right program of tests/grade/.
 */
#ifndef RAYO_HARNESS_H
#define RAYO_HARNESS_H

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define RAYO_INPUT (1 << 16)

static char rayo_nonce[34];
static char rayo_input[RAYO_INPUT];
static size_t rayo_at, rayo_end;
static int rayo_read_done;

static void rayo_read_input(void)
{
    size_t n = 0;
    if (rayo_read_done)
        return;
    rayo_read_done = 1;
    while (n < sizeof rayo_nonce - 1) {
        ssize_t r = read(0, rayo_nonce + n, 1);
        if (r <= 0 || rayo_nonce[n] == '\n')
            break;
        n++;
    }
    rayo_nonce[n] = 0;
    while (rayo_end < RAYO_INPUT - 1) {
        ssize_t r = read(0, rayo_input + rayo_end, RAYO_INPUT - 1 - rayo_end);
        if (r <= 0)
            break;
        rayo_end += (size_t)r;
    }
    rayo_input[rayo_end] = 0;
    close(0);
}

__attribute__((used, section(".preinit_array")))
static void (*const rayo_preinit)(void) = rayo_read_input;

static void rayo_say(const char *format, ...)
{
    va_list args;
    rayo_read_input(); /* if .preinit_array did not run */
    printf("\n%s ", rayo_nonce);
    va_start(args, format);
    vprintf(format, args);
    va_end(args);
    printf("\n");
    fflush(stdout);
}

/* The record being read, and the place of its next number. */
static char rayo_line[16384];
static size_t rayo_at_line;

/* The next number of the current record (0 when there is none). */
static double rayo_number(void)
{
    char *end;
    double v = strtod(rayo_line + rayo_at_line, &end);
    if (end == rayo_line + rayo_at_line)
        return 0;
    rayo_at_line = (size_t)(end - rayo_line);
    return v;
}

__attribute__((unused)) static float rayo_float(void)
{
    return (float)rayo_number();
}

/* The names whose signature is the statement's ("u NAME"). */
static char rayo_usable_names[1024];

__attribute__((unused)) static int rayo_usable(const char *name)
{
    const char *p = rayo_usable_names;
    size_t n = strlen(name);
    while ((p = strstr(p, name)) != NULL) {
        if ((p == rayo_usable_names || p[-1] == ' ') && p[n] == ' ')
            return 1;
        p += n;
    }
    return 0;
}

/* Each harness's own: whether the function called name is linked in,
   and one call of it, case k, on the record's numbers. */
static int rayo_present(const char *name);
static void rayo_call(const char *name, unsigned k);

int main(void)
{
    rayo_read_input();
    while (rayo_at < rayo_end) {
        size_t n = strcspn(rayo_input + rayo_at, "\n");
        char kind = 0, name[64] = "";
        int used = 0;
        if (n >= sizeof rayo_line)
            n = sizeof rayo_line - 1;
        memcpy(rayo_line, rayo_input + rayo_at, n);
        rayo_line[n] = 0;
        rayo_at += strcspn(rayo_input + rayo_at, "\n");
        rayo_at += rayo_input[rayo_at] == '\n';
        if (sscanf(rayo_line, " %c %63s%n", &kind, name, &used) < 2)
            continue;
        rayo_at_line = (size_t)used;
        if (kind == 'u' && strlen(rayo_usable_names) + strlen(name) + 2 <
                               sizeof rayo_usable_names) {
            strcat(rayo_usable_names, name);
            strcat(rayo_usable_names, " ");
        } else if (kind == 'm' && !rayo_present(name)) {
            rayo_say("missing %s", name);
        } else if (kind == 'c' && rayo_present(name)) {
            unsigned k = (unsigned)rayo_number();
            rayo_say("call %s %u", name, k);
            fflush(stdout);
            rayo_call(name, k);
        }
    }
    rayo_say("done");
    return 0;
}

#endif
