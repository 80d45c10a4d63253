/*
 * table.h - an exercise's functions criterion as a table, and the one
 * engine that runs it (engine.c): probe the signatures, build the
 * harness (harness/ejN.c, embedded in the library) around the
 * student's objects, write it its calls, run it, judge each function,
 * say how the run ended.  An exercise (ej1.c, ej2.c, ej3.c) gives its
 * functions and prototypes, the harness it is called through and its
 * link words, its calls and their expected values, its own judging
 * and, for valgrind, the functions whose blocks mean something.
 * Private to src/grade; docs/architecture.md says how to add one.
 */
#ifndef RAYO_GRADE_FUNCTIONS_TABLE_H
#define RAYO_GRADE_FUNCTIONS_TABLE_H

#include <stddef.h>

#include "harness.h"

#define FUNCTIONS_MAX 16 /* functions of one exercise, at most */

/* A function the statement asks for, as it writes its prototype. */
typedef struct functions_function {
    const char *name;
    const char *prototype;
} functions_function;

/* A function whose blocks valgrind may name, and what that means: a
   leak of what it made, or (write) a write past what it allocated. */
typedef struct functions_owner {
    const char *function;
    int write;
    const char *explanation;
} functions_owner;

typedef struct functions_exercise {
    const functions_function *functions;
    size_t count;
    /* The harness (harness/ejN.c as embedded) and its link words. */
    const unsigned char *harness;
    const size_t *harness_size;
    const char *const *link;
    size_t link_count;
    /* The engine's probe: probe_before and every prototype, then the
       #include of the student's file; one probe for all, one each when
       that fails.  assignment: its findings say "the assignment's"
       (ej1's wording), else "the statement's". */
    const char *probe_before;
    int assignment;
    /* Or the exercise's own probe (ej3's types), which says its own
       findings and sets usable[f] for the functions to call. */
    rayo_status (*probe)(grade_context *ctx, int *usable, rayo_error *err);
    /* The harness's call records for the usable functions
       (rayo_harness.h); the engine writes their "u" and "m" first. */
    void (*write_calls)(harness_text *t, const int *usable);
    /* Judges function f, usable, from the log. */
    rayo_status (*judge)(grade_context *ctx, unsigned f, const char *log,
                         const int *usable, rayo_error *err);
    harness_describe describe;
    const functions_owner *owners;
    size_t owner_count;
} functions_exercise;

extern const functions_exercise functions_ej1, functions_ej2, functions_ej3;

/* The k-th owner of all the exercises' tables, NULL past the last:
   valgrind explains a frame by its function's name whichever exercise
   is graded (a program given without --exercise is graded as ej1). */
const functions_owner *functions_owner_at(size_t k);

/* The table of an exercise (ej1's for RAYO_COURSE_EXERCISES). */
const functions_exercise *functions_exercise_of(int course);

/* engine.c: function name was right on all its cases known inputs, or
   (maker not NULL) was called on what maker returned and valgrind checks
   the rest.  Not a line of its own: the criterion sums them up in one,
   after its findings.  RAYO_ERR_NOMEM when memory runs out. */
rayo_status functions_right(grade_context *ctx, const char *name,
                            unsigned cases, const char *maker,
                            rayo_error *err);

/* The records an exercise's harness is given for the usable functions:
   "u" and "m" for each, then its calls; NULL when memory runs out. */
char *functions_calls(const functions_exercise *ex, const int *usable);

#endif
