/*
 * scene_lexer.h - the words of a scene file, one line at a time, and the
 * "FILE:LINE:COL: ..." messages that point at them.
 *
 * A scene file is lines of words separated by blanks (space, tab, a
 * carriage return before the newline); '#' starts a comment that runs to
 * the end of the line.  The lexer hands the grammar (scene_file.c) one
 * line at a time and the words of that line one at a time, knowing
 * nothing of keywords; it refuses lines longer than RAYO_SCENE_MAX_LINE
 * bytes and NUL bytes.  Private to the library.
 */
#ifndef RAYO_SCENE_LEXER_H
#define RAYO_SCENE_LEXER_H

#include <stddef.h>

#include "rayo/status.h"

typedef struct scene_word {
    const char *text; /* not NUL-terminated */
    size_t length;
    size_t column; /* 1-based byte column */
} scene_word;

typedef struct scene_lexer {
    const char *name; /* the file, for messages */
    const char *text;
    size_t length;
    size_t line_start, line_end; /* the current line, without newline */
    size_t next_line;            /* where the line after it starts */
    size_t pos;                  /* next byte to look at on the line */
    unsigned long line;          /* 1-based number of the current line */
    rayo_error *err;             /* where failures are recorded; may be NULL */
} scene_lexer;

void scene_lexer_init(scene_lexer *lx, const char *name, const char *text,
                      size_t length, rayo_error *err);

/*
 * Moves to the next line that has a word on it and sets *more to 1, or
 * to 0 at the end of the text.  Fails (RAYO_ERR_LIMIT, RAYO_ERR_FORMAT)
 * on a line that is too long or holds a NUL byte.
 */
rayo_status scene_lexer_next_line(scene_lexer *lx, int *more);

/* The next word of the line into *word: 1, or 0 at the end of the line. */
int scene_lexer_word(scene_lexer *lx, scene_word *word);

/* 1 when the line has another word (without taking it). */
int scene_lexer_more(scene_lexer *lx);

/* The column at which the next word starts, or the line's end. */
size_t scene_lexer_column(scene_lexer *lx);

/* 1 when word is exactly the keyword text. */
int scene_word_is(const scene_word *word, const char *keyword);

/* FNV-1a over a word's bytes: the hash the material names' tables use
 * (scene_file_objects.c, scene_file_split.c). */
size_t scene_word_hash(const char *text, size_t length);

/*
 * Writes word into buffer as printable text for a message: at most 40
 * bytes of it, other bytes shown as '?', "..." when cut.  buffer should
 * hold 48 bytes.
 */
const char *scene_word_show(const scene_word *word, char *buffer,
                            size_t size);

/* Records "NAME:LINE:COLUMN: message" in lx->err and returns status. */
rayo_status scene_lexer_fail(const scene_lexer *lx, size_t column,
                             rayo_status status, const char *format, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

#endif
