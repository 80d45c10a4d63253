/*
 * grade.h - checking a student's submission the way the course does:
 * it compiles with the course's flags, its functions return the right
 * values, it runs to the end under limits, its output is strict Netpbm of
 * the right size, its image is consistent with the reference, and
 * valgrind finds no invalid access and no leak.
 *
 * The grader is library code: it never prints.  It fills a report, one
 * entry per criterion (pass, fail or skipped, with reason lines written
 * for the student), that the command turns into text or JSON.  Each
 * exercise of the course is an entry in a registry (rayo_grade_exercise).
 * Every program runs isolated and under limits (below; docs/grading.md).
 */
#ifndef RAYO_GRADE_H
#define RAYO_GRADE_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/course.h"
#include "rayo/export.h"
#include "rayo/image.h"
#include "rayo/lang_id.h"
#include "rayo/status.h"

/*
 * Isolation: by default the compiler, the functions' harness, the
 * program and valgrind all run inside a bubblewrap sandbox (new user,
 * PID, network, IPC and UTS namespaces; a read-only system; the program's
 * folder a size-limited tmpfs; no capabilities), under resource limits (a
 * cgroup per run, where one can be made, for the memory and processes of
 * the whole tree; setrlimit before exec: CPU time, address space, file
 * size, process count, descriptors) and a wall-clock timeout measured by
 * the grader; the report's isolation line says which limits hold.  When
 * no sandbox can be made the report says so (rayo_grade_report.isolated,
 * .isolation) and the limits alone remain: they stop honest mistakes, not
 * code written to do harm.
 */

#ifdef __cplusplus
extern "C" {
#endif

/* The criteria, in the order they are checked and reported. */
typedef enum rayo_grade_criterion {
    RAYO_GRADE_COMPILE,   /* cc -std=c99 -Wall -Werror -pedantic ... -lm */
    RAYO_GRADE_FUNCTIONS, /* producto_interno, norma, intersecta_esfera */
    RAYO_GRADE_RUN,       /* runs to exit status 0 within the limits */
    RAYO_GRADE_OUTPUT,    /* strict Netpbm, the exercise's size */
    RAYO_GRADE_IMAGE,     /* consistent with the reference image */
    RAYO_GRADE_VALGRIND,  /* no invalid access, no leak */
    RAYO_GRADE_CRITERIA   /* how many there are */
} rayo_grade_criterion;

typedef enum rayo_grade_result {
    RAYO_GRADE_SKIPPED = 0, /* not checked (reason says why) */
    RAYO_GRADE_PASS,
    RAYO_GRADE_FAIL
} rayo_grade_result;

/* One criterion's outcome: a result and reason lines for the student. */
typedef struct rayo_grade_item {
    rayo_grade_result result;
    char **lines;       /* line_count lines, no newline; owned */
    size_t line_count;
    size_t warnings;    /* lines that are warnings */
} rayo_grade_item;

typedef struct rayo_grade_report {
    rayo_grade_item items[RAYO_GRADE_CRITERIA];
    char *verdict;      /* compare's verdict ("identical", ...) or NULL */
    int isolated;       /* 1 when the submission ran in the sandbox */
    /* "sandbox: bubblewrap (user, pid, ...); limits: ...",
       "not isolated: WHY; limits: ..." or "off" */
    char isolation[512];
} rayo_grade_report;

/* How the submission is isolated (rayo_grade_options.sandbox). */
typedef enum rayo_grade_sandbox_mode {
    RAYO_GRADE_SANDBOX_AUTO = 0, /* the sandbox when it can be made, else
                                    run unisolated and say so */
    RAYO_GRADE_SANDBOX_REQUIRE,  /* the sandbox, or refuse to grade */
    RAYO_GRADE_SANDBOX_OFF       /* no sandbox, no warning */
} rayo_grade_sandbox_mode;

/* What an exercise asks for.  The registry is constant data. */
typedef struct rayo_grade_exercise {
    const char *name;        /* "ej1" */
    const char *title;       /* "Ejercicio obligatorio 1: the sphere",
                                English: a catalogue message */
    uint32_t width, height;  /* the image the program must write */
    char magic;              /* its plain Netpbm format: '1' PBM, '2' PGM,
                                '3' PPM */
    rayo_course_exercise course; /* its scene (course.h) */
    /* Renders the exercise's reference image into image; NULL for an
       exercise the course gives no reference for (TP1). */
    rayo_status (*reference)(rayo_image *image, rayo_error *err);
    /* A whole program's executable, built by the submission's own
       Makefile (TP1: "20212_tp1"); its submission is a folder and it is
       checked by what the statement fixes (docs/grading.md, "TP1").
       NULL for the exercises grade compiles from their sources. */
    const char *program;
} rayo_grade_exercise;

/* The exercise called name, or NULL. */
RAYO_API const rayo_grade_exercise *rayo_grade_exercise_find(const char *name);

/* The registry: *count exercises. */
RAYO_API const rayo_grade_exercise *rayo_grade_exercises(size_t *count);

typedef struct rayo_grade_options {
    const char *const *sources;  /* the student's .c files */
    size_t source_count;
    const rayo_grade_exercise *exercise;
    const char *cc;              /* compiler; NULL: $CC, else "cc" */
    const char *reference;       /* image file; NULL: the exercise's */
    const char *diff;            /* write the compare picture here */
    double timeout;              /* wall seconds per run (default 10) */
    double cpu;                  /* CPU seconds per run (default 10) */
    uint64_t memory;             /* the run's tree, and the address
                                    space of each process, bytes
                                    (512 MiB) */
    uint64_t output_limit;       /* file size, bytes (64 MiB) */
    unsigned long processes;     /* the run's tree, and RLIMIT_NPROC
                                    (64) */
    int valgrind;                /* run memcheck when installed */
    rayo_grade_sandbox_mode sandbox; /* default AUTO */
    uint64_t disk;               /* the sandbox's tmpfs, bytes (256 MiB) */
    /* Polled while a program runs (may be NULL): nonzero stops the
       grading, kills what runs and fails with RAYO_ERR_CANCELLED. */
    int (*cancelled)(void *context);
    void *cancel_context;
    /* The language of the image comparison's sentences in the report
       (grade's own lines are English still); default RAYO_LANG_EN. */
    rayo_lang lang;
} rayo_grade_options;

/* The defaults above, for exercise ej1 and no sources. */
RAYO_API void rayo_grade_options_init(rayo_grade_options *options);

/*
 * Grades a submission.  RAYO_OK means the grading itself worked, however
 * the submission did: read the report.  Errors are the grader's own (no
 * temporary directory, a reference that cannot be read, out of memory),
 * and leave the report empty.  Free the report with
 * rayo_grade_report_free in every case.
 */
RAYO_API rayo_status rayo_grade(const rayo_grade_options *options,
                                rayo_grade_report *report, rayo_error *err);

/*
 * Whether a submission graded with these options would be isolated: 1
 * and text "bubblewrap (user, pid, net, ipc namespaces; ...)", or 0 and
 * text "not isolated: WHY" ("off" for RAYO_GRADE_SANDBOX_OFF).  The first
 * call tries the sandbox for real (bwrap on PATH runs /bin/true inside
 * one); later calls reuse the answer.  Not thread-safe on the first call.
 * rayo_grade with RAYO_GRADE_SANDBOX_REQUIRE fails with RAYO_ERR_INVALID
 * when this says 0.
 */
RAYO_API int rayo_grade_sandbox_check(const rayo_grade_options *options,
                                      char *text, size_t room);

/* RAYO_GRADE_PASS when no criterion failed, else RAYO_GRADE_FAIL. */
RAYO_API rayo_grade_result rayo_grade_overall(const rayo_grade_report *report);

/* "compile", "functions", "run", "output", "image", "valgrind". */
RAYO_API const char *rayo_grade_criterion_name(rayo_grade_criterion criterion);

/* "pass", "fail", "skipped". */
RAYO_API const char *rayo_grade_result_name(rayo_grade_result result);

RAYO_API void rayo_grade_report_free(rayo_grade_report *report);

/*
 * The C sources of a submission: path itself when it is a file, else
 * the *.c files directly inside the directory, sorted by name.  Free
 * with rayo_grade_paths_free.  RAYO_ERR_INVALID when a directory holds
 * no .c file.
 */
RAYO_API rayo_status rayo_grade_sources(const char *path, char ***sources,
                                        size_t *count, rayo_error *err);

/* The submission folders directly inside dir, sorted by name. */
RAYO_API rayo_status rayo_grade_submissions(const char *dir, char ***folders,
                                            size_t *count, rayo_error *err);

RAYO_API void rayo_grade_paths_free(char **paths, size_t count);

#ifdef __cplusplus
}
#endif

#endif
