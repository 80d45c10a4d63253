/*
 * grade_impl.h - what the grader's source files share and nobody else
 * needs: adding reason lines to a criterion, the temporary directory,
 * running a child process under limits, and the steps themselves.
 *
 * Not a public interface: the command and the tests use grade.h.
 */
#ifndef RAYO_GRADE_IMPL_H
#define RAYO_GRADE_IMPL_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/grade.h"
#include "rayo/image.h"
#include "rayo/status.h"

#if defined(__GNUC__) || defined(__clang__)
#define GRADE_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define GRADE_PRINTF(f, a)
#endif

/* report.c: appends one formatted line (a warning when it begins
   "warning: "); RAYO_ERR_NOMEM when memory runs out. */
rayo_status grade_say(rayo_grade_item *item, rayo_error *err,
                      const char *format, ...) GRADE_PRINTF(3, 4);

/* Sets the result and appends a line, in one call. */
rayo_status grade_fail(rayo_grade_item *item, rayo_error *err,
                       const char *format, ...) GRADE_PRINTF(3, 4);

/* Appends the first max lines of text (a compiler's messages, a log),
   each indented, and "... (N more lines)" when there are more. */
rayo_status grade_quote(rayo_grade_item *item, const char *text,
                        size_t max, rayo_error *err);

/* tempdir.c */
rayo_status grade_tempdir_create(char **path, rayo_error *err);
/* Removes the directory and everything in it; frees path. */
void grade_tempdir_remove(char *path);
/* dir + "/" + name, allocated; NULL when memory runs out. */
char *grade_path_join(const char *dir, const char *name);
/* a + b, allocated; NULL when memory runs out. */
char *grade_concat(const char *a, const char *b);
/* Reads a whole file (at most limit bytes) into a NUL-terminated buffer. */
rayo_status grade_read_file(const char *path, uint64_t limit, char **data,
                            size_t *size, rayo_error *err);
rayo_status grade_write_file(const char *path, const char *text,
                             rayo_error *err);

/* process.c: one run of a program, its limits and what became of it. */
typedef struct grade_limits {
    double wall;          /* seconds; the process group is killed after */
    double cpu;           /* seconds; 0 = no limit */
    uint64_t memory;      /* address space bytes; 0 = no limit */
    uint64_t file_size;   /* bytes; 0 = no limit */
    unsigned long processes; /* 0 = no limit */
    int (*cancelled)(void *context); /* may be NULL */
    void *cancel_context;
} grade_limits;

typedef enum grade_ending {
    GRADE_EXITED,     /* status holds the exit status */
    GRADE_SIGNALED,   /* status holds the signal */
    GRADE_TIMED_OUT,  /* killed by the grader after limits.wall seconds */
    GRADE_CANCELLED   /* killed because limits.cancelled said so */
} grade_ending;

typedef struct grade_outcome {
    grade_ending ending;
    int status;
    double seconds;   /* wall time */
} grade_outcome;

/*
 * Runs argv[0] (a path, or a name found on PATH when search is set) in
 * dir with standard input from /dev/null and standard output and error
 * into the files stdout_path and stderr_path.  env NULL: a minimal
 * environment (PATH, HOME=dir, TMPDIR=dir, LANG=C); else env.
 */
rayo_status grade_process_run(char *const argv[], char *const env[],
                              const char *dir, const char *stdout_path,
                              const char *stderr_path,
                              const grade_limits *limits, int search,
                              grade_outcome *outcome, rayo_error *err);

/* The limits a student's program runs under (run.c). */
grade_limits grade_run_limits(const rayo_grade_options *options);
/* Only a wall clock, for the (trusted) compiler. */
grade_limits grade_compiler_limits(const rayo_grade_options *options,
                                   double seconds);

/* The full path of a program on PATH, allocated; NULL when none. */
char *grade_which(const char *name);

/* "segmentation fault (SIGSEGV)" and the like. */
const char *grade_signal_name(int signal_number);

/* The state of a grading in progress, shared by the steps. */
typedef struct grade_context {
    const rayo_grade_options *options;
    rayo_grade_report *report;
    char *dir;          /* the temporary directory */
    const char *const *sources; /* the student's files, as given */
    char **absolute;    /* the same, absolute (for #include) */
    size_t source_count;
    char **cc;          /* the compiler command, split on spaces */
    size_t cc_words;
    char *program;      /* the compiled program */
    int stopped;        /* the run was stopped by a limit */
    char *output;       /* what the program wrote */
    size_t output_size;
} grade_context;

/* Builds an argv: the compiler words, then the given words, then NULL.
   Free with free() (the strings are borrowed). */
char **grade_cc_argv(const grade_context *ctx, const char *const *words,
                     size_t count);

/* The steps; each fills its own criterion. */
rayo_status grade_step_compile(grade_context *ctx, rayo_error *err);
rayo_status grade_step_functions(grade_context *ctx, rayo_error *err);
rayo_status grade_step_run(grade_context *ctx, rayo_error *err);
rayo_status grade_step_image(grade_context *ctx, const rayo_image *image,
                             const rayo_image *reference, int salvaged,
                             rayo_error *err);
rayo_status grade_step_valgrind(grade_context *ctx, rayo_error *err);

#endif
