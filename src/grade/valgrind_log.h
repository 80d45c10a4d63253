/*
 * valgrind_log.h - reading valgrind's log as bytes (valgrind_log.c):
 * its lines one at a time, with their "==PID== " frame taken off, and
 * the signs that something other than valgrind wrote into it.
 *
 * Not a parser of valgrind's findings: valgrind.c decides what each line
 * means for the criterion.  Internal to the grader.
 */
#ifndef RAYO_GRADE_VALGRIND_LOG_H
#define RAYO_GRADE_VALGRIND_LOG_H

#include <stddef.h>

/* One line of the log.  Nothing in it is NUL-terminated. */
typedef struct vg_line {
    const char *text;   /* the whole line, without its '\n' */
    size_t length;
    const char *body;   /* after the frame and the spaces that follow */
    size_t body_length;
    long pid;           /* the frame's PID; -1 when the line has none */
} vg_line;

/* The line at *pos of data[0, size) and *pos moved past it; 0 when
   *pos is at the end.  NUL bytes are bytes like any other. */
int vg_next_line(const char *data, size_t size, size_t *pos,
                 vg_line *line);

/* 1 when the line's body begins with word (a C string). */
int vg_begins(const vg_line *line, const char *word);

/* Where word (a C string) first is in the line's body, or NULL. */
const char *vg_find(const vg_line *line, const char *word);

/* length bytes of text into out as a C string of at most room - 1
   bytes, a NUL byte becoming a space. */
void vg_copy(const char *text, size_t length, char *out, size_t room);

/* What in a log valgrind does not write. */
typedef struct vg_signs {
    int nul;        /* a NUL byte */
    int unframed;   /* a line without a ==PID==, --PID-- or **PID** frame
                       (before valgrind's own crash report, if any) */
    int duplicate;  /* two ERROR SUMMARY lines from one process */
    int touched_fd; /* valgrind refused the program a write (or a dup)
                       on this descriptor, its log's or above; -1: none */
    int panic;      /* valgrind stopped on an internal error */
    size_t panic_at; /* where its report of it begins */
} vg_signs;

/* Looks for those signs; log_fd is the log's descriptor. */
void vg_check(const char *data, size_t size, int log_fd, vg_signs *signs);

/* 1 when text (a program's output) has a line framed as valgrind
   frames its log ("==PID== ..."). */
int vg_framed_text(const char *data, size_t size);

#endif
