/*
 * grade_roster.c - the students in a class's folder (see grade_roster.h).
 *
 * Each entry of the folder is looked at once, by its name and kind;
 * folders are graded where they are, and what must be copied (a zip's
 * sources, a student's flat files under their own names, so that
 * `#include "vector.h"` finds ana_vector.h) goes into one temporary
 * folder of rayo's, a subfolder per student, removed at the end.
 *
 * Flat files are grouped by grade_names.c's split of their names.  The
 * grouping is printed, so a teacher sees it before trusting the table.
 */
#define _POSIX_C_SOURCE 200809L

#include "grade_roster.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"
#include "grade_names.h"
#include "grade_staging.h"
#include "zip_read.h"

#define SAFE_MAX 80

/* ---- small helpers ---- */

static char *copy_of(const char *s, size_t n)
{
    char *c = malloc(n + 1);
    if (c != NULL) {
        memcpy(c, s, n);
        c[n] = '\0';
    }
    return c;
}

static int ends_with(const char *s, const char *end)
{
    size_t n = strlen(s), m = strlen(end);
    return n > m && strcmp(s + n - m, end) == 0;
}

static int is_c_name(const char *s)
{
    return s[0] != '.' && ends_with(s, ".c");
}

/* Appends item (size bytes) to *array of *count, growing it. */
static int push(void *array, size_t *count, size_t size, const void *item)
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

const char *cli_layout_name(cli_layout layout)
{
    switch (layout) {
    case CLI_LAYOUT_FOLDER: return N_("a folder");
    case CLI_LAYOUT_MOODLE: return N_("Moodle");
    case CLI_LAYOUT_CLASSROOM: return N_("a GitHub Classroom repository");
    case CLI_LAYOUT_ZIP: return N_("a zip file");
    case CLI_LAYOUT_FILES: return N_("files named by student");
    }
    return "unknown";
}

/* ---- the folder's entries ---- */

typedef struct entry {
    char *name;
    char kind; /* 'd' folder, 'f' regular file, 'o' anything else */
} entry;

static void entries_free(entry *list, size_t count)
{
    size_t i;
    for (i = 0; i < count; i++)
        free(list[i].name);
    free(list);
}

static int by_entry(const void *a, const void *b)
{
    return strcmp(((const entry *)a)->name, ((const entry *)b)->name);
}

/* The entries of dir but '.'-names, sorted, links followed. */
static rayo_status list_entries(const char *dir, entry **list,
                                size_t *count, rayo_error *err)
{
    DIR *d = opendir(dir);
    struct dirent *de;
    *list = NULL;
    *count = 0;
    if (d == NULL)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", dir,
                              strerror(errno));
    while ((de = readdir(d)) != NULL) {
        struct stat st;
        entry e;
        char *path;
        if (de->d_name[0] == '.')
            continue;
        path = cli_path_join(dir, de->d_name);
        e.name = strdup(de->d_name);
        if (path == NULL || e.name == NULL) {
            free(path);
            free(e.name);
            goto nomem;
        }
        e.kind = stat(path, &st) != 0 ? 'o'
                 : S_ISDIR(st.st_mode) ? 'd'
                 : S_ISREG(st.st_mode) ? 'f' : 'o';
        free(path);
        if (!push(list, count, sizeof e, &e)) {
            free(e.name);
            goto nomem;
        }
    }
    closedir(d);
    if (*count > 0)
        qsort(*list, *count, sizeof **list, by_entry);
    return RAYO_OK;
nomem:
    closedir(d);
    entries_free(*list, *count);
    *list = NULL;
    *count = 0;
    return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory", dir);
}

/* Moodle's "NAME_DIGITS_assignsubmission_KIND_REST": the name's length,
   the kind and the rest; 0 when s is not so named. */
static size_t moodle_name(const char *s, const char **kind,
                          const char **rest)
{
    const char *mark = strstr(s, "_assignsubmission_");
    const char *digits;
    if (mark == NULL || mark == s)
        return 0;
    digits = mark;
    while (digits > s && digits[-1] >= '0' && digits[-1] <= '9')
        digits--;
    if (digits == mark || digits - 1 <= s || digits[-1] != '_')
        return 0;
    *kind = mark + strlen("_assignsubmission_");
    *rest = strchr(*kind, '_');
    *rest = *rest != NULL ? *rest + 1 : *kind + strlen(*kind);
    return (size_t)(digits - 1 - s);
}

/* ---- building ---- */

typedef struct builder {
    const char *dir;
    cli_roster *roster;
    rayo_error *err;
} builder;

static rayo_status nomem(builder *b)
{
    return rayo_error_set(b->err, RAYO_ERR_NOMEM, "%s: out of memory",
                          b->dir);
}

static rayo_status leave_out(builder *b, const char *name, const char *why)
{
    cli_unplaced u;
    u.name = strdup(name);
    u.why = why;
    if (u.name == NULL || !push(&b->roster->unplaced,
                                &b->roster->unplaced_count, sizeof u, &u)) {
        free(u.name);
        return nomem(b);
    }
    return RAYO_OK;
}

/* Whether a student called name[0..n) is in the roster already. */
static int taken(builder *b, const char *name, size_t n)
{
    size_t i;
    for (i = 0; i < b->roster->count; i++)
        if (strlen(b->roster->students[i].name) == n &&
            strncmp(b->roster->students[i].name, name, n) == 0)
            return 1;
    return 0;
}

/* A new student called name (length n); NULL when out of memory. */
static cli_student *add_student(builder *b, const char *name, size_t n,
                                cli_layout layout)
{
    cli_roster *r = b->roster;
    cli_student s;
    char safe[SAFE_MAX + 16];
    size_t i, suffix = 1;
    memset(&s, 0, sizeof s);
    s.layout = layout;
    s.name = copy_of(name, n);
    if (s.name == NULL)
        return NULL;
    cli_safe_file_name(s.name, safe, SAFE_MAX + 1);
    for (i = 0; i < r->count; i++) {
        if (strcmp(r->students[i].safe, safe) == 0) {
            char base[SAFE_MAX + 1];
            cli_safe_file_name(s.name, base, sizeof base);
            snprintf(safe, sizeof safe, "%s-%zu", base, ++suffix);
            i = (size_t)-1; /* look again from the start */
        }
    }
    s.safe = strdup(safe);
    if (s.safe == NULL || !push(&r->students, &r->count, sizeof s, &s)) {
        free(s.name);
        free(s.safe);
        return NULL;
    }
    return &r->students[r->count - 1];
}

static int add_file(cli_student *s, const char *name)
{
    char *copy = strdup(name);
    if (copy == NULL || !push(&s->files, &s->file_count, sizeof copy, &copy)) {
        free(copy);
        return 0;
    }
    return 1;
}

/* A new folder of rayo's for the student's copied files. */
static rayo_status staged_folder(builder *b, cli_student *s)
{
    cli_roster *r = b->roster;
    if (r->staging == NULL) {
        const char *tmp = getenv("TMPDIR");
        char *pattern = cli_path_join(
            tmp != NULL && tmp[0] != '\0' ? tmp : "/tmp", "rayo-class.XXXXXX");
        if (pattern == NULL)
            return nomem(b);
        if (mkdtemp(pattern) == NULL) {
            rayo_status status = rayo_error_set(b->err, RAYO_ERR_IO,
                                                "%s: %s", pattern,
                                                strerror(errno));
            free(pattern);
            return status;
        }
        r->staging = pattern;
    }
    s->folder = cli_path_join(r->staging, s->safe);
    if (s->folder == NULL)
        return nomem(b);
    if (mkdir(s->folder, 0700) != 0)
        return rayo_error_set(b->err, RAYO_ERR_IO, "%s: %s", s->folder,
                              strerror(errno));
    return RAYO_OK;
}

/* The zip at path (shown as from) copied out into the student's folder;
   a refused zip is the student's problem, not the class's. */
static rayo_status add_zip(builder *b, cli_student *s, const char *path,
                           const char *from)
{
    char **names = NULL;
    size_t count = 0, others = 0, i;
    rayo_error zip_err = RAYO_ERROR_INIT(cli_lang());
    rayo_status status = staged_folder(b, s);
    if (status != RAYO_OK)
        return status;
    if (!add_file(s, from))
        return nomem(b);
    rayo_error_clear(&zip_err);
    status = cli_zip_extract_sources(path, s->folder, &names, &count,
                                     &others, &zip_err);
    if (status == RAYO_ERR_NOMEM)
        return nomem(b);
    if (status != RAYO_OK) {
        s->problem = strdup(zip_err.message);
        return s->problem != NULL ? RAYO_OK : nomem(b);
    }
    for (i = 0; i < count && status == RAYO_OK; i++)
        if (!add_file(s, names[i]))
            status = nomem(b);
    rayo_grade_paths_free(names, count);
    return status;
}

/* What a student's folder holds: its entries, how many C sources and
   zips, its one zip's and its one subfolder's names. */
typedef struct folder_look {
    entry *inside;
    size_t count, sources, zips, folders;
    const char *zip, *folder;
} folder_look;

static rayo_status look_into(builder *b, const char *path, folder_look *l)
{
    size_t i;
    memset(l, 0, sizeof *l);
    /* A folder that cannot be listed is graded all the same, and the
       grading says why it failed. */
    if (list_entries(path, &l->inside, &l->count, b->err) == RAYO_ERR_NOMEM)
        return RAYO_ERR_NOMEM;
    rayo_error_clear(b->err);
    for (i = 0; i < l->count; i++) {
        const char *name = l->inside[i].name;
        if (l->inside[i].kind == 'd' && l->folders++ == 0)
            l->folder = name;
        if (l->inside[i].kind != 'f')
            continue;
        l->sources += is_c_name(name);
        if (ends_with(name, ".zip") && l->zips++ == 0)
            l->zip = name;
    }
    return RAYO_OK;
}

/* A folder of DIR: one student's, graded where it is, or its one zip,
   or (twice at most) its one subfolder when it holds nothing else. */
static rayo_status add_folder(builder *b, const char *name, size_t n,
                              cli_layout layout, const char *entry_name)
{
    char *path = cli_path_join(b->dir, entry_name);
    char *shown_as = strdup(entry_name);
    folder_look l;
    size_t i, depth;
    cli_student *s = add_student(b, name, n, layout);
    rayo_status status;
    if (path == NULL || shown_as == NULL || s == NULL) {
        free(path);
        free(shown_as);
        return nomem(b);
    }
    for (depth = 0;; depth++) {
        char *deeper, *deeper_shown;
        if (look_into(b, path, &l) != RAYO_OK) {
            free(path);
            free(shown_as);
            return RAYO_ERR_NOMEM;
        }
        if (depth == 2 || l.sources > 0 || l.zips > 0 || l.folders != 1)
            break;
        deeper = cli_path_join(path, l.folder);
        deeper_shown = cli_path_join(shown_as, l.folder);
        entries_free(l.inside, l.count);
        free(path);
        free(shown_as);
        path = deeper;
        shown_as = deeper_shown;
        if (path == NULL || shown_as == NULL) {
            free(path);
            free(shown_as);
            return nomem(b);
        }
    }
    if (l.sources == 0 && l.zips == 1) {
        char *zip_path = cli_path_join(path, l.zip);
        char *from = cli_path_join(shown_as, l.zip);
        status = zip_path != NULL && from != NULL
                     ? add_zip(b, s, zip_path, from) : nomem(b);
        free(zip_path);
        free(from);
    } else {
        status = RAYO_OK;
        s->folder = path;
        path = NULL;
        for (i = 0; i < l.count && status == RAYO_OK; i++) {
            char *file;
            if (l.inside[i].kind != 'f' ||
                !cli_is_source_name(l.inside[i].name))
                continue;
            file = cli_path_join(shown_as, l.inside[i].name);
            if (file == NULL || !add_file(s, file))
                status = nomem(b);
            free(file);
        }
    }
    entries_free(l.inside, l.count);
    free(path);
    free(shown_as);
    return status;
}

/* The prefix, up to and with a '-', that every plain folder shares
   (GitHub Classroom's "assignment-name-"); 0 when there is none. */
static size_t classroom_prefix(const entry *list, size_t count)
{
    const char *first = NULL;
    size_t shared = 0, folders = 0, i;
    for (i = 0; i < count; i++) {
        const char *kind, *rest;
        size_t n = 0;
        if (list[i].kind != 'd' || moodle_name(list[i].name, &kind, &rest))
            continue;
        folders++;
        if (first == NULL) {
            first = list[i].name;
            shared = strlen(first);
            continue;
        }
        while (n < shared && first[n] == list[i].name[n])
            n++;
        shared = n;
    }
    if (folders < 2)
        return 0;
    while (shared > 0 && first[shared - 1] != '-')
        shared--;
    /* Every name must keep something after the prefix. */
    for (i = 0; i < count; i++)
        if (list[i].kind == 'd' && strlen(list[i].name) <= shared)
            return 0;
    return shared;
}

/* ---- files named by student ---- */

/* The flat files, grouped by name, copied under their own names. */
static rayo_status add_flat(builder *b, cli_flat_file *f, size_t count)
{
    size_t k, j;
    cli_flat_split(f, count);
    for (k = 0; k < count; k++) {
        cli_student *s;
        char *name, *from;
        rayo_status status = RAYO_OK;
        if (f[k].own == NULL)
            continue; /* already placed with an earlier file */
        name = copy_of(f[k].entry, f[k].prefix);
        if (name == NULL)
            return nomem(b);
        if (taken(b, name, strlen(name))) {
            free(name);
            for (j = k; j < count; j++)
                if (f[j].own != NULL && f[j].prefix == f[k].prefix &&
                    strncmp(f[j].entry, f[k].entry, f[k].prefix) == 0) {
                    if (leave_out(b, f[j].entry, "the student has a "
                                  "folder or zip file too") != RAYO_OK)
                        return RAYO_ERR_NOMEM;
                    if (j != k)
                        f[j].own = NULL;
                }
            f[k].own = NULL;
            continue;
        }
        s = add_student(b, name, strlen(name),
                        f[k].fixed ? CLI_LAYOUT_MOODLE : CLI_LAYOUT_FILES);
        free(name);
        if (s == NULL || (status = staged_folder(b, s)) != RAYO_OK)
            return s == NULL ? nomem(b) : status;
        for (j = k; j < count && status == RAYO_OK; j++) {
            if (f[j].own == NULL || f[j].prefix != f[k].prefix ||
                strncmp(f[j].entry, f[k].entry, f[k].prefix) != 0)
                continue;
            from = cli_path_join(b->dir, f[j].entry);
            if (from == NULL)
                return nomem(b);
            if (cli_copy_source(from, s->folder, f[j].own))
                status = add_file(s, f[j].entry) ? RAYO_OK : nomem(b);
            else
                status = leave_out(b, f[j].entry, errno == EEXIST
                                   ? "the student has another file of "
                                     "that own name"
                                   : errno == EFBIG
                                   ? N_("larger than 1 MiB; expected a C "
                                        "source")
                                   : N_("it could not be copied"));
            free(from);
            if (j != k)
                f[j].own = NULL;
        }
        f[k].own = NULL;
        if (status != RAYO_OK)
            return status;
        if (s->file_count == 0 &&
            (s->problem = strdup("none of the student's files could be "
                                 "copied")) == NULL)
            return nomem(b);
    }
    return RAYO_OK;
}

/* ---- the class ---- */

/* A file of DIR: a zip, a flat source, or left out. */
static rayo_status add_entry_file(builder *b, const entry *e,
                                  cli_flat_file **flat,
                                  size_t *flat_count)
{
    const char *kind = NULL, *rest = NULL;
    size_t n = moodle_name(e->name, &kind, &rest);
    cli_flat_file f;
    memset(&f, 0, sizeof f);
    f.entry = e->name;
    if (n > 0 && strncmp(kind, "file_", 5) != 0)
        return leave_out(b, e->name, "Moodle's online text, not a file");
    if (ends_with(e->name, ".zip")) {
        char *path = cli_path_join(b->dir, e->name);
        cli_student *s;
        rayo_status status;
        if (n == 0)
            n = strlen(e->name) - 4;
        if (path == NULL)
            return nomem(b);
        if (taken(b, e->name, n)) {
            free(path);
            return leave_out(b, e->name, "a second submission of the same "
                             "student");
        }
        s = add_student(b, e->name, n, n == strlen(e->name) - 4
                                           ? CLI_LAYOUT_ZIP
                                           : CLI_LAYOUT_MOODLE);
        status = s != NULL ? add_zip(b, s, path, e->name) : nomem(b);
        free(path);
        return status;
    }
    if (n > 0 && cli_is_source_name(rest)) {
        f.prefix = n;
        f.own = rest;
        f.fixed = 1;
    } else if (n > 0 || !cli_is_source_name(e->name)) {
        return leave_out(b, e->name, "not a C source, header or zip file");
    } else {
        size_t i;
        for (i = 0; e->name[i] != '\0' && !cli_flat_splits_at(e->name, i); i++)
            ;
        if (e->name[i] == '\0')
            return leave_out(b, e->name, "no student's name before the "
                             "file's own name; expected NAME_main.c");
    }
    return push(flat, flat_count, sizeof f, &f) ? RAYO_OK : nomem(b);
}

static int by_student(const void *a, const void *b)
{
    return strcmp(((const cli_student *)a)->name,
                  ((const cli_student *)b)->name);
}

static int by_unplaced(const void *a, const void *b)
{
    return strcmp(((const cli_unplaced *)a)->name,
                  ((const cli_unplaced *)b)->name);
}

rayo_status cli_roster_build(const char *dir, cli_roster *roster,
                             rayo_error *err)
{
    builder b;
    entry *list = NULL;
    cli_flat_file *flat = NULL;
    size_t count = 0, flat_count = 0, strip, i;
    rayo_status status;
    memset(roster, 0, sizeof *roster);
    b.dir = dir;
    b.roster = roster;
    b.err = err;
    status = list_entries(dir, &list, &count, err);
    if (status != RAYO_OK)
        return status;
    strip = classroom_prefix(list, count);
    for (i = 0; i < count && status == RAYO_OK; i++) {
        const entry *e = &list[i];
        const char *kind, *rest;
        size_t n;
        if (e->kind == 'f') {
            status = add_entry_file(&b, e, &flat, &flat_count);
        } else if (e->kind != 'd') {
            status = leave_out(&b, e->name, "not a file or a folder");
        } else if ((n = moodle_name(e->name, &kind, &rest)) > 0) {
            if (strncmp(kind, "file_", 5) != 0)
                status = leave_out(&b, e->name, "Moodle's online text, "
                                   "not a file");
            else if (taken(&b, e->name, n))
                status = leave_out(&b, e->name, "a second submission of "
                                   "the same student");
            else
                status = add_folder(&b, e->name, n, CLI_LAYOUT_MOODLE,
                                    e->name);
        } else {
            status = add_folder(&b, e->name + strip, strlen(e->name) - strip,
                                strip > 0 ? CLI_LAYOUT_CLASSROOM
                                          : CLI_LAYOUT_FOLDER,
                                e->name);
        }
    }
    if (status == RAYO_OK && flat_count > 0)
        status = add_flat(&b, flat, flat_count);
    free(flat);
    entries_free(list, count);
    if (status != RAYO_OK)
        return status;
    if (roster->count > 1)
        qsort(roster->students, roster->count, sizeof *roster->students,
              by_student);
    if (roster->unplaced_count > 1)
        qsort(roster->unplaced, roster->unplaced_count,
              sizeof *roster->unplaced, by_unplaced);
    if (roster->count == 0)
        return rayo_error_set(err, RAYO_ERR_INVALID, "%s: no submissions "
                              "inside; --each expects a folder, zip file "
                              "or files named NAME_main.c per student",
                              dir);
    return RAYO_OK;
}

void cli_roster_free(cli_roster *roster)
{
    size_t i;
    for (i = 0; i < roster->count; i++) {
        cli_student *s = &roster->students[i];
        free(s->name);
        free(s->safe);
        free(s->folder);
        rayo_grade_paths_free(s->files, s->file_count);
        free(s->problem);
    }
    free(roster->students);
    for (i = 0; i < roster->unplaced_count; i++)
        free(roster->unplaced[i].name);
    free(roster->unplaced);
    if (roster->staging != NULL)
        cli_remove_staging(roster->staging);
    free(roster->staging);
    memset(roster, 0, sizeof *roster);
}
