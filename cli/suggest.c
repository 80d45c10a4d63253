/*
 * suggest.c - the nearest of a few known words to a mistyped one, for
 * "did you mean compare?" after an unknown command or exercise.
 *
 * The distance is Levenshtein's (one letter added, removed or changed
 * counts one; two neighbours swapped count one more), on bytes; a word
 * is suggested only when it is the one nearest and at most two edits
 * away, at most half of what was typed.  Words here are short names
 * (under 32 bytes); longer input is never near.
 */
#include <stdio.h>
#include <string.h>

#include "cli.h"

#define WORD_MAX 32

static size_t distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b), i, j;
    size_t d[WORD_MAX + 1][WORD_MAX + 1];
    if (la > WORD_MAX || lb > WORD_MAX)
        return (size_t)-1;
    for (i = 0; i <= la; i++)
        d[i][0] = i;
    for (j = 0; j <= lb; j++)
        d[0][j] = j;
    for (i = 1; i <= la; i++)
        for (j = 1; j <= lb; j++) {
            size_t best = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
            if (d[i - 1][j] + 1 < best)
                best = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < best)
                best = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] &&
                a[i - 2] == b[j - 1] && d[i - 2][j - 2] + 1 < best)
                best = d[i - 2][j - 2] + 1;
            d[i][j] = best;
        }
    return d[la][lb];
}

const char *cli_nearest(const char *word, const char *const *names,
                        size_t count)
{
    const char *best = NULL;
    size_t best_distance = (size_t)-1, i;
    int tie = 0;
    for (i = 0; i < count; i++) {
        size_t d = distance(word, names[i]);
        if (d < best_distance) {
            best = names[i];
            best_distance = d;
            tie = 0;
        } else if (d == best_distance) {
            tie = 1;
        }
    }
    if (best == NULL || tie || best_distance > 2 ||
        2 * best_distance > strlen(word))
        return NULL;
    return best;
}

int cli_unknown_exercise(const char *option, const char *text,
                         const char *const *names, size_t count)
{
    char list[256] = "";
    const char *nearest = cli_nearest(text, names, count);
    size_t i, used = 0;
    for (i = 0; i < count && used < sizeof list; i++)
        used += (size_t)snprintf(list + used, sizeof list - used, "%s%s",
                                 i > 0 ? ", " : "", names[i]);
    if (nearest != NULL)
        return cli_usage_error(_("%s: unknown exercise %s; did you mean %s? "
                                 "The exercises are %s"),
                               option, cli_quote(text), nearest, list);
    return cli_usage_error(_("%s: unknown exercise %s; the exercises are %s"),
                           option, cli_quote(text), list);
}
