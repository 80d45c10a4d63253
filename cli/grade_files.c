/*
 * grade_files.c - the --csv and --gradescope files of `rayo grade`,
 * written whole or not at all (standard output for "-"): what they say
 * is grade_export.c's, made in memory first so that a grading stopped
 * halfway leaves no half file.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "grade_print.h"
#include "grade_request.h"
#include "output_guard.h"

int cli_grade_is_stdout(const char *path)
{
    return path != NULL && strcmp(path, "-") == 0;
}

/* text (size bytes) into path, whole or not at all; an exit status. */
static int write_whole(const char *path, const char *text, size_t size)
{
    rayo_output *out;
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    rayo_error_clear(&err);
    fflush(stdout);
    if (cli_output_open(&out, path, &err) != RAYO_OK)
        return cli_report(&err);
    if (rayo_output_write(out, text, size, &err) != RAYO_OK) {
        cli_output_abort(out);
        return cli_report(&err);
    }
    if (cli_output_commit(out, &err) != RAYO_OK)
        return cli_report(&err);
    return CLI_EXIT_OK;
}

FILE *cli_grade_export_start(char **text, size_t *size, const char *path)
{
    FILE *stream;
    *text = NULL;
    *size = 0;
    stream = open_memstream(text, size);
    if (stream == NULL)
        cli_sayf(_("%s: out of memory"), path);
    return stream;
}

int cli_grade_export_finish(FILE *stream, char **text, size_t *size,
                            const char *path)
{
    int status;
    if (fclose(stream) != 0 || *text == NULL) {
        free(*text);
        cli_sayf(_("%s: out of memory"), path);
        return CLI_EXIT_NOMEM;
    }
    status = write_whole(path, *text, *size);
    free(*text);
    return status;
}

int cli_grade_export_one(const grade_request *req, const char *student,
                         const rayo_grade_report *report, const rayo_error *err)
{
    const char *message = report == NULL ? err->message : NULL;
    int status = CLI_EXIT_OK;
    char *text;
    size_t size;
    FILE *stream;
    if (req->csv != NULL) {
        if ((stream = cli_grade_export_start(&text, &size, req->csv)) == NULL)
            return CLI_EXIT_NOMEM;
        cli_grade_csv_header(stream);
        cli_grade_csv_row(stream, student, report, message, &req->points);
        status = cli_grade_export_finish(stream, &text, &size, req->csv);
    }
    if (req->gradescope != NULL && status == CLI_EXIT_OK) {
        char line[600];
        if ((stream = cli_grade_export_start(&text, &size, req->gradescope)) ==
            NULL)
            return CLI_EXIT_NOMEM;
        cli_grade_gradescope(
            stream, report, message,
            report != NULL
                ? cli_grade_isolation_line(report->isolation, line, sizeof line)
                : NULL,
            &req->points);
        status = cli_grade_export_finish(stream, &text, &size, req->gradescope);
    }
    return status;
}

