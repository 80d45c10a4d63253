/*
 * lang.c - naming and choosing a language: codes, --lang's parsing, the
 * environment's choice, and numbers written with the language's decimal
 * separator, and messages formatted with it (rayo_lang_vformat).
 *
 * The environment is read as gettext reads it, with one difference on
 * purpose: LANGUAGE counts even when the locale is "C" or not generated,
 * and no locale is ever set (setlocale would change every printf's
 * decimal point in the whole program, threads included).  The lookup of
 * translations is catalog.c's.
 */
#define _POSIX_C_SOURCE 200809L

#include "rayo/lang.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "format_point.h"

static const char *const codes[RAYO_LANG_COUNT] = {"en", "es"};

const char *rayo_lang_code(rayo_lang lang)
{
    return (unsigned)lang < RAYO_LANG_COUNT ? codes[lang] : codes[0];
}

int rayo_lang_from_locale(const char *name, rayo_lang *lang)
{
    size_t i;
    if (name == NULL)
        return 0;
    for (i = 0; i < RAYO_LANG_COUNT; i++) {
        size_t n = strlen(codes[i]);
        /* "es", "es_AR", "es.UTF-8", "es@euro"; not "est" */
        if (strncmp(name, codes[i], n) == 0 &&
            (name[n] == '\0' || name[n] == '_' || name[n] == '.' ||
             name[n] == '@')) {
            *lang = (rayo_lang)i;
            return 1;
        }
    }
    return 0;
}

rayo_status rayo_lang_parse(const char *text, rayo_lang *lang,
                            rayo_error *err)
{
    if (rayo_lang_from_locale(text, lang))
        return RAYO_OK;
    return rayo_error_set(err, RAYO_ERR_INVALID,
                          "'%.40s' is not a language rayo speaks; expected "
                          "es or en",
                          text);
}

/* The first entry of a LANGUAGE list that names a known language. */
static int from_language_list(const char *list, rayo_lang *lang)
{
    while (list != NULL && *list != '\0') {
        const char *colon = strchr(list, ':');
        size_t n = colon ? (size_t)(colon - list) : strlen(list);
        char entry[64];
        if (n > 0 && n < sizeof entry) {
            memcpy(entry, list, n);
            entry[n] = '\0';
            if (rayo_lang_from_locale(entry, lang))
                return 1;
        }
        list = colon ? colon + 1 : NULL;
    }
    return 0;
}

rayo_lang rayo_lang_from_environment(void)
{
    static const char *const variables[] = {"LC_ALL", "LC_MESSAGES", "LANG"};
    rayo_lang lang = RAYO_LANG_EN;
    size_t i;
    if (from_language_list(getenv("LANGUAGE"), &lang))
        return lang;
    for (i = 0; i < sizeof variables / sizeof variables[0]; i++) {
        const char *value = getenv(variables[i]);
        if (value != NULL && *value != '\0')
            return rayo_lang_from_locale(value, &lang) ? lang : RAYO_LANG_EN;
    }
    return RAYO_LANG_EN;
}

/* The decimal separator lang writes numbers with. */
static char decimal_point(rayo_lang lang)
{
    return lang == RAYO_LANG_ES ? ',' : '.';
}

char *rayo_lang_decimal(rayo_lang lang, double value, int decimals,
                        char *buffer, size_t room)
{
    char *point;
    if (room == 0)
        return buffer;
    if (decimals < 0)
        decimals = 0;
    if (decimals > 17)
        decimals = 17;
    snprintf(buffer, room, "%.*f", decimals, value);
    /* printf's separator is the C locale's '.' unless the program set
       another locale; either way it becomes the language's. */
    if ((point = strpbrk(buffer, ".,")) != NULL)
        *point = decimal_point(lang);
    return buffer;
}

void rayo_lang_vformat(rayo_lang lang, char *buffer, size_t room,
                       const char *format, va_list args)
{
    if (room == 0)
        return;
    if (decimal_point(lang) != '.')
        rayo_format_point(buffer, room, decimal_point(lang),
                          rayo_gettext(lang, format), args);
    else
        vsnprintf(buffer, room, rayo_gettext(lang, format), args);
}
