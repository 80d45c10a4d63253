/*
 * grade_names.c - splitting flat files' names by student, and students'
 * names made into file names (see grade_names.h).
 *
 * The split is quadratic in the number of files (each file's splits are
 * counted against every file): a class is a few hundred files.  Why the
 * class decides: "ana_perez_main.c" alone cannot say whether the student
 * is "ana" or "ana_perez", but beside "beto_main.c" the shared own name
 * "main.c" can (docs/grading.md has the examples).
 */
#define _POSIX_C_SOURCE 200809L

#include "grade_names.h"

#include <stdio.h>
#include <string.h>

#include "cli.h"

#define SAFE_MAX 80

static int ends_with(const char *s, const char *end)
{
    size_t n = strlen(s), m = strlen(end);
    return n > m && strcmp(s + n - m, end) == 0;
}

int cli_is_source_name(const char *s)
{
    return s[0] != '.' && (ends_with(s, ".c") || ends_with(s, ".h"));
}

/* Whether entry splits at i into a name and a source's own name. */
int cli_flat_splits_at(const char *entry_name, size_t i)
{
    return i > 0 && (entry_name[i] == '_' || entry_name[i] == '-') &&
           cli_is_source_name(entry_name + i + 1);
}

/* How many files have own as the own name of one of their splits. */
static size_t own_count(const cli_flat_file *f, size_t count, const char *own)
{
    size_t k, i, total = 0;
    for (k = 0; k < count; k++) {
        const char *s = f[k].entry;
        for (i = 0; s[i] != '\0'; i++)
            if (cli_flat_splits_at(s, i) && strcmp(s + i + 1, own) == 0) {
                total++;
                break;
            }
    }
    return total;
}

/* How many files split into the name s[0..n) and an own name. */
static size_t name_count(const cli_flat_file *f, size_t count, const char *s,
                         size_t n)
{
    size_t k, total = 0;
    for (k = 0; k < count; k++)
        if (strlen(f[k].entry) > n && strncmp(f[k].entry, s, n) == 0 &&
            cli_flat_splits_at(f[k].entry, n))
            total++;
    return total;
}

/* How many files other than f[skip] took the name s[0..n). */
static size_t name_taken(const cli_flat_file *f, size_t count, size_t skip,
                         const char *s, size_t n)
{
    size_t k, total = 0;
    for (k = 0; k < count; k++)
        if (k != skip && f[k].prefix == n &&
            strncmp(f[k].entry, s, n) == 0)
            total++;
    return total;
}

/* Each file's split, by the class's most shared own names. */
void cli_flat_split(cli_flat_file *f, size_t count)
{
    size_t k, i;
    for (k = 0; k < count; k++) {
        const char *s = f[k].entry;
        size_t best = 0, best_own = 0, best_name = 0;
        if (f[k].fixed)
            continue;
        for (i = 0; s[i] != '\0'; i++) {
            size_t own, name;
            if (!cli_flat_splits_at(s, i))
                continue;
            own = own_count(f, count, s + i + 1);
            name = name_count(f, count, s, i);
            /* ties: the longer name */
            if (own > best_own || (own == best_own && name >= best_name)) {
                best = i;
                best_own = own;
                best_name = name;
            }
        }
        f[k].prefix = best;
        f[k].own = s + best + 1;
    }
    /* A file whose own name no other file shares, and whose name no
       other file took, joins a name that others took. */
    for (k = 0; k < count; k++) {
        const char *s = f[k].entry;
        size_t best = 0;
        if (f[k].fixed || f[k].own == NULL ||
            own_count(f, count, f[k].own) > 1 ||
            name_taken(f, count, k, s, f[k].prefix) > 0)
            continue;
        for (i = 0; s[i] != '\0'; i++)
            if (i != f[k].prefix && cli_flat_splits_at(s, i) &&
                name_taken(f, count, k, s, i) > 0)
                best = i;
        if (best > 0) {
            f[k].prefix = best;
            f[k].own = s + best + 1;
        }
    }
}


void cli_safe_file_name(const char *name, char *out, size_t room)
{
    size_t used = 0;
    const unsigned char *p = (const unsigned char *)name;
    if (room > SAFE_MAX + 1)
        room = SAFE_MAX + 1;
    while (*p != '\0' && used + 1 < room) {
        size_t n = p[0] >= 0x80 ? cli_utf8_sequence(p) : 0;
        /* U+00C0 to U+024F: the accented Latin letters (but the
           multiplication and division signs). */
        if (n == 2 && p[0] >= 0xC3 && p[0] <= 0xC9 &&
            !(p[0] == 0xC3 && (p[1] == 0x97 || p[1] == 0xB7))) {
            if (used + 3 > room)
                break;
            memcpy(out + used, p, 2);
            used += 2;
            p += 2;
            continue;
        }
        if ((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') ||
            (*p >= '0' && *p <= '9') || *p == '-' || *p == '_' ||
            (*p == '.' && used > 0))
            out[used++] = (char)*p;
        else if (used == 0 || out[used - 1] != '_')
            out[used++] = '_';
        p += n > 0 ? n : 1;
    }
    out[used] = '\0';
    if (used == 0 || strcmp(out, "_") == 0)
        snprintf(out, room, "student");
}
