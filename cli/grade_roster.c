/*
 * grade_roster.c - the students in a class's folder (see grade_roster.h):
 * each entry of the folder looked at once, by its name and kind, and
 * handed to the student it makes (grade_roster_student.c): a folder,
 * Moodle's names, GitHub Classroom's shared prefix, a zip, or a flat
 * file named by student (grouped by grade_names.c's split of the
 * names).  The grouping is printed, so a teacher sees it before
 * trusting the table; what fits no shape is left out with its reason.
 */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <errno.h>
#include <sys/stat.h>

#include "cli.h"
#include "grade_roster_impl.h"

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

void roster_entries_free(entry *list, size_t count)
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

rayo_status roster_list_entries(const char *dir, entry **list, size_t *count,
                                rayo_error *err)
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
    roster_entries_free(*list, *count);
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
        return roster_leave_out(b, e->name, "Moodle's online text, not a file");
    if (ends_with(e->name, ".zip")) {
        char *path = cli_path_join(b->dir, e->name);
        cli_student *s;
        rayo_status status;
        if (n == 0)
            n = strlen(e->name) - 4;
        if (path == NULL)
            return roster_nomem(b);
        if (roster_taken(b, e->name, n)) {
            free(path);
            return roster_leave_out(b, e->name,
                                    "a second submission of the same "
                                    "student");
        }
        s = roster_add_student(b, e->name, n,
                               n == strlen(e->name) - 4 ? CLI_LAYOUT_ZIP
                                                        : CLI_LAYOUT_MOODLE);
        status =
            s != NULL ? roster_add_zip(b, s, path, e->name) : roster_nomem(b);
        free(path);
        return status;
    }
    if (n > 0 && cli_is_source_name(rest)) {
        f.prefix = n;
        f.own = rest;
        f.fixed = 1;
    } else if (n > 0 || !cli_is_source_name(e->name)) {
        return roster_leave_out(b, e->name,
                                "not a C source, header or zip file");
    } else {
        size_t i;
        for (i = 0; e->name[i] != '\0' && !cli_flat_splits_at(e->name, i); i++)
            ;
        if (e->name[i] == '\0')
            return roster_leave_out(b, e->name,
                                    "no student's name before the "
                                    "file's own name; expected NAME_main.c");
    }
    return push(flat, flat_count, sizeof f, &f) ? RAYO_OK : roster_nomem(b);
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
    status = roster_list_entries(dir, &list, &count, err);
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
            status = roster_leave_out(&b, e->name, "not a file or a folder");
        } else if ((n = moodle_name(e->name, &kind, &rest)) > 0) {
            if (strncmp(kind, "file_", 5) != 0)
                status = roster_leave_out(&b, e->name,
                                          "Moodle's online text, "
                                          "not a file");
            else if (roster_taken(&b, e->name, n))
                status = roster_leave_out(&b, e->name,
                                          "a second submission of "
                                          "the same student");
            else
                status = roster_add_folder(&b, e->name, n, CLI_LAYOUT_MOODLE,
                                           e->name);
        } else {
            status = roster_add_folder(
                &b, e->name + strip, strlen(e->name) - strip,
                strip > 0 ? CLI_LAYOUT_CLASSROOM : CLI_LAYOUT_FOLDER, e->name);
        }
    }
    if (status == RAYO_OK && flat_count > 0)
        status = roster_add_flat(&b, flat, flat_count);
    free(flat);
    roster_entries_free(list, count);
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
