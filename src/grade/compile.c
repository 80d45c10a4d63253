/*
 * compile.c - the first criterion: the submission compiles with the
 * course's flags, `cc -std=c99 -Wall -Werror -pedantic ... -lm`.
 *
 * The compiler is the user's own and runs in the current directory, so
 * its messages name the files as the user typed them; only the program
 * it makes goes into the temporary directory.  In the sandbox it sees
 * the system and the sources' folders only (an #include of /etc/shadow
 * finds nothing).  -g is added
 * so valgrind can name lines; it changes no warning.  The report shows
 * the command word for word as it ran.  On failure the first messages
 * are quoted; when every error is a warning that -Werror made fatal that
 * is pointed out as such, and when a real error is among them, that one
 * is named as the thing to fix.
 */
#define _POSIX_C_SOURCE 200809L

#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grade_impl.h"
#include "functions/harness.h"

#define COMPILE_SECONDS 120.0
#define QUOTED_LINES 8

static const char *const course_flags[] = {"-std=c99", "-Wall", "-Werror",
                                           "-pedantic"};
#define COURSE_FLAGS (sizeof course_flags / sizeof course_flags[0])

#define SHOWN_COMMAND 1000 /* characters of the compile line shown */
#define SHOWN_ERROR 300    /* characters of a quoted error line */

/* Counts c and stores it while there is room: *n past room - 1 means
   the text was cut. */
static void put(char *buffer, size_t room, size_t *n, char c)
{
    if (*n + 1 < room)
        buffer[*n] = c;
    (*n)++;
}

static void put_text(char *buffer, size_t room, size_t *n, const char *s)
{
    for (; *s != '\0'; s++)
        put(buffer, room, n, *s);
}

/*
 * One word of the command, as a shell reads it back: bare when it holds
 * only characters no shell treats specially, else in single quotes,
 * else (control bytes) in $'...' with the bytes escaped.
 */
static void put_word(char *buffer, size_t room, size_t *n, const char *word)
{
    static const char safe[] = "abcdefghijklmnopqrstuvwxyz"
                               "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                               "0123456789_@%+=:,./-";
    const unsigned char *p;
    int control = 0;
    if (word[0] != '\0' && strspn(word, safe) == strlen(word)) {
        put_text(buffer, room, n, word);
        return;
    }
    for (p = (const unsigned char *)word; *p != '\0'; p++)
        if (*p < 0x20 || *p == 0x7f)
            control = 1;
    if (!control) {
        put(buffer, room, n, '\'');
        for (p = (const unsigned char *)word; *p != '\0'; p++) {
            if (*p == '\'')
                put_text(buffer, room, n, "'\\''");
            else
                put(buffer, room, n, (char)*p);
        }
        put(buffer, room, n, '\'');
        return;
    }
    put_text(buffer, room, n, "$'");
    for (p = (const unsigned char *)word; *p != '\0'; p++) {
        char escaped[8];
        if (*p == '\n')
            put_text(buffer, room, n, "\\n");
        else if (*p == '\t')
            put_text(buffer, room, n, "\\t");
        else if (*p == '\\' || *p == '\'') {
            put(buffer, room, n, '\\');
            put(buffer, room, n, (char)*p);
        } else if (*p < 0x20 || *p == 0x7f) {
            snprintf(escaped, sizeof escaped, "\\x%02x", *p);
            put_text(buffer, room, n, escaped);
        } else
            put(buffer, room, n, (char)*p);
    }
    put(buffer, room, n, '\'');
}

/*
 * The command that ran, word for word, for the report: the compiler's
 * own words (all of --cc or $CC), the course's flags, -g, and the
 * sources as given.  One exception: the program it makes is in a
 * temporary directory that is gone when the student reads this, so that
 * word is shown as "programa", the name a student would give it.
 */
static rayo_status say_command(grade_context *ctx, rayo_grade_item *item,
                               char *const *argv, rayo_error *err)
{
    char line[SHOWN_COMMAND + 1];
    size_t i, n = 0;
    for (i = 0; argv[i] != NULL; i++) {
        if (i > 0)
            put(line, sizeof line, &n, ' ');
        put_word(line, sizeof line, &n,
                 argv[i] == ctx->program ? "programa" : argv[i]);
    }
    if (n >= sizeof line) {
        n = sizeof line - 4;
        memcpy(line + n, "...", 3);
        n += 3;
    }
    line[n] = '\0';
    return grade_say(item, err, "%s", line);
}

/* The line at p, without its newline: its start and length. */
static size_t line_at(const char *text, const char *p, const char **start)
{
    while (p > text && p[-1] != '\n')
        p--;
    *start = p;
    return strcspn(p, "\n");
}

/*
 * The compiler's error lines (those with "error: " in them, as gcc and
 * clang write "FILE:LINE:COL: error: ..." and "fatal error: ..."), told
 * apart: *werror the first that -Werror made of a warning ("[-Werror"
 * on the line), *plain the first that is an error of its own.  Each is
 * the start of its line, or NULL when there is none.
 */
/* 1 when the length bytes at line hold word. */
static int line_has(const char *line, size_t length, const char *word)
{
    size_t n = strlen(word), i;
    for (i = 0; i + n <= length; i++)
        if (line[i] == word[0] && memcmp(line + i, word, n) == 0)
            return 1;
    return 0;
}

static void find_errors(const char *text, const char **werror,
                        const char **plain)
{
    const char *p = text;
    *werror = NULL;
    *plain = NULL;
    while (*p != '\0') {
        size_t length = strcspn(p, "\n");
        if (line_has(p, length, "error: ")) {
            int is_werror = line_has(p, length, "[-Werror");
            if (is_werror && *werror == NULL)
                *werror = p;
            if (!is_werror && *plain == NULL)
                *plain = p;
        }
        p += length;
        if (*p == '\n')
            p++;
    }
}

/* The text between "error: " and " [-Werror..." on the line at start. */
static const char *werror_hint(const char *start, size_t *length)
{
    const char *end = start + strcspn(start, "\n");
    const char *flag = strstr(start, "[-Werror");
    const char *text = strstr(start, "error: ");
    if (flag == NULL || text == NULL || flag > end || text > flag)
        return NULL;
    text += 7;
    *length = (size_t)(flag - text);
    while (*length > 0 && text[*length - 1] == ' ')
        (*length)--;
    return text;
}

/*
 * When the error on the line at start comes from a macro standing where
 * the student wrote a name (a parameter called CX beside #define CX 0.5):
 * the macro's name in name and the place the student wrote it in place
 * ("main.c:5:60"), and 1.  gcc puts the error at the #define and adds
 * "note: in expansion of macro 'CX'" at the use; clang puts the error at
 * the use and adds "note: expanded from macro 'CX'".  Only the notes
 * before the next error count.
 */
static int macro_use(const char *start, char *name, size_t name_room,
                     char *place, size_t place_room)
{
    const char *p = start + strcspn(start, "\n");
    while (*p == '\n') {
        const char *line = p + 1, *note, *q;
        size_t length = strcspn(line, "\n"), n;
        int gcc;
        if (line_has(line, length, "error: "))
            return 0;
        note = strstr(line, "in expansion of macro ");
        gcc = note != NULL && note < line + length;
        if (!gcc)
            note = strstr(line, "expanded from macro ");
        if (note != NULL && note < line + length) {
            /* The name between quotes of any kind (ASCII or UTF-8). */
            q = note + strcspn(note, "'\xe2");
            while (*q == '\'' || (unsigned char)*q >= 0x80)
                q++;
            n = strspn(q, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                          "0123456789_");
            if (n == 0 || n >= name_room)
                return 0;
            memcpy(name, q, n);
            name[n] = '\0';
            /* The place: "FILE:LINE:COL" before ": note:" (gcc) or
               before ": error:" (clang). */
            q = gcc ? line : start;
            note = strstr(q, gcc ? ": note: " : ": error: ");
            n = note != NULL ? (size_t)(note - q) : 0;
            if (n == 0 || n >= place_room || memchr(q, '\n', n) != NULL)
                return 0;
            memcpy(place, q, n);
            place[n] = '\0';
            return 1;
        }
        p = line + length;
    }
    return 0;
}

/*
 * The hint after the quote: when every error is a warning -Werror made
 * fatal, that the course wants code without warnings; when a plain error
 * is among them, that this one (quoted, as it may be past the quoted
 * lines) is the thing to fix: the warnings alone would not stop it.
 */
static rayo_status explain_errors(rayo_grade_item *item, const char *errors,
                                  rayo_error *err)
{
    const char *werror, *plain, *line;
    size_t length = 0;
    find_errors(errors, &werror, &plain);
    if (werror == NULL)
        return RAYO_OK;
    if (plain == NULL) {
        const char *hint = werror_hint(werror, &length);
        if (hint == NULL)
            return RAYO_OK;
        return grade_say(item, err, "a warning (%.*s) that -Werror turns "
                                    "into an error: the course requires "
                                    "code without warnings",
                         (int)length, hint);
    }
    length = line_at(errors, plain, &line);
    {
        char name[64], place[256], clean[256];
        if (macro_use(line, name, sizeof name, place, sizeof place)) {
            harness_clean(place, strlen(place), clean, sizeof clean);
            return grade_say(item, err, "the first real error is at %s, "
                                        "where the name %s is one of the "
                                        "file's macros (#define %s): the "
                                        "preprocessor puts the macro's "
                                        "value in its place, so a "
                                        "parameter or a variable cannot "
                                        "have that name; rename it",
                             clean, name, name);
        }
    }
    while (length > 0 && (line[0] == ' ' || line[0] == '\t')) {
        line++;
        length--;
    }
    return grade_say(item, err, "the first real error, not a warning, is "
                                "the one to fix first: %.*s%s",
                     (int)(length > SHOWN_ERROR ? SHOWN_ERROR : length),
                     line, length > SHOWN_ERROR ? "..." : "");
}

/* The device an "#include" named, from the compiler's "fatal error:
   /dev/NAME: ..." line (gcc) or "fatal error: '/dev/NAME' file not
   found" (clang): its start and length, or NULL. */
static const char *device_named(const char *errors, size_t *length)
{
    const char *p = strstr(errors, "fatal error: /dev/");
    const char *quoted = strstr(errors, "fatal error: '/dev/");
    if (p == NULL && quoted == NULL)
        return NULL;
    p = p != NULL ? p + strlen("fatal error: ")
                  : quoted + strlen("fatal error: '");
    *length = strcspn(p, ":' \n");
    if (*length > 40)
        *length = 40;
    return p;
}

/* When a limit stopped the compile: the line that says which; RAYO_OK
   and *said 0 when none did. */
static rayo_status say_limit(grade_context *ctx, const grade_captured *got,
                             const char *errors, int *said, rayo_error *err)
{
    const rayo_grade_options *o = ctx->options;
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_COMPILE];
    const char *device;
    size_t length = 0;
    *said = 1;
    if (got->memory_exceeded || strstr(errors, "out of memory") != NULL ||
        strstr(errors, "memory exhausted") != NULL)
        return grade_fail(item, err, "memory limit exceeded: the compiler "
                                     "used more than %llu MiB and was "
                                     "stopped",
                          (unsigned long long)(o->memory >> 20));
    device = device_named(errors, &length);
    if (device != NULL)
        return grade_fail(item, err, "it includes a device (%.*s): the "
                                     "compiler sees no device but /dev/null",
                          (int)length, device);
    if (strstr(errors, "File size limit exceeded") != NULL ||
        strstr(errors, "No space left on device") != NULL ||
        (got->outcome.ending == GRADE_SIGNALED &&
         got->outcome.status == SIGXFSZ))
        return grade_fail(item, err, "disk limit exceeded: the compiler's "
                                     "output grew past %llu MiB and was "
                                     "stopped (an enormous initialised "
                                     "array?)",
                          (unsigned long long)(o->output_limit >> 20));
    if (strstr(errors, "CPU time limit exceeded") != NULL ||
        (got->outcome.ending == GRADE_SIGNALED &&
         got->outcome.status == SIGXCPU))
        return grade_fail(item, err, "CPU time limit exceeded: the compiler "
                                     "worked for more than %g s and was "
                                     "stopped",
                          o->cpu > 10 ? o->cpu : 10);
    *said = 0;
    return RAYO_OK;
}

static rayo_status explain_failure(grade_context *ctx,
                                   const grade_captured *got,
                                   const char *errors, char *const *argv,
                                   rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_COMPILE];
    rayo_status status;
    int said = 0;
    if (got->outcome.ending == GRADE_TIMED_OUT)
        status = grade_fail(item, err, "the compiler did not finish in "
                                       "%.0f seconds", COMPILE_SECONDS);
    else {
        status = say_limit(ctx, got, errors, &said, err);
        if (status == RAYO_OK)
            status = said ? grade_say(item, err, "the compiler says:")
                          : grade_fail(item, err, "does not compile with "
                                                  "the course's flags; the "
                                                  "compiler says:");
    }
    if (status == RAYO_OK)
        status = grade_quote(item, errors, QUOTED_LINES, err);
    if (status == RAYO_OK && !said)
        status = explain_errors(item, errors, err);
    if (status == RAYO_OK)
        status = say_command(ctx, item, argv, err);
    return status;
}

rayo_status grade_step_compile(grade_context *ctx, rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_COMPILE];
    size_t count = COURSE_FLAGS + 4 + ctx->source_count, i, n = 0;
    const char **words = malloc(count * sizeof *words);
    char **argv = NULL;
    const char *errors;
    grade_limits limits = grade_compiler_limits(ctx->options,
                                                COMPILE_SECONDS);
    grade_run run;
    grade_captured got;
    rayo_status status = RAYO_ERR_NOMEM;

    memset(&got, 0, sizeof got);
    {
        /* Found before forking: a failed exec looks different under
           debuggers and valgrind. */
        char *found = grade_which(ctx->cc[0]);
        if (found == NULL) {
            free(words);
            return grade_fail(item, err, "could not run the compiler '%s': "
                                         "not found or not executable (set "
                                         "CC or --cc)",
                              ctx->cc[0]);
        }
        free(found);
    }
    ctx->program = grade_path_join(ctx->dir, "programa");
    if (words == NULL || ctx->program == NULL) {
        rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
        goto done;
    }
    for (i = 0; i < COURSE_FLAGS; i++)
        words[n++] = course_flags[i];
    words[n++] = "-g";
    words[n++] = "-o";
    words[n++] = ctx->program;
    for (i = 0; i < ctx->source_count; i++)
        words[n++] = ctx->compiled[i];
    words[n++] = "-lm";
    argv = grade_cc_argv(ctx, words, n);
    if (argv == NULL) {
        rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
        goto done;
    }
    run = grade_tool_run(argv);
    status = grade_spawn(ctx, &run, &limits, &got, err);
    if (status != RAYO_OK)
        goto done;
    errors = got.errors != NULL ? got.errors : "";
    if (got.outcome.ending == GRADE_EXITED && got.outcome.status == 0) {
        item->result = RAYO_GRADE_PASS;
        status = say_command(ctx, item, argv, err);
        if (status == RAYO_OK && errors[0] != '\0')
            status = grade_warn(item, err, "warning: the compiler printed "
                                          "messages but succeeded:");
        if (status == RAYO_OK && errors[0] != '\0')
            status = grade_quote(item, errors, QUOTED_LINES, err);
    } else {
        status = explain_failure(ctx, &got, errors, argv, err);
        free(ctx->program);
        ctx->program = NULL;
    }
done:
    grade_captured_free(&got);
    free(argv);
    free(words);
    return status;
}
