/*
 * grade_roster_student.c - a student of a class's folder added to the
 * roster: a folder graded where it is (or its one zip, or the one
 * subfolder it wraps), a zip's sources copied out, or flat files named
 * by student grouped and copied under their own names, so that
 * `#include "vector.h"` finds ana_vector.h.  What must be copied goes
 * into one temporary folder of rayo's, a subfolder per student, removed
 * with the roster.  Which entry is which is grade_roster.c's.
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"
#include "grade_roster_impl.h"
#include "zip_read.h"

#define SAFE_MAX 80

rayo_status roster_nomem(builder *b)
{
    return rayo_error_set(b->err, RAYO_ERR_NOMEM, "%s: out of memory",
                          b->dir);
}

rayo_status roster_leave_out(builder *b, const char *name, const char *why)
{
    cli_unplaced u;
    u.name = strdup(name);
    u.why = why;
    if (u.name == NULL || !push(&b->roster->unplaced,
                                &b->roster->unplaced_count, sizeof u, &u)) {
        free(u.name);
        return roster_nomem(b);
    }
    return RAYO_OK;
}

int roster_taken(builder *b, const char *name, size_t n)
{
    size_t i;
    for (i = 0; i < b->roster->count; i++)
        if (strlen(b->roster->students[i].name) == n &&
            strncmp(b->roster->students[i].name, name, n) == 0)
            return 1;
    return 0;
}

cli_student *roster_add_student(builder *b, const char *name, size_t n,
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
            return roster_nomem(b);
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
        return roster_nomem(b);
    if (mkdir(s->folder, 0700) != 0)
        return rayo_error_set(b->err, RAYO_ERR_IO, "%s: %s", s->folder,
                              strerror(errno));
    return RAYO_OK;
}

rayo_status roster_add_zip(builder *b, cli_student *s, const char *path,
                           const char *from)
{
    char **names = NULL;
    size_t count = 0, others = 0, i;
    rayo_error zip_err = RAYO_ERROR_INIT(cli_lang());
    rayo_status status = staged_folder(b, s);
    if (status != RAYO_OK)
        return status;
    if (!add_file(s, from))
        return roster_nomem(b);
    rayo_error_clear(&zip_err);
    status = cli_zip_extract_sources(path, s->folder, &names, &count,
                                     &others, &zip_err);
    if (status == RAYO_ERR_NOMEM)
        return roster_nomem(b);
    if (status != RAYO_OK) {
        s->problem = strdup(zip_err.message);
        return s->problem != NULL ? RAYO_OK : roster_nomem(b);
    }
    for (i = 0; i < count && status == RAYO_OK; i++)
        if (!add_file(s, names[i]))
            status = roster_nomem(b);
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
    if (roster_list_entries(path, &l->inside, &l->count, b->err) ==
        RAYO_ERR_NOMEM)
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

rayo_status roster_add_folder(builder *b, const char *name, size_t n,
                              cli_layout layout, const char *entry_name)
{
    char *path = cli_path_join(b->dir, entry_name);
    char *shown_as = strdup(entry_name);
    folder_look l;
    size_t i, depth;
    cli_student *s = roster_add_student(b, name, n, layout);
    rayo_status status;
    if (path == NULL || shown_as == NULL || s == NULL) {
        free(path);
        free(shown_as);
        return roster_nomem(b);
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
        roster_entries_free(l.inside, l.count);
        free(path);
        free(shown_as);
        path = deeper;
        shown_as = deeper_shown;
        if (path == NULL || shown_as == NULL) {
            free(path);
            free(shown_as);
            return roster_nomem(b);
        }
    }
    if (l.sources == 0 && l.zips == 1) {
        char *zip_path = cli_path_join(path, l.zip);
        char *from = cli_path_join(shown_as, l.zip);
        status = zip_path != NULL && from != NULL
                     ? roster_add_zip(b, s, zip_path, from)
                     : roster_nomem(b);
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
                status = roster_nomem(b);
            free(file);
        }
    }
    roster_entries_free(l.inside, l.count);
    free(path);
    free(shown_as);
    return status;
}

rayo_status roster_add_flat(builder *b, cli_flat_file *f, size_t count)
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
            return roster_nomem(b);
        if (roster_taken(b, name, strlen(name))) {
            free(name);
            for (j = k; j < count; j++)
                if (f[j].own != NULL && f[j].prefix == f[k].prefix &&
                    strncmp(f[j].entry, f[k].entry, f[k].prefix) == 0) {
                    if (roster_leave_out(b, f[j].entry,
                                         "the student has a "
                                         "folder or zip file too") != RAYO_OK)
                        return RAYO_ERR_NOMEM;
                    if (j != k)
                        f[j].own = NULL;
                }
            f[k].own = NULL;
            continue;
        }
        s = roster_add_student(b, name, strlen(name),
                               f[k].fixed ? CLI_LAYOUT_MOODLE
                                          : CLI_LAYOUT_FILES);
        free(name);
        if (s == NULL || (status = staged_folder(b, s)) != RAYO_OK)
            return s == NULL ? roster_nomem(b) : status;
        for (j = k; j < count && status == RAYO_OK; j++) {
            if (f[j].own == NULL || f[j].prefix != f[k].prefix ||
                strncmp(f[j].entry, f[k].entry, f[k].prefix) != 0)
                continue;
            from = cli_path_join(b->dir, f[j].entry);
            if (from == NULL)
                return roster_nomem(b);
            if (cli_copy_source(from, s->folder, f[j].own))
                status = add_file(s, f[j].entry) ? RAYO_OK : roster_nomem(b);
            else
                status = roster_leave_out(
                    b, f[j].entry,
                    errno == EEXIST  ? "the student has another file of "
                                       "that own name"
                    : errno == EFBIG ? N_("larger than 1 MiB; expected a C "
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
            return roster_nomem(b);
    }
    return RAYO_OK;
}
