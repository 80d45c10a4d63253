/*
 * cli.h - what the subcommands of the `rayo` command share: exit
 * statuses, the subcommand entry points, and the parsing of option values
 * into numbers with one-line messages naming the option, the value and
 * what is accepted.
 *
 * Only the command prints; everything here writes to stderr in the form
 * "rayo: --option: 'value' ...; expected ...".
 */
#ifndef RAYO_CLI_H
#define RAYO_CLI_H

#include <stdarg.h>
#include <stdio.h>

#include "rayo.h"

/*
 * lang.c: the language of the command's messages, chosen once by
 * cli_lang_init from --lang (anywhere before "--"; a leading one, before
 * the subcommand, is taken out of argv) or the environment; an unknown
 * --lang is one line and CLI_EXIT_USAGE.  Every human message is marked:
 * _("...") translates it, N_("...") marks it for a later _(), and
 * _n("one", "many", n) picks the plural form (docs/i18n.md).
 */
rayo_lang cli_lang(void);
int cli_lang_init(int *argc, char **argv);
#define _(msgid) rayo_gettext(cli_lang(), msgid)
#define N_(msgid) msgid
#define _n(singular, plural, count) \
    rayo_ngettext(cli_lang(), singular, plural, count)

enum {
    CLI_EXIT_OK = 0,
    CLI_EXIT_FAILURE = 1, /* output failures; compare: inconsistent;
                             grade: failed */
    CLI_EXIT_USAGE = 2,   /* bad options, or an input that cannot be read
                             (missing, unreadable, a directory, malformed) */
    CLI_EXIT_NOMEM = 3    /* out of memory (or of the address space that
                             `ulimit -v` allows) */
};

/* Subcommands: each takes its own argv (argv[0] is the subcommand name). */
int cli_render(int argc, char **argv);
int cli_convert(int argc, char **argv);
int cli_compare(int argc, char **argv);
int cli_view(int argc, char **argv);
int cli_grade(int argc, char **argv);

/* view: the terminal's width ($COLUMNS, else 80), and an image printed
 * as text on stream (preview.h); returns an exit status. */
unsigned cli_terminal_columns(void);
int cli_print_preview(const rayo_image *image,
                      const rayo_preview_options *options, FILE *stream);

/* Every command: an input that cannot be read is bad input (exit 2;
 * memory excepted); text output flushed and checked (a closed pipe ends
 * quietly, other failures exit 1). */
int cli_unreadable(const rayo_error *err);
int cli_flush_text(FILE *stream, const char *name);

/* input.c: CLI_EXIT_OK when path ('-' passes) can be opened for reading
 * and is of the kind asked for; else one line naming it and the reason,
 * and CLI_EXIT_USAGE.  cli_same_file: 1 when a and b name the same file
 * (the same name, or the same device and inode, links followed), so that
 * an output never overwrites an input. */
typedef enum cli_input_kind {
    CLI_INPUT_FILE,    /* a folder is refused */
    CLI_INPUT_ANY,     /* a file or a folder */
    CLI_INPUT_FOLDER   /* a file is refused */
} cli_input_kind;
int cli_check_input(const char *path, cli_input_kind kind);
int cli_same_file(const char *a, const char *b);

/* escape.c: text from outside on one line.  The character at s as shown
   (control bytes and invalid UTF-8 as \n, \t, \r, \xHH; bidirectional
   controls and U+2028, U+2029 as \uHHHH; a backslash
   doubled when names), into text; returns the bytes of s it stands for,
   *columns how wide it is.  cli_put_escaped writes s so, at most max
   bytes (0: no limit) then "...".  cli_say and cli_sayf print "rayo: "
   and the message so, cut at CLI_MESSAGE_MAX bytes, and a newline on
   stderr: every message of the command goes through them. */
#define CLI_MESSAGE_MAX 1000
/* Bytes in the valid UTF-8 sequence of 2 to 4 bytes at s, else 0. */
size_t cli_utf8_sequence(const unsigned char *s);
size_t cli_escape_unit(const char *s, int names, char text[8],
                       size_t *columns);
void cli_put_escaped(FILE *stream, const char *s, int names, size_t max);
void cli_say(const char *text);
void cli_sayf(const char *format, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
void cli_vsayf(const char *format, va_list args)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 1, 0)))
#endif
    ;

/* Prints "rayo: MESSAGE" on stderr; returns CLI_EXIT_USAGE. */
/* quote.c: a command-line value as a message quotes it, apostrophes
 * included: whole when short, else a prefix and its length
 * ('77777777…' (100000 characters)).  Valid until four more quotes. */
const char *cli_quote(const char *text);

/* suggest.c: the one of names nearest to word (a typo away), or NULL;
 * cli_unknown_exercise: "OPTION: unknown exercise 'TEXT'; did you mean
 * ej1? The exercises are ej1, ej2, ej3", returns CLI_EXIT_USAGE. */
const char *cli_nearest(const char *word, const char *const *names,
                        size_t count);
int cli_unknown_exercise(const char *option, const char *text,
                         const char *const *names, size_t count);

/* JSON strings (json_text.c): s with control bytes as JSON escapes and
 * bytes that are not UTF-8 as U+FFFD; cli_json_text_line first escapes
 * s as the text report does (one line, \n, \x1b, ...) and cuts it at
 * max bytes with "...". */
void cli_json_string(FILE *stream, const char *s);
void cli_json_text_line(FILE *stream, const char *s, size_t max);

int cli_usage_error(const char *format, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/*
 * Reports a failed library call: nothing for a closed pipe (the process
 * then dies of SIGPIPE, quietly, as cat would), "rayo: MESSAGE" for the
 * rest.  Returns the exit status that fits the status: 2 for bad input,
 * 1 for I/O and memory.
 */
int cli_report(const rayo_error *err);

/*
 * A subcommand got `found` operands where it wants WHAT: prints "rayo:
 * COMMAND: expected WHAT, got N arguments; see 'rayo COMMAND --help'" and
 * returns CLI_EXIT_USAGE.
 */
int cli_wrong_operands(const char *command, int found, const char *what);

/* The message getopt_long's result calls for; returns CLI_EXIT_USAGE. */
int cli_bad_option(int option, char **argv, int index);

/*
 * Parse option values.  On failure they print one line naming option,
 * text and what is accepted, and return 0; on success they return 1.
 */
int cli_parse_uint(const char *option, const char *text, unsigned long min,
                   unsigned long max, unsigned long *value);
int cli_parse_double(const char *option, const char *text, double *value);
/* Exactly count comma-separated finite numbers; `shape` names them. */
int cli_parse_numbers(const char *option, const char *text, size_t count,
                      const char *shape, double *values);

/* grade --reference course: the path of the course's reference image
   for exercise ("ej1", ...) into path; 0 when it is not installed
   (course_data.c says where it looks). */
int cli_course_reference(const char *exercise, char *path, size_t room);

/* An image operand: course:ej1, course:ej2 or course:ej3 names the
   course's image (resolved into path, *resolved pointing at it) unless a
   file has that very name; anything else is *resolved as it is.  An
   unknown or missing course image is one line and CLI_EXIT_USAGE. */
int cli_image_operand(const char *operand, char *path, size_t room,
                      const char **resolved);

/* The course's exercise whose image (as cli_course_reference finds it)
   shows the same picture as image (rayo_image_same_picture), whatever
   the file's format; RAYO_COURSE_EXERCISES when none does or it cannot
   be read. */
rayo_course_exercise cli_course_picture(const rayo_image *image);

/* 1 when standard output is a terminal (an image is then shown as
   `rayo view` shows it, not written). */
int cli_stdout_is_terminal(void);

#endif
