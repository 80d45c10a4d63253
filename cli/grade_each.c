/*
 * grade_each.c - `rayo grade --each`: a class graded, one row of the
 * table (or one JSON object, one CSV row) a submission in the folders'
 * order, each student's report into --feedback's folder, then how many
 * passed and the class's summary (grade_tally.c).
 *
 * The folders are found by grade_roster.c and graded on threads by
 * grade_class.c; this file only lays the results out.  One folder that
 * cannot be graded is a row of its own and does not stop the class.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "grade_class.h"
#include "grade_feedback.h"
#include "grade_print.h"
#include "grade_request.h"
#include "grade_roster.h"
#include "grade_tally.h"
#include "interrupt.h"

#define STUDENT_COLUMNS 40 /* the widest the table's student column gets */

static void json_string(const char *s)
{
    cli_json_string(stdout, s);
}

static void print_table_header(size_t width, int scored)
{
    size_t c;
    cli_grade_print_column("student", width);
    for (c = 0; c < RAYO_GRADE_CRITERIA; c++)
        printf(" %-9s", rayo_grade_criterion_name(c));
    if (scored)
        printf(" %-9s", "score");
    printf(" result\n");
}

static void print_table_row(const char *student, size_t width,
                            const rayo_grade_report *r,
                            const cli_grade_points *points)
{
    size_t c;
    cli_grade_print_column(student, width);
    for (c = 0; c < RAYO_GRADE_CRITERIA; c++)
        printf(" %-9s", r->items[c].result == RAYO_GRADE_FAIL
                            ? "FAIL"
                            : rayo_grade_result_name(r->items[c].result));
    if (points != NULL) {
        char score[64];
        double max, got = cli_grade_score(r, points, &max);
        snprintf(score, sizeof score, "%.10g/%.10g", got, max);
        printf(" %-9s", score);
    }
    printf(" %s\n", rayo_grade_overall(r) == RAYO_GRADE_PASS ? "PASS"
                                                             : "FAIL");
}

/* The student column: as wide as the widest name (escaped), at least
   "student", at most STUDENT_COLUMNS (wider names are cut). */
static size_t student_width(const cli_roster *roster)
{
    size_t width = strlen("student"), i;
    for (i = 0; i < roster->count; i++) {
        size_t columns = cli_grade_escaped_columns(roster->students[i].name);
        if (columns > width)
            width = columns;
    }
    return width < STUDENT_COLUMNS ? width : STUDENT_COLUMNS;
}

/* What the class's table, JSON and CSV have so far. */
typedef struct class_printer {
    const grade_request *req;
    const cli_roster *roster;
    size_t width, passed, printed;
    int cancelled, quiet;
    int feedback_status;         /* the first failure writing a report */
    FILE *csv;                   /* the CSV rows, in memory */
    cli_tally tally;
} class_printer;

/* The student's report into --feedback's folder: the text one grading
   prints, or why it could not be graded. */
static void write_feedback(class_printer *p, const cli_student *student,
                           const rayo_grade_report *report,
                           const char *error)
{
    char *text = NULL;
    size_t size = 0;
    int status;
    FILE *stream = open_memstream(&text, &size);
    if (stream == NULL) {
        cli_sayf(_("--feedback: %s: out of memory"), p->req->feedback);
        status = CLI_EXIT_FAILURE;
    } else {
        if (report != NULL)
            cli_grade_print_text(stream, report);
        else
            fprintf(stream, "rayo grade could not grade this submission: "
                    "%s\n", error);
        if (fclose(stream) != 0 || text == NULL) {
            cli_sayf(_("--feedback: %s: out of memory"), p->req->feedback);
            status = CLI_EXIT_FAILURE;
        } else {
            status = cli_feedback_write(p->req->feedback, student, text,
                                        size);
        }
    }
    free(text);
    if (status != CLI_EXIT_OK && p->feedback_status == CLI_EXIT_OK)
        p->feedback_status = status;
}

/* One submission's row, in the folders' order (grade_class.h). */
static int print_graded(const cli_graded *g, void *context)
{
    class_printer *p = context;
    const grade_request *req = p->req;
    const cli_student *who = &p->roster->students[g->index];
    const char *student = who->name;
    if (g->status != RAYO_OK && g->err.status == RAYO_ERR_CANCELLED) {
        p->cancelled = 1;
        return 1;
    }
    if (req->json && p->printed > 0)
        printf(",\n ");
    p->printed++;
    if (g->status != RAYO_OK || who->problem != NULL) {
        /* One bad folder does not stop the class. */
        const char *message = who->problem != NULL ? who->problem
                                                   : g->err.message;
        if (req->json) {
            printf("{\"student\": ");
            json_string(student);
            printf(", \"result\": \"error\", \"error\": ");
            json_string(message);
            printf("}");
        } else if (!p->quiet) {
            cli_grade_print_column(student, p->width);
            printf(" error: ");
            cli_grade_print_escaped(stdout, message, 0);
            putchar('\n');
        }
        if (p->csv != NULL)
            cli_grade_csv_row(p->csv, student, NULL, message, &req->points);
        cli_tally_add(&p->tally, NULL);
        if (req->feedback != NULL)
            write_feedback(p, who, NULL, message);
    } else {
        if (req->json)
            cli_grade_print_json(student, g->options, &g->report);
        else if (!p->quiet)
            print_table_row(student, p->width, &g->report,
                            req->scored ? &req->points : NULL);
        cli_tally_add(&p->tally, &g->report);
        if (req->feedback != NULL)
            write_feedback(p, who, &g->report, NULL);
        if (rayo_grade_overall(&g->report) == RAYO_GRADE_PASS)
            p->passed++;
        if (p->csv != NULL)
            cli_grade_csv_row(p->csv, student, &g->report, NULL,
                              &req->points);
    }
    fflush(stdout);
    return cli_interrupted() != 0;
}

int cli_grade_each(const char *dir, grade_request *req)
{
    cli_roster roster;
    char **folders;
    size_t count, i;
    char *csv_text = NULL;
    size_t csv_size = 0;
    class_printer p;
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    char isolation[512];
    int status;
    rayo_error_clear(&err);
    if (cli_roster_build(dir, &roster, &err) != RAYO_OK) {
        cli_roster_free(&roster);
        return cli_report(&err);
    }
    cli_roster_say(dir, &roster);
    count = roster.count;
    folders = malloc(count * sizeof *folders);
    if (folders == NULL) {
        cli_roster_free(&roster);
        cli_sayf(_("%s: out of memory"), dir);
        return CLI_EXIT_FAILURE;
    }
    for (i = 0; i < count; i++)
        folders[i] = roster.students[i].folder;
    if (req->feedback != NULL &&
        (status = cli_feedback_prepare(req->feedback)) != CLI_EXIT_OK) {
        free(folders);
        cli_roster_free(&roster);
        return status;
    }
    memset(&p, 0, sizeof p);
    p.req = req;
    p.roster = &roster;
    p.width = student_width(&roster);
    p.quiet = cli_grade_is_stdout(req->csv);
    if (req->csv != NULL) {
        p.csv = cli_grade_export_start(&csv_text, &csv_size, req->csv);
        if (p.csv == NULL) {
            free(folders);
            cli_roster_free(&roster);
            return CLI_EXIT_FAILURE;
        }
        cli_grade_csv_header(p.csv);
    }
    /* Whether a sandbox can be made is found once, here, before the
       gradings start on their threads. */
    rayo_grade_sandbox_check(&req->options, isolation, sizeof isolation);
    if (req->options.sandbox == RAYO_GRADE_SANDBOX_OFF)
        snprintf(isolation, sizeof isolation, "off");
    if (req->json)
        printf("[");
    else if (!p.quiet) {
        cli_grade_print_isolation(stdout, isolation);
        print_table_header(p.width, req->scored);
    }
    cli_grade_class(folders, count,
                    req->jobs > 0 ? req->jobs : cli_grade_default_jobs(),
                    &req->options, 1, print_graded, &p);
    if (req->json)
        printf("]\n");
    else if (!p.quiet) {
        printf(_n("\n%zu of %zu submission passed\n",
                  "\n%zu of %zu submissions passed\n", count),
               p.passed, count);
        if (!p.cancelled && cli_interrupted() == 0) {
            putchar('\n');
            cli_tally_print(stdout, &p.tally);
        }
    }
    status = p.passed == count ? CLI_EXIT_OK : CLI_EXIT_FAILURE;
    if (p.feedback_status != CLI_EXIT_OK)
        status = p.feedback_status;
    if (p.csv != NULL) {
        if (p.cancelled || cli_interrupted() != 0) {
            fclose(p.csv);
            free(csv_text);
        } else {
            int written =
                cli_grade_export_finish(p.csv, &csv_text, &csv_size, req->csv);
            if (written != CLI_EXIT_OK)
                status = written;
        }
    }
    cli_tally_free(&p.tally);
    free(folders);
    cli_roster_free(&roster);
    return status;
}

