/*
 * t_lang.c - languages (lang.h): the choice from locale names and the
 * environment, --lang's parsing, translations and plural forms looked up
 * in the embedded Spanish catalog, plural rules of other languages, and
 * numbers with the language's decimal separator.
 *
 * The translations expected are po/es.po's own words, typed here again;
 * the plural rules are checked against the forms those languages' rules
 * give by hand (Polish's few/many, Slovenian's four forms).
 */
#define _POSIX_C_SOURCE 200809L

#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

#include "../../src/core/catalog.h"

static void environment(const char *language, const char *lc_all,
                        const char *lc_messages, const char *lang)
{
    const char *names[] = {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"};
    const char *values[] = {language, lc_all, lc_messages, lang};
    int i;
    for (i = 0; i < 4; i++) {
        if (values[i] == NULL)
            unsetenv(names[i]);
        else
            setenv(names[i], values[i], 1);
    }
}

static long plural(const char *rule, unsigned long n)
{
    return rayo_plural_form(rule, strlen(rule), n);
}

typedef struct lookup {
    rayo_lang lang;
    int same; /* every lookup gave the expected text */
} lookup;

static void *look_up_many(void *context)
{
    lookup *l = context;
    const char *want = l->lang == RAYO_LANG_ES
                           ? "render: no hay memoria suficiente"
                           : "render: out of memory";
    int i;
    l->same = 1;
    for (i = 0; i < 20000; i++)
        if (strcmp(rayo_gettext(l->lang, "render: out of memory"), want) != 0)
            l->same = 0;
    return NULL;
}

int main(void)
{
    static const char slavic[] =
        "(n==1 ? 0 : n%10>=2 && n%10<=4 && (n%100<10 || n%100>=20) ? 1 : 2)";
    static const char slovenian[] =
        "(n%100==1 ? 0 : n%100==2 ? 1 : n%100==3 || n%100==4 ? 2 : 3);";
    static const char sing[] = "'%.*s…' (%lu character)";
    static const char plur[] = "'%.*s…' (%lu characters)";
    rayo_lang lang = RAYO_LANG_EN;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    char number[RAYO_LANG_NUMBER_SIZE];
    const char *msgid = "render: out of memory";
    lookup a = {RAYO_LANG_ES, 0}, b = {RAYO_LANG_EN, 0};
    pthread_t ta, tb;

    /* locale names */
    ok(rayo_lang_from_locale("es", &lang) && lang == RAYO_LANG_ES, "es");
    ok(rayo_lang_from_locale("es_AR.UTF-8", &lang) && lang == RAYO_LANG_ES,
       "es_AR.UTF-8");
    ok(rayo_lang_from_locale("es@euro", &lang) && lang == RAYO_LANG_ES,
       "es@euro");
    ok(rayo_lang_from_locale("en_GB", &lang) && lang == RAYO_LANG_EN,
       "en_GB");
    ok(!rayo_lang_from_locale("est", &lang), "est is not Spanish");
    ok(!rayo_lang_from_locale("C", &lang), "C names no language");
    ok(!rayo_lang_from_locale("", &lang), "the empty name, none");
    ok(!rayo_lang_from_locale(NULL, &lang), "NULL, none");
    is_string(rayo_lang_code(RAYO_LANG_ES), "es", "the code of Spanish");
    ok(rayo_lang_parse("fr", &lang, &err) == RAYO_ERR_INVALID &&
           strstr(err.message, "'fr'") != NULL &&
           strstr(err.message, "es or en") != NULL,
       "--lang fr: refused, naming it and the codes");

    /* the environment, in gettext's order */
    environment(NULL, NULL, NULL, "es_AR.UTF-8");
    is_int(rayo_lang_from_environment(), RAYO_LANG_ES, "LANG=es_AR.UTF-8");
    environment(NULL, "C", NULL, "es_AR.UTF-8");
    is_int(rayo_lang_from_environment(), RAYO_LANG_EN, "LC_ALL=C wins");
    environment(NULL, "", "es_ES", "en_US");
    is_int(rayo_lang_from_environment(), RAYO_LANG_ES,
           "an empty LC_ALL is skipped; LC_MESSAGES=es_ES");
    environment("fr:es", "C", NULL, NULL);
    is_int(rayo_lang_from_environment(), RAYO_LANG_ES,
           "LANGUAGE=fr:es: its first known entry, even under C");
    environment("en", NULL, NULL, "es_AR.UTF-8");
    is_int(rayo_lang_from_environment(), RAYO_LANG_EN, "LANGUAGE=en wins");
    environment("de", NULL, NULL, "es_AR.UTF-8");
    is_int(rayo_lang_from_environment(), RAYO_LANG_ES,
           "LANGUAGE with no known entry: LANG decides");
    environment(NULL, NULL, NULL, NULL);
    is_int(rayo_lang_from_environment(), RAYO_LANG_EN, "nothing set");

    /* translations */
    ok(rayo_gettext(RAYO_LANG_EN, msgid) == msgid, "English: the msgid");
    is_string(rayo_gettext(RAYO_LANG_ES, msgid),
              "render: no hay memoria suficiente",
              "Spanish: the catalog's text");
    is_string(rayo_gettext(RAYO_LANG_ES, "no such message in the catalog"),
              "no such message in the catalog", "a message not there: itself");
    is_string(rayo_gettext(RAYO_LANG_ES, ""), "", "the empty msgid: itself");
    is_string(rayo_ngettext(RAYO_LANG_ES, sing, plur, 1),
              "'%.*s…' (%lu carácter)", "Spanish, 1: singular");
    is_string(rayo_ngettext(RAYO_LANG_ES, sing, plur, 0),
              "'%.*s…' (%lu caracteres)", "Spanish, 0: plural");
    is_string(rayo_ngettext(RAYO_LANG_ES, sing, plur, 100000),
              "'%.*s…' (%lu caracteres)", "Spanish, 100000: plural");
    ok(rayo_ngettext(RAYO_LANG_EN, sing, plur, 1) == sing, "English, 1");
    ok(rayo_ngettext(RAYO_LANG_EN, sing, plur, 2) == plur, "English, 2");
    is_string(rayo_ngettext(RAYO_LANG_ES, "one thing", "%lu things", 3),
              "%lu things", "a plural not in the catalog: English's form");

    /* plural rules */
    is_int(plural("(n != 1);", 0), 1, "n != 1, 0");
    is_int(plural("(n != 1);", 1), 0, "n != 1, 1");
    is_int(plural("nplurals", 1), -1, "not an expression: -1");
    is_int(plural("n +", 1), -1, "a cut expression: -1");
    is_int(plural("n / 0", 7), 0, "division by zero: 0");
    is_int(plural(slavic, 1), 0, "Polish, 1: one");
    is_int(plural(slavic, 3), 1, "Polish, 3: few");
    is_int(plural(slavic, 5), 2, "Polish, 5: many");
    is_int(plural(slavic, 12), 2, "Polish, 12: many");
    is_int(plural(slavic, 22), 1, "Polish, 22: few");
    is_int(plural(slavic, 112), 2, "Polish, 112: many");
    is_int(plural(slovenian, 101), 0, "Slovenian, 101: one");
    is_int(plural(slovenian, 202), 1, "Slovenian, 202: two");
    is_int(plural(slovenian, 4), 2, "Slovenian, 4: few");
    is_int(plural(slovenian, 11), 3, "Slovenian, 11: other");

    /* numbers */
    is_string(rayo_lang_decimal(RAYO_LANG_ES, 0.5, 1, number, sizeof number),
              "0,5", "0.5 in Spanish");
    is_string(rayo_lang_decimal(RAYO_LANG_EN, 0.5, 1, number, sizeof number),
              "0.5", "0.5 in English");
    is_string(rayo_lang_decimal(RAYO_LANG_ES, -12.3, 2, number,
                                sizeof number),
              "-12,30", "-12.3 to two places in Spanish");
    is_string(rayo_lang_decimal(RAYO_LANG_ES, 342, 0, number, sizeof number),
              "342", "a whole number: no separator");

    /* two threads, two languages, at once */
    pthread_create(&ta, NULL, look_up_many, &a);
    pthread_create(&tb, NULL, look_up_many, &b);
    pthread_join(ta, NULL);
    pthread_join(tb, NULL);
    ok(a.same && b.same, "Spanish and English looked up at once on two "
                         "threads");
    return tap_done();
}
