/*
 * lang.h - the language human text is written in, and the lookup of a
 * message's translation in it.
 *
 * Every message rayo shows a person exists in English (the text in the
 * source) and in each language of po/ (GNU gettext catalogs, compiled
 * into the library).  The language is a value passed to each call, never
 * a global or a locale: two threads may format in two languages at once,
 * and no generated system locale is needed.  Machine output (exit
 * statuses, JSON keys, verdict tokens, CSV headers) never goes through
 * here.  How a program picks the language (LANGUAGE, LC_ALL, LC_MESSAGES,
 * LANG, an option) is rayo_lang_from_environment's and the caller's
 * business; docs/i18n.md tells the whole story.  Valid C99.
 */
#ifndef RAYO_LANG_H
#define RAYO_LANG_H

#include <stdarg.h>
#include <stddef.h>

#include "rayo/export.h"
#include "rayo/lang_id.h"
#include "rayo/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* rayo_lang (RAYO_LANG_EN, RAYO_LANG_ES) and RAYO_LANG_COUNT: lang_id.h */

/* "en", "es": the code of the language, as --lang and po/ name it. */
RAYO_API const char *rayo_lang_code(rayo_lang lang);

/* "en" or "es" (also "en_US", "es_AR.UTF-8", ...) into *lang; anything
   else is RAYO_ERR_INVALID, naming the text and the accepted codes. */
RAYO_API rayo_status rayo_lang_parse(const char *text, rayo_lang *lang,
                                     rayo_error *err);

/*
 * The language a locale name asks for: 1 and *lang for a name starting
 * with a known code ("es", "es_AR.UTF-8", "en_GB"), 0 for anything else
 * ("C", "POSIX", "", "fr_FR", NULL).
 */
RAYO_API int rayo_lang_from_locale(const char *name, rayo_lang *lang);

/*
 * The language the environment asks for, as Unix programs read it: the
 * first known entry of LANGUAGE (a colon-separated list), else the first
 * of LC_ALL, LC_MESSAGES and LANG that is set and not empty; any es*
 * there gives Spanish, anything else English.  It needs no generated
 * locale and never calls setlocale.
 */
RAYO_API rayo_lang rayo_lang_from_environment(void);

/*
 * The translation of msgid into lang, or msgid itself (English, or a
 * message the catalog lacks).  The result lives as long as the program.
 * rayo_ngettext picks the plural form of count by the catalog's own
 * rule ("1 píxel", "2 píxeles"); without a translation, singular when
 * count is 1, else plural.  Both are safe from any thread.
 */
RAYO_API const char *rayo_gettext(rayo_lang lang, const char *msgid)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format_arg(2)))
#endif
    ;
RAYO_API const char *rayo_ngettext(rayo_lang lang, const char *singular,
                                   const char *plural, unsigned long count)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format_arg(2))) __attribute__((format_arg(3)))
#endif
    ;

/*
 * value with `decimals` digits after the separator (0 to 17) the way
 * lang writes numbers in text: "0.5" in English, "0,5" in Spanish.  No
 * grouping of thousands.  Into buffer (room bytes; RAYO_LANG_NUMBER_SIZE
 * always suffices for |value| < 1e30); returns buffer.
 */
#define RAYO_LANG_NUMBER_SIZE 64
RAYO_API char *rayo_lang_decimal(rayo_lang lang, double value, int decimals,
                                 char *buffer, size_t room);

/*
 * vsnprintf(buffer, room, rayo_gettext(lang, format), args), with the
 * numbers of floating-point conversions (%g, %.2f, ...) written with
 * lang's decimal separator: what rayo_error_set writes, for library code
 * that formats a message of its own before recording it.  Numbered
 * conversions (%2$s) of a translation are followed as printf does.
 * buffer is always terminated when room > 0.
 */
RAYO_API void rayo_lang_vformat(rayo_lang lang, char *buffer, size_t room,
                                const char *format, va_list args)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 4, 0)))
#endif
    ;

#ifdef __cplusplus
}
#endif

#endif
