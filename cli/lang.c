/*
 * lang.c - the language the command speaks: chosen once, at the start,
 * from --lang or the environment (rayo_lang_from_environment), and used
 * by every message through _() and _n() (cli.h).
 *
 * --lang is read here, before the subcommand parses its options, so
 * that --help and the very first error are already in the language
 * asked for; the subcommands' getopt tables accept it and ignore it.
 * Only the command has a language of its own: the library is told the
 * language in each call that formats text.
 */
#include <string.h>

#include "cli.h"

static rayo_lang current = RAYO_LANG_EN;

rayo_lang cli_lang(void)
{
    return current;
}

/* The value of a --lang at argv[i] ("--lang=es", or "--lang" "es"),
   *used set to the words it takes; NULL when argv[i] is not one. */
static const char *lang_value(int argc, char **argv, int i, int *used)
{
    static const char option[] = "--lang";
    size_t n = sizeof option - 1;
    if (strncmp(argv[i], option, n) != 0)
        return NULL;
    if (argv[i][n] == '=') {
        *used = 1;
        return argv[i] + n + 1;
    }
    if (argv[i][n] != '\0')
        return NULL;
    *used = 2;
    return i + 1 < argc ? argv[i + 1] : "";
}

int cli_lang_init(int *argc, char **argv)
{
    int i, used;
    current = rayo_lang_from_environment();
    for (i = 1; i < *argc && strcmp(argv[i], "--") != 0; i += used) {
        const char *value = lang_value(*argc, argv, i, &used);
        rayo_lang lang;
        if (value == NULL) {
            used = 1;
            continue;
        }
        if (*value == '\0')
            return cli_usage_error(_("--lang: needs a language; expected es "
                                     "or en"));
        if (!rayo_lang_from_locale(value, &lang))
            return cli_usage_error(_("--lang: %s is not a language rayo "
                                     "speaks; expected es or en"),
                                   cli_quote(value));
        current = lang;
    }
    /* `rayo --lang es compare ...`: the option before the command */
    if (*argc > 1 && lang_value(*argc, argv, 1, &used) != NULL) {
        memmove(argv + 1, argv + 1 + used,
                (size_t)(*argc - 1 - used + 1) * sizeof *argv);
        *argc -= used;
    }
    return CLI_EXIT_OK;
}
