/*
 * t_status.c - errors in a language (status.h, rayo_lang_vformat in
 * lang.h): rayo_error_set looks its English format up in the error's
 * language, writes numbers with that language's decimal separator,
 * follows a translation's numbered arguments, and leaves English exactly
 * what vsnprintf writes; an error's language survives rayo_error_clear.
 *
 * The Spanish expected is po/es.po's own, typed here again; the
 * formatter's output is checked against snprintf's for the same format
 * and values, with only the decimal point changed.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

static char formatted[RAYO_ERROR_MESSAGE_SIZE];

/* rayo_lang_vformat into `formatted` (room bytes of it). */
static const char *vf(rayo_lang lang, size_t room, const char *format, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static const char *vf(rayo_lang lang, size_t room, const char *format, ...)
{
    va_list args;
    va_start(args, format);
    rayo_lang_vformat(lang, formatted, room, format, args);
    va_end(args);
    return formatted;
}

static void initialised(void)
{
    rayo_error es = RAYO_ERROR_INIT(RAYO_LANG_ES), zero;
    memset(&zero, 0, sizeof zero);
    ok(es.status == RAYO_OK && es.lang == RAYO_LANG_ES &&
           es.message[0] == '\0',
       "RAYO_ERROR_INIT: no failure, Spanish, an empty message");
    is_int(rayo_error_lang(&zero), RAYO_LANG_EN,
           "a zero-initialised error is English");
    is_int(rayo_error_lang(NULL), RAYO_LANG_EN, "no error: English");
    zero.lang = (rayo_lang)7;
    is_int(rayo_error_lang(&zero), RAYO_LANG_EN,
           "a language rayo does not know: English");
    rayo_error_init(&zero, RAYO_LANG_ES);
    is_int(rayo_error_lang(&zero), RAYO_LANG_ES, "rayo_error_init sets it");
    rayo_error_set(&zero, RAYO_ERR_INVALID, "render cancelled");
    rayo_error_clear(&zero);
    ok(zero.status == RAYO_OK && zero.message[0] == '\0' &&
           zero.lang == RAYO_LANG_ES,
       "rayo_error_clear empties the message and keeps the language");
    is_int(rayo_error_set(NULL, RAYO_ERR_LIMIT, "render cancelled"),
           RAYO_ERR_LIMIT, "rayo_error_set(NULL) returns the status");
}

#define RADIUS "sphere radius %g is not accepted; expected a finite number > 0"

static void both_languages(void)
{
    rayo_error en = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_error es = RAYO_ERROR_INIT(RAYO_LANG_ES);
    is_int(rayo_error_set(&es, RAYO_ERR_INVALID, RADIUS, -0.5),
           RAYO_ERR_INVALID, "rayo_error_set returns the status");
    is_int(es.status, RAYO_ERR_INVALID, "and records it");
    is_string(es.message,
              "no se acepta el radio de esfera -0,5; se esperaba un número "
              "finito > 0",
              "Spanish: the translation, with a decimal comma");
    rayo_error_set(&en, RAYO_ERR_INVALID, RADIUS, -0.5);
    is_string(en.message,
              "sphere radius -0.5 is not accepted; expected a finite number "
              "> 0",
              "English: the source's text, with a decimal point");
    rayo_error_set(&es, RAYO_ERR_FORMAT, "%s: not a regular file", "a.pbm");
    is_string(es.message, "a.pbm: no es un archivo común",
              "Spanish: an argument in its place");
    rayo_error_set(&es, RAYO_ERR_FORMAT,
                   "%s: byte %llu: found %s as coordinate %d of triangle "
                   "%llu's corner %d; expected a finite number",
                   "m.stl", 84ULL, "nan", 2, 7ULL, 3);
    is_string(es.message,
              "m.stl: byte 84: se encontró nan como coordenada 2 del vértice "
              "3 del triángulo 7; se esperaba un número finito",
              "Spanish: a translation's numbered arguments, reordered");
    rayo_error_set(&es, RAYO_ERR_INVALID,
                   "light colour (%g, %g, %g) is not accepted; expected "
                   "finite numbers >= 0",
                   0.5, -1.0, 0.25);
    is_string(es.message,
              "no se acepta el color de luz (0,5; -1; 0,25); se esperaban "
              "números finitos >= 0",
              "Spanish: three numbers, kept apart by semicolons");
    rayo_error_set(&es, RAYO_ERR_INVALID, "a message no catalog has: %g",
                   2.5);
    is_string(es.message, "a message no catalog has: 2,5",
              "a message without a translation: English, Spanish numbers");
}

/* "%2$s %1$g %2$s" in Spanish: numbered arguments, which ISO C's
   printf lacks (POSIX has them), so the compiler is not asked to check. */
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat"
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
#endif
static const char *numbered(void)
{
    return vf(RAYO_LANG_ES, sizeof formatted, "%2$s %1$g %2$s", 0.5, "x");
}
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic pop
#endif

/* The formatter against snprintf: the same text but the point. */
static void same_as_printf(void)
{
    char want[256];
    snprintf(want, sizeof want, "[%5d|%-4u|%02x|%lu|%lld|%zu|%c|%%|%.3s]",
             -42, 7u, 10u, 123456789UL, -5LL, (size_t)99, 'q', "abcdef");
    is_string(vf(RAYO_LANG_ES, sizeof formatted,
                 "[%5d|%-4u|%02x|%lu|%lld|%zu|%c|%%|%.3s]", -42, 7u, 10u,
                 123456789UL, -5LL, (size_t)99, 'q', "abcdef"),
              want, "integers, characters, strings: what snprintf writes");
    is_string(vf(RAYO_LANG_ES, sizeof formatted, "[%*d|%-*s|%.*s]", 4, 7,
                 3, "a", 2, "xyz"),
              "[   7|a  |xy]", "widths and precisions from arguments");
    is_string(vf(RAYO_LANG_ES, sizeof formatted, "[%*d]", -3, 5), "[5  ]",
              "a negative width from an argument pads on the right");
    is_string(vf(RAYO_LANG_ES, sizeof formatted, "%g %.3f %e %.1f %g",
                 0.125, 1.5, 1.5, -2.25, HUGE_VAL),
              "0,125 1,500 1,500000e+00 -2,2 inf",
              "%%g, %%f, %%e: a decimal comma; infinity has none");
    is_string(vf(RAYO_LANG_EN, sizeof formatted, "%g %.3f", 0.125, 1.5),
              "0.125 1.500", "English: a decimal point");
    is_string(numbered(), "x 0,5 x",
              "numbered arguments, one of them twice");
    is_string(vf(RAYO_LANG_ES, 10, "abcdef %g!", 1.25), "abcdef 1,",
              "cut to the room given, the comma still in place");
    is_string(vf(RAYO_LANG_EN, 10, "abcdef %g!", 1.25), "abcdef 1.",
              "English cut the same way");
    vf(RAYO_LANG_ES, 1, "%s", "abc");
    is_string(formatted, "", "room for the terminator only: empty");
}

int main(void)
{
    initialised();
    both_languages();
    same_as_printf();
    return tap_done();
}
