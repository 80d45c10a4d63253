/*
 * grade_feedback.c - the grouping's lines and the students' report
 * files (see grade_feedback.h).
 *
 * Names come from the class's archive (folder names, file names, zip
 * entries): they go out through cli_sayf, which escapes control bytes
 * and cuts long lines, never raw.  The report files' names are made
 * from the student's name by grade_roster.c, never taken as they are.
 */
#define _POSIX_C_SOURCE 200809L

#include "grade_feedback.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "output_guard.h"

void cli_roster_say(const char *dir, const cli_roster *roster)
{
    size_t i, j;
    cli_sayf(_("%s: how the submissions were grouped (%zu in all)"), dir,
             roster->count);
    for (i = 0; i < roster->count; i++) {
        const cli_student *s = &roster->students[i];
        char *files = NULL;
        size_t size = 0;
        FILE *list = open_memstream(&files, &size);
        if (list == NULL)
            return;
        for (j = 0; j < s->file_count; j++)
            fprintf(list, "%s%s", j > 0 ? ", " : "", s->files[j]);
        if (s->file_count == 0)
            fputs(_("no C source"), list);
        if (fclose(list) != 0 || files == NULL) {
            free(files);
            return;
        }
        cli_sayf("%s (%s): %s", s->name, _(cli_layout_name(s->layout)),
                 files);
        free(files);
    }
    for (i = 0; i < roster->unplaced_count; i++)
        cli_sayf(_("left out: %s (%s)"), roster->unplaced[i].name,
                 _(roster->unplaced[i].why));
}

int cli_feedback_prepare(const char *dir)
{
    struct stat st;
    if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
        cli_sayf("--feedback: %s: %s", dir, strerror(errno));
        return CLI_EXIT_FAILURE;
    }
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        cli_sayf(_("--feedback: %s: not a folder; expected a folder for "
                   "the students' reports"), dir);
        return CLI_EXIT_USAGE;
    }
    return CLI_EXIT_OK;
}

int cli_feedback_write(const char *dir, const cli_student *student,
                       const char *text, size_t size)
{
    size_t room = strlen(dir) + strlen(student->safe) + 8;
    char *path = malloc(room);
    rayo_output *out;
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    int status = CLI_EXIT_OK;
    if (path == NULL) {
        cli_sayf(_("--feedback: %s: out of memory"), dir);
        return CLI_EXIT_FAILURE;
    }
    snprintf(path, room, "%s/%s.txt", dir, student->safe);
    rayo_error_clear(&err);
    if (cli_output_open(&out, path, &err) != RAYO_OK) {
        status = cli_report(&err);
    } else if (rayo_output_write(out, text, size, &err) != RAYO_OK) {
        cli_output_abort(out);
        status = cli_report(&err);
    } else if (cli_output_commit(out, &err) != RAYO_OK) {
        status = cli_report(&err);
    }
    free(path);
    return status;
}
