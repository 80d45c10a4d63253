/*
 * harness.h - the machinery of the functions engine (engine.c): a
 * growing text, the (trusted) compiler, probes of a student's file
 * against prototypes, building a harness (harness/) around the
 * student's objects, running it and reading its log.  The protocol:
 * the harness says "call NAME K" before each call and "result NAME K
 * V1 V2 ..." after it, "missing NAME" for an absent function and
 * "done" at the end, each line framed by a per-run nonce it reads from
 * standard input before any of the student's code runs; a result line
 * without it, or a second result of one case, is the finding "the
 * program wrote into the grader's channel".  Private to src/grade.
 */
#ifndef RAYO_GRADE_HARNESS_H
#define RAYO_GRADE_HARNESS_H

#include <stddef.h>

#include "../grade_impl.h"

#define HARNESS_REASON 400 /* room for one probe's reason */
#define HARNESS_NONCE 32   /* hexadecimal digits of the channel's nonce */
/* grade_outcome.status of a harness that exited with status 0 before
   saying "done" (exit(0) in a student's function): not an exit status. */
#define HARNESS_EXITED_EARLY 256

/* A growing string; failed is set once memory runs out. */
typedef struct harness_text {
    char *data;
    size_t length, capacity;
    int failed;
} harness_text;

void harness_append(harness_text *t, const char *format, ...)
    GRADE_PRINTF(2, 3);

/* " %.9g" for each of v[0..n-1]: numbers of a harness record, each
   read back as the float it was. */
void harness_numbers(harness_text *t, const double *v, size_t n);

/* The record "c NAME K" of a call on three vectors and a scalar, the
   shape EJ2's and EJ3's value cases share. */
void harness_vector_record(harness_text *t, const char *name, unsigned k,
                           const double *a, const double *b,
                           const double *c, double s);

/* Runs the compiler words (its own first) in the current directory: ok
   when it exits 0; its standard error in *errors (allocated). */
rayo_status harness_cc(grade_context *ctx, const char *const *words,
                       size_t count, int *ok, char **errors,
                       rayo_error *err);

/* The compiler's first "error: " message, without the file position,
   one line, control bytes escaped. */
void harness_first_error(const char *errors, char *out, size_t room);

/* Checks source i: before, then #include "the source", then after, with
   -fsyntax-only.  ok when it compiles; else the first error in reason. */
rayo_status harness_probe(grade_context *ctx, size_t i, const char *before,
                          const char *after, int *ok, char *reason,
                          size_t room, rayo_error *err);

/* The same, and the compiler's messages in *messages (allocated). */
rayo_status harness_probe_full(grade_context *ctx, size_t i,
                               const char *before, const char *after,
                               int *ok, char *reason, size_t room,
                               char **messages, rayo_error *err);

/* From the messages of a probe that redeclared name: the type of the
   student's own definition, as the compiler's note "previous definition
   of NAME with type TYPE" gives it (gcc); "" when there is none. */
void harness_previous_type(const char *errors, const char *name, char *out,
                           size_t room);

/* Compiles each source with main renamed to rayo_student_main, then
   the harness (its source's size bytes, with harness/rayo_harness.h
   beside it) with them into ctx->dir/harness, with the extra link words
   (e.g. -Wl,--wrap=realloc) before -lm.  ok when both worked; else the
   compiler's messages in *errors. */
rayo_status harness_build(grade_context *ctx, const unsigned char *source,
                          size_t size, const char *const *extra,
                          size_t extra_count, int *ok, char **errors,
                          rayo_error *err);

/* Runs the harness under the program's limits with a fresh nonce and
   then its calls (records, harness/rayo_harness.h) on its standard
   input: in *log (allocated, NUL-terminated) the protocol lines
   it said, unframed (of each case the last result), and the student's
   own output; how it ended in *outcome (HARNESS_EXITED_EARLY when it
   exited 0 before "done").  Lines posing as the harness's fail the
   criterion with the channel finding. */
rayo_status harness_run(grade_context *ctx, const char *calls, char **log,
                        grade_outcome *outcome, rayo_error *err);

/* 1 when the log has "missing NAME". */
int harness_missing(const char *log, const char *name);

/* The numbers after "result NAME K ": how many were read (at most max),
   -1 when there is no such line (the run ended before). */
int harness_result(const char *log, const char *name, unsigned k,
                   double *values, int max);

/* The rest of the line "result NAME K ..." (into out), 0 when none. */
int harness_result_text(const char *log, const char *name, unsigned k,
                        char *out, size_t room);

/* What a call looks like to a student, in lang: "norma(0.5, 0.5, 0.5)". */
typedef void (*harness_describe)(const char *name, unsigned k, rayo_lang lang,
                                 char *out, size_t room);

/* When the harness did not end with exit status 0: one reason naming the
   last call announced (described by describe) and how it ended. */
rayo_status harness_judge_ending(grade_context *ctx, const char *log,
                                 const grade_outcome *outcome,
                                 harness_describe describe, rayo_error *err);

/* The likely causes of a NaN a function returns, by kind of function. */
#define HARNESS_NAN_ARITHMETIC "0/0 or the square root of a negative number"
#define HARNESS_NAN_DISCRIMINANT                                            \
    "the square root of a negative discriminant (delta < 0: the ray "       \
    "misses; test it before taking the root) or 0/0"
#define HARNESS_NAN_NORMAL                                                  \
    "a vector of length 0 divided by its length (0/0)"
#define HARNESS_NAN_SHADING                                                 \
    "0/0, the square root of a negative discriminant or a normal of "      \
    "length 0"
#define HARNESS_INT_MIN -2147483648.0

/* When one of v[0..n-1] (n 1: a number, 3: a vector or colour) is NaN
   or infinite: the whole reason line for call in out ("... returned nan
   (not a number): likely CAUSE"), nan_cause for a NaN and inf_cause
   for an infinity (a whole clause; NULL: "likely a division by 0"),
   and 1; else 0. */
int harness_not_finite(const char *call, const double *v, size_t n,
                       const char *nan_cause, const char *inf_cause,
                       char *out, size_t room);

/* Cuts text (in place) to at most max bytes when it is longer: at a
   space, never inside a word, a UTF-8 sequence or an open quote, and
   " ..." after it. */
void harness_shorten(char *text, size_t max);

/* Escapes control bytes and bounds the length: for untrusted text. */
void harness_clean(const char *in, size_t length, char *out, size_t room);

#endif
