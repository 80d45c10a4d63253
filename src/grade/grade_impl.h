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

/* report.c: appends one formatted line, format looked up in the catalog
   of err's language (a catalog message: grade_say, grade_fail and
   grade_warn are xgettext keywords); RAYO_ERR_NOMEM when memory runs
   out. */
rayo_status grade_say(rayo_grade_item *item, rayo_error *err,
                      const char *format, ...) GRADE_PRINTF(3, 4);

/* Sets the result and appends a line, in one call. */
rayo_status grade_fail(rayo_grade_item *item, rayo_error *err,
                       const char *format, ...) GRADE_PRINTF(3, 4);

/* Appends a line that is a warning (counted in item->warnings). */
rayo_status grade_warn(rayo_grade_item *item, rayo_error *err,
                       const char *format, ...) GRADE_PRINTF(3, 4);

/* Appends the first max lines of text (a compiler's messages, a log),
   each indented, and "... (N more lines)" when there are more. */
rayo_status grade_quote(rayo_grade_item *item, const char *text,
                        size_t max, rayo_error *err);

/* run/tempdir.c */
rayo_status grade_tempdir_create(char **path, rayo_error *err);
/* Removes the directory and everything in it with descriptor-relative
   calls (no symbolic link followed, no PATH_MAX limit, any depth);
   frees path. */
void grade_tempdir_remove(char *path);
/* dir + "/" + name, allocated; NULL when memory runs out. */
char *grade_path_join(const char *dir, const char *name);
/* The folder part of path, allocated ("." for none); NULL when memory
   runs out. */
char *grade_dir_of(const char *path);
/* a + b, allocated; NULL when memory runs out. */
char *grade_concat(const char *a, const char *b);
/* Reads a whole file (at most limit bytes) into a NUL-terminated buffer;
   opened without following a symbolic link, without blocking, and only
   when it is a regular file. */
rayo_status grade_read_file(const char *path, uint64_t limit, char **data,
                            size_t *size, rayo_error *err);
rayo_status grade_write_file(const char *path, const char *text,
                             rayo_error *err);
/* Reads descriptor fd (at most limit bytes) into a NUL-terminated
   buffer; *cut when there was more. */
rayo_status grade_read_fd(int fd, uint64_t limit, char **data, size_t *size,
                          int *cut, rayo_error *err);

/* checks/output_header.c: what an output's first bytes say it is (Netpbm's
   magic and size, plain or raw; PNG's IHDR), read without decoding. */
typedef struct grade_header {
    const char *format;     /* "plain PBM", "raw PPM", "PNG", ... */
    uint64_t width, height; /* as the header says (huge ones saturated) */
    unsigned depth;         /* bits per sample; 0 when not said */
} grade_header;
/* 1 and *header filled when the output begins with a header it knows. */
int grade_header_peek(const void *data, size_t size, grade_header *header);
/* How many times the exercise's pixel count an output may promise and
   still be decoded (and compared, as an image of the wrong size). */
#define GRADE_SIZE_MARGIN 4
/* The most pixels an output's header may promise: GRADE_SIZE_MARGIN
   times the larger of the exercise's size and the reference's. */
uint64_t grade_pixels_allowed(const rayo_grade_exercise *exercise,
                              const rayo_image *reference);
/* Descriptors per process (RLIMIT_NOFILE) for every run: far more than
   a course's program or the compiler opens. */
#define GRADE_OPEN_FILES 256

/* run/process.c: one run of a program, its limits and what became of it. */
typedef struct grade_limits {
    double wall;          /* seconds; the process group is killed after */
    double cpu;           /* seconds; 0 = no limit */
    uint64_t memory;      /* address space bytes; 0 = no limit */
    uint64_t tree_memory; /* bytes for the whole tree (its cgroup, where
                             one can be made); 0 = no limit */
    uint64_t file_size;   /* bytes; 0 = no limit */
    unsigned long processes; /* per uid (rlimit) and for the tree (its
                                cgroup); 0 = no limit */
    unsigned long open_files; /* descriptors per process; 0 = no limit */
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
    double seconds;   /* wall time, the grader's clock */
} grade_outcome;

/* Who runs: the compiler (trusted tool) or the student's code. */
typedef enum grade_role {
    /* In the current directory with the caller's environment; in the
       sandbox it sees the system, the sources' folders read-only and
       the build folder (ctx->dir) writable. */
    GRADE_ROLE_TOOL,
    /* In the work folder (ctx->work; in the sandbox a fresh tmpfs of
       options->disk bytes) with a minimal environment (PATH, HOME and
       TMPDIR the work folder, LANG=C). */
    GRADE_ROLE_STUDENT
} grade_role;

/* What to run and what to bring back. */
typedef struct grade_run {
    char *const *argv;    /* argv[0] a path, or a name on PATH (search) */
    int search;
    grade_role role;
    const char *program;  /* STUDENT: the built file it runs (bound
                             read-only into the sandbox at its path) */
    uint64_t out_limit;   /* bytes of standard output kept */
    int log_fd;           /* >= 3: a socket handed to it as this
                             descriptor is read while it runs (valgrind's
                             log; grade_log_fd gives the number), and
                             its soft RLIMIT_NOFILE lowered to it */
    int collect;          /* STUDENT: bring back the one image file
                             (.pbm .pgm .ppm .pnm) it left in its folder */
    int input;            /* > 0: a descriptor (a pipe's reading end)
                             that becomes its standard input; 0: none,
                             /dev/null */
} grade_run;

/* What came back.  Free with grade_captured_free. */
typedef struct grade_captured {
    grade_outcome outcome;
    char *out;            /* standard output (at most out_limit bytes) */
    size_t out_size;
    char *errors;         /* standard error (at most 1 MiB) */
    size_t errors_size;
    char *log;            /* what came through log_fd (at most 16 MiB) */
    size_t log_size;
    int log_overflow;     /* more came than was kept */
    char *file_name;      /* collect: the image file's name, or NULL */
    char *file;           /* and its bytes (at most out_limit) */
    size_t file_size;
    int memory_exceeded;  /* the kernel killed in its cgroup for memory */
    uint64_t memory_peak; /* the tree's peak memory (0: not known) */
} grade_captured;

struct grade_context;

/*
 * Runs one program under limits, inside the sandbox when ctx has one.
 * Standard input is /dev/null (or run->input); standard output and error go to unlinked
 * files the grader opened (the program cannot swap them), read back
 * into got.  The wall clock is the grader's: a run that ends after
 * limits->wall seconds by that clock counts as timed out, whatever
 * stopped the grader meanwhile.  Errors are the grader's own (no fork,
 * a sandbox that could not be set up, cancelled).
 */
rayo_status grade_spawn(struct grade_context *ctx, const grade_run *run,
                        const grade_limits *limits, grade_captured *got,
                        rayo_error *err);
void grade_captured_free(grade_captured *got);
/* The descriptor for valgrind's log: below the soft RLIMIT_NOFILE the
   grader has (so it can be placed there) and at most 1023; -1 when the
   limit is too low for one. */
int grade_log_fd(void);

/* run/cgroup.c: a control group of its own per run (cgroup v2, else v1),
   limiting the memory and the processes of the whole tree. */
typedef struct grade_cgroup {
    int version;          /* 2, 1, or 0: none (the rlimits alone hold) */
    char *dirs[2];        /* v2: [0]; v1: [0] memory, [1] pids */
    int procs[2];         /* their cgroup.procs, open for writing */
} grade_cgroup;
/* 2 or 1: the kind of cgroup a run gets here; 0: none, and why (tried
   once, for real, and cached). */
int grade_cgroup_kind(char *why, size_t room);
/* Makes a run's group: memory bytes (0: no limit) for the tree, swap
   included, and at most processes (0: no limit).  cg->version 0, and
   RAYO_OK, where none can be made. */
rayo_status grade_cgroup_create(grade_cgroup *cg, uint64_t memory,
                                unsigned long processes, rayo_error *err);
/* In the child before exec (async-signal-safe): joins the group. */
int grade_cgroup_enter(const grade_cgroup *cg);
/* After the run: 1 when the kernel killed in it for lack of memory. */
int grade_cgroup_oom(const grade_cgroup *cg);
/* The tree's peak memory in bytes; 0 when not known. */
uint64_t grade_cgroup_peak(const grade_cgroup *cg);
/* Kills whatever is left in it and removes it. */
void grade_cgroup_remove(grade_cgroup *cg);
/* run/limits.c: the limits that hold on a run here, for the report's
   first line. */
void grade_limits_describe(const rayo_grade_options *options, char *text,
                           size_t room);
/* The limits a run gets here: as asked with a cgroup; without one, the
   sandbox's processes fewer, so that address space times processes
   bounds the tree, and an address space for every run. */
grade_limits grade_limits_here(const grade_limits *limits, int sandboxed);

/* run/sandbox.c: whether the sandbox works (cached), and its command. */
int grade_sandbox_available(char *why, size_t room);
/* The bwrap words in front of run->argv, for ctx; with processes > 0,
   RLIMIT_NPROC set to it inside (the processes of the sandbox's user
   namespace) and *counted 1.  NULL when memory runs out.  Free with
   grade_words_free. */
char **grade_sandbox_argv(const struct grade_context *ctx,
                          const grade_run *run, int json_fd,
                          unsigned long processes, int *counted);
void grade_words_free(char **words);
/* The text rayo_grade_report.isolation holds for a working sandbox. */
void grade_sandbox_describe(uint64_t disk, char *text, size_t room);

/* The limits a student's program runs under (run/run.c). */
grade_limits grade_run_limits(const rayo_grade_options *options);
/* A tool's run of argv (found on PATH), 1 MiB of its output kept. */
grade_run grade_tool_run(char *const *argv);
/* Only a wall clock, for the (trusted) compiler. */
grade_limits grade_compiler_limits(const rayo_grade_options *options,
                                   double seconds);

/* The full path of a program on PATH, allocated; NULL when none. */
char *grade_which(const char *name);

/* "segmentation fault (SIGSEGV)" and the like. */
const char *grade_signal_name(int signal_number);

/* The most arguments a graded program is given. */
#define GRADE_ARGS 8

/* The state of a grading in progress, shared by the steps. */
typedef struct grade_context {
    const rayo_grade_options *options;
    rayo_grade_report *report;
    char *dir;          /* the temporary directory (the build folder) */
    char *work;         /* dir/work: the program's folder */
    int sandboxed;      /* runs go through bubblewrap (run/sandbox.c) */
    char *bwrap;        /* its path */
    char *cwd;          /* the current directory (the compiler's) */
    const char *const *sources; /* the student's files, as given */
    char **absolute;    /* the same, absolute (for #include) */
    char **compiled;    /* the names the compiler is given: as typed, or
                           absolute when the sandbox could not see them
                           as typed */
    size_t source_count;
    char **cc;          /* the compiler command, split on spaces */
    size_t cc_words;
    char *program;      /* the compiled program */
    int stopped;        /* the run was stopped by a limit */
    char *output;       /* what the program wrote */
    size_t output_size;
    unsigned long run_uid; /* the sandbox's uid of its own (run/uid.c);
                              0 while it has none */
    int work_kept;      /* the work folder holds the built submission:
                           the sandbox binds it instead of a fresh tmpfs */
    char *const *args;  /* the program's arguments under valgrind (at
                           most GRADE_ARGS), or NULL for none */
    /* The functions the functions criterion found right, in the order
       judged, for its one summing-up line (functions/engine.c). */
    struct functions_right *right;
    size_t right_count;
} grade_context;

/* run/uid.c: the uid the sandboxed runs of ctx take (0: the grader's
   own): one of their own where the grader is root and no cgroup can be
   made, with the build folder handed to it and the sources' folders
   copied for it. */
rayo_status grade_run_uid(grade_context *ctx, unsigned long *uid,
                          rayo_error *err);
/* The copy of source i's folder that such a uid's sandbox binds where
   the folder is, allocated; NULL when memory runs out. */
char *grade_source_copy(const grade_context *ctx, size_t i);

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
/* tp1.c: the steps of an exercise whose submission is a whole program
   built by its own Makefile (rayo_grade_exercise.program). */
rayo_status grade_tp1_steps(grade_context *ctx, rayo_error *err);

#endif
