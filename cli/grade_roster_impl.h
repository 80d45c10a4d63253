/*
 * grade_roster_impl.h - what the two halves of the roster share: the
 * class folder's walk (grade_roster.c) lists the entries and hands each
 * to the student it makes (grade_roster_student.c), through a builder.
 * Private to cli/grade_roster*.c.
 */
#ifndef RAYO_CLI_GRADE_ROSTER_IMPL_H
#define RAYO_CLI_GRADE_ROSTER_IMPL_H

#include <stdlib.h>
#include <string.h>

#include "grade_names.h"
#include "grade_roster.h"
#include "grade_staging.h"

static inline char *copy_of(const char *s, size_t n)
{
    char *c = malloc(n + 1);
    if (c != NULL) {
        memcpy(c, s, n);
        c[n] = '\0';
    }
    return c;
}

static inline int ends_with(const char *s, const char *end)
{
    size_t n = strlen(s), m = strlen(end);
    return n > m && strcmp(s + n - m, end) == 0;
}

static inline int is_c_name(const char *s)
{
    return s[0] != '.' && ends_with(s, ".c");
}

/* Appends item (size bytes) to *array of *count, growing it. */
static inline int push(void *array, size_t *count, size_t size,
                       const void *item)
{
    void **a = array;
    char *grown;
    if (*count >= ((size_t)-1) / size / 2 - 1)
        return 0;
    grown = realloc(*a, (*count + 1) * size);
    if (grown == NULL)
        return 0;
    memcpy(grown + *count * size, item, size);
    *a = grown;
    (*count)++;
    return 1;
}

typedef struct entry {
    char *name;
    char kind; /* 'd' folder, 'f' regular file, 'o' anything else */
} entry;

/* The entries of dir but '.'-names, sorted, links followed; freed with
   roster_entries_free. */
rayo_status roster_list_entries(const char *dir, entry **list, size_t *count,
                                rayo_error *err);
void roster_entries_free(entry *list, size_t count);

/* The roster being built from the folder dir. */
typedef struct builder {
    const char *dir;
    cli_roster *roster;
    rayo_error *err;
} builder;

/* "DIR: out of memory"; and an entry of DIR left out, with the reason. */
rayo_status roster_nomem(builder *b);
rayo_status roster_leave_out(builder *b, const char *name, const char *why);

/* Whether a student called name[0..n) is in the roster already. */
int roster_taken(builder *b, const char *name, size_t n);

/* A new student called name (length n); NULL when out of memory. */
cli_student *roster_add_student(builder *b, const char *name, size_t n,
                                cli_layout layout);

/* The zip at path (shown as from) copied out into the student's folder;
   a refused zip is the student's problem, not the class's. */
rayo_status roster_add_zip(builder *b, cli_student *s, const char *path,
                           const char *from);

/* A folder of DIR: one student's, graded where it is, or its one zip,
   or (twice at most) its one subfolder when it holds nothing else. */
rayo_status roster_add_folder(builder *b, const char *name, size_t n,
                              cli_layout layout, const char *entry_name);

/* The flat files, grouped by name, copied under their own names. */
rayo_status roster_add_flat(builder *b, cli_flat_file *f, size_t count);

#endif
