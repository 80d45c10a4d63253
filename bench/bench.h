/*
 * bench.h - what the benchmark's files share: the clock, the table of
 * results, the render job, pipes drained by a thread, and child processes
 * measured for time and peak memory.
 *
 * The benchmark (`make bench`) is a program, not a test: it prints a
 * table and writes JSON, and checks nothing in `make check`.  Every
 * figure is the best of several runs in the same process, so the ratios
 * in the table compare figures taken minutes apart on the same machine.
 * bench.c explains how to add a row.
 */
#ifndef RAYO_BENCH_H
#define RAYO_BENCH_H

#include <stddef.h>
#include <stdint.h>

#include "rayo.h"

typedef struct bench_table bench_table;

/* Seconds on a monotonic clock. */
double bench_now(void);

/* The smaller of two times, where a negative one stands for none (not
 * measured yet, or failed): the best-of-N every figure takes. */
double bench_best(double a, double b);

/* Adds a measured figure (label as printed; key as in the JSON); unit
 * "skipped" (value -1) for one that needs a tool this machine lacks. */
void bench_add(bench_table *table, const char *key, const char *label,
               double value, const char *unit);

/*
 * Adds a target: value compared with limit (at_most: value <= limit,
 * else value >= limit).  Printed after the figures with pass or FAIL.
 */
void bench_target(bench_table *table, const char *label, double value,
                  double limit, int at_most);

/* A target that could not be judged here (a tool missing): printed as
 * "skipped", neither pass nor FAIL. */
void bench_target_skipped(bench_table *table, const char *label,
                          double limit, int at_most);

/* The value of the figure with this key; -1 when there is none. */
double bench_value(const bench_table *table, const char *key);

/* The number of runs each figure takes the best of. */
int bench_repeats(const bench_table *table);

/* The rows against other programs (peer_rows.c): the value after "key "
 * at the start of a line of text (-1 if none); a / b, or -1 unless both
 * are positive; a figure (value < 0: "failed") or target that says
 * "skipped" unless available. */
double bench_output_value(const char *text, const char *key);
double bench_ratio(double a, double b);
void bench_add_peer(bench_table *table, const char *key, const char *label,
                    double value, const char *unit, int available);
void bench_target_peer(bench_table *table, const char *label, double value,
                       double limit, int at_most, int available);

/* The first number in the file at path (GNU time's -o), or -1. */
double bench_read_number(const char *path);

/* A pipe whose reading end a thread empties into nothing. */
typedef struct bench_pipe bench_pipe;
int bench_pipe_open(bench_pipe **pipe, int *write_fd);
/* Closes the writing end (if still open) and waits for the reader. */
void bench_pipe_close(bench_pipe *pipe, int write_fd);

/*
 * Runs argv (argv[0] a path) with stdout on /dev/null, or `sh -c
 * command` when argv is NULL; returns the wall time in seconds, or a
 * negative number when the child fails.  With max_rss_kib not NULL it
 * runs under /usr/bin/time instead and puts there the peak resident set
 * of the child and its descendants, in KiB (process.c says why); the
 * time then includes GNU time's own start.
 */
double bench_run_child(char *const argv[], const char *command,
                       long *max_rss_kib);

/*
 * Runs `sh -c command`, its standard output on /dev/null or, with capture
 * not NULL, read into capture (NUL-terminated, cut at capture_size - 1
 * bytes); returns the wall time in seconds, or a negative number when
 * the child fails, and puts the child's processor time (user + system,
 * its waited-for descendants included) in *cpu_seconds.
 */
double bench_run_measured(const char *command, char *capture,
                          size_t capture_size, double *cpu_seconds);

/*
 * The job `rayo render` does, in process (render_job.c): the frame
 * rendered through a writer of format (plain or raw) into out, which is
 * then committed, or aborted on a failure.  0, or -1.
 */
int bench_render_into(rayo_output *out, const rayo_camera *camera,
                      const rayo_scene *scene,
                      const rayo_render_options *options, rayo_format format,
                      int plain);

/* The rows: seed.c, large.c, bvh.c, commands.c, compare_noise.c,
 * peers.c, meshes.c. */
void bench_seed(bench_table *table);
void bench_large(bench_table *table, const char *rayo);
void bench_bvh(bench_table *table);
void bench_commands(bench_table *table, const char *rows_file);
void bench_compare_noise(bench_table *table);
void bench_peers(bench_table *table);
void bench_meshes(bench_table *table);

/* The median time a new thread takes to start running on an idle CPU
 * (thread_start.c), seconds; -1 when no thread could be created. */
double bench_thread_start_seconds(void);

/* bytes set to zero in bands by `threads` threads started for it
 * (band_fill.c), seconds; -1 when memory ran out. */
double bench_band_fill_seconds(size_t bytes, unsigned threads);

/* The assignment's program, the baseline of seed.c (baseline.c). */
void bench_baseline_seed(int fd);

#endif
