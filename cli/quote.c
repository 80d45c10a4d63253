/*
 * quote.c - a value from the command line as a message quotes it: whole
 * and in apostrophes when it is short, else a short prefix and its
 * length ('77777777…' (100000 characters)), so that a mistyped value
 * of a megabyte does not fill the screen.
 *
 * The quote is raw text: cli_say escapes the whole message (escape.c),
 * control bytes included.  The prefix is cut between UTF-8 characters.
 * Not for file names (shown whole: a cut name cannot be found).
 */
#include <stdio.h>
#include <string.h>

#include "cli.h"

#define QUOTE_WHOLE_MAX 40 /* bytes quoted whole */
#define QUOTE_PREFIX 16    /* characters kept of a longer value */
#define QUOTE_SLOTS 4      /* quotes alive at once in one message */

/* Characters in s, counted as UTF-8 (a stray byte counts as one). */
static unsigned long characters(const char *s, size_t limit, size_t *bytes)
{
    unsigned long count = 0;
    size_t i = 0;
    while (s[i] != '\0' && count < limit) {
        size_t n = cli_utf8_sequence((const unsigned char *)s + i);
        i += n > 0 ? n : 1;
        count++;
    }
    if (bytes != NULL)
        *bytes = i;
    return count;
}

const char *cli_quote(const char *text)
{
    static char slots[QUOTE_SLOTS][QUOTE_WHOLE_MAX * 2 + 96];
    static unsigned next;
    char *out = slots[next++ % QUOTE_SLOTS];
    size_t prefix;
    unsigned long total;
    if (strlen(text) <= QUOTE_WHOLE_MAX) {
        snprintf(out, sizeof slots[0], "'%s'", text);
        return out;
    }
    characters(text, QUOTE_PREFIX, &prefix);
    total = characters(text, (size_t)-1, NULL);
    snprintf(out, sizeof slots[0],
             _n("'%.*s…' (%lu character)", "'%.*s…' (%lu characters)",
                total),
             (int)prefix, text, total);
    return out;
}
