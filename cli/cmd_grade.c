/*
 * cmd_grade.c - `rayo grade`: grade one submission (files or a folder)
 * or, with --each, every submission folder in a directory, and print the
 * report as text or JSON.
 *
 * All the checking is library code (grade.h); this file parses options,
 * lays the report out and picks the exit status: 0 when everything
 * passed, 1 when a criterion failed, 2 for usage errors and for
 * --sandbox=require where no sandbox can be made.  The report's first
 * line says how the submission was isolated; --check says only that.
 */
#define _POSIX_C_SOURCE 200809L

#include <getopt.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cli_parse.h"
#include "grade_class.h"
#include "grade_export.h"
#include "grade_feedback.h"
#include "grade_roster.h"
#include "grade_tally.h"
#include "interrupt.h"
#include "output_guard.h"

typedef struct grade_request {
    rayo_grade_options options;
    char course_reference[4096]; /* --reference course, resolved */
    int json, each, check;
    unsigned jobs;               /* -j: submissions graded at once */
    const char *csv;             /* --csv FILE or "-" */
    const char *gradescope;      /* --gradescope FILE */
    cli_grade_points points;     /* --points */
    int scored;                  /* --points was given: a score column */
    const char *feedback;        /* --feedback DIR */
} grade_request;

/* The grading's cancel callback: after SIGINT/SIGTERM the grading stops,
   kills the running program and removes its temporary directory, then
   we die of the signal. */
static int stop_requested(void *context)
{
    (void)context;
    return cli_interrupted() != 0;
}

static void print_help(void)
{
    size_t count, i;
    const rayo_grade_exercise *exercises = rayo_grade_exercises(&count);
    printf(
        _("usage: rayo grade [OPTIONS] SOURCE.c [MORE.c ...]\n"
          "       rayo grade [OPTIONS] FOLDER\n"
          "       rayo grade [OPTIONS] --each DIRECTORY\n\n"
          "Checks a submission the way the course does: it compiles with "
          "cc -std=c99\n-Wall -Werror -pedantic ... -lm; the functions the "
          "exercise's statement asks\nfor have its signatures and return the "
          "right values (ej1: producto_interno,\nnorma, intersecta_esfera; "
          "ej2 and ej3: all of theirs, on inputs chosen to\nreveal the usual "
          "mistakes); it runs with no input to exit status 0 under\nlimits; "
          "its output is strict plain PBM, PGM or PPM of the right size; its "
          "image\nis consistent with the reference (as 'rayo compare' "
          "judges); and valgrind\nfinds no invalid access and no leak.  Every "
          "failure is explained.\n\n"
          "options:\n"
          "      --exercise NAME    the exercise (default ej1)\n"
          "      --reference FILE   compare with this image instead of the "
          "exercise's\n"
          "                         reference rendered by rayo; 'course': "
          "the course's\n"
          "                         own image (referencia-catedra-ejN.png)\n"
          "      --diff OUT.png     keep the difference picture\n"
          "      --json             the report as JSON\n"
          "      --each             DIRECTORY holds one folder per student: "
          "grade each,\n"
          "                         print a table\n"
          "                         (also Moodle's folders, zip files, GitHub "
          "Classroom's\n"
          "                         repositories, files named NAME_main.c)\n"
          "      --feedback DIR     with --each, write each student's report "
          "into DIR\n"
          "  -j, --jobs N           with --each, grade N submissions at once "
          "(default:\n"
          "                         the number of CPUs); the table is the "
          "same\n"
          "      --csv FILE         also write one CSV row per submission "
          "('-': to\n"
          "                         standard output, instead of the report)\n"
          "      --gradescope FILE  also write Gradescope's results.json for "
          "the\n"
          "                         submission (not with --each)\n"
          "      --points LIST      points per criterion for --csv and "
          "--gradescope\n"
          "                         (and a score column in --each's table)\n"
          "                         (default compile=10,functions=20,run=10,"
          "output=10,\n"
          "                         image=40,valgrind=10)\n"
          "      --timeout SEC      wall-clock limit per run (default 10)\n"
          "      --cpu SEC          CPU time limit per run (default 10)\n"
          "      --memory MIB       memory of the run's whole process tree "
          "(default 512)\n"
          "      --output-limit MIB largest file the program may write "
          "(default 64)\n"
          "      --processes N      processes of the run's tree (default "
          "64)\n"
          "      --no-valgrind      skip the valgrind run\n"
          "      --cc COMMAND       the compiler (default $CC, else cc)\n"
          "      --sandbox MODE     auto (default): run everything in a "
          "bubblewrap sandbox\n"
          "                         when one can be made, else say it is "
          "not isolated;\n"
          "                         require: refuse to grade without it; "
          "off: no sandbox\n"
          "      --disk MIB         the sandbox's disk for the program "
          "(default 256)\n"
          "      --check            say whether the sandbox works here, "
          "grade nothing\n"
          "                         (exit 0 when it does, 2 when not)\n"
          "      --lang es|en       the language of messages (default: from "
          "the\n"
          "                         environment: LANGUAGE, LC_ALL, "
          "LC_MESSAGES, LANG)\n"
          "  -h, --help             this help\n\n"
          "exercises:\n"));
    for (i = 0; i < count; i++)
        printf("  %-8s %s\n", exercises[i].name, exercises[i].title);
    printf(_("\nThe report's first line says how the submission was isolated "
             "(docs/grading.md\nsays what the sandbox stops and what it does "
             "not).\n\n"
             "exit status: 0 everything passed, 1 something failed or an "
             "output could not be\nwritten, 2 bad options or an input that "
             "cannot be read (missing, unreadable,\na directory, malformed), "
             "or --sandbox=require without a sandbox.\n"));
}

static int parse_seconds(const char *option, const char *text, double *value)
{
    if (!cli_parse_double(option, text, value))
        return 0;
    if (!(*value > 0 && *value <= 3600)) {
        cli_usage_error(_("%s: %s is out of range; expected seconds, more "
                          "than 0 and at most 3600"),
                        option, cli_quote(text));
        return 0;
    }
    return 1;
}

static int parse_mib(const char *option, const char *text, uint64_t *bytes)
{
    unsigned long mib;
    if (!cli_parse_uint(option, text, 1, 1048576, &mib))
        return 0;
    *bytes = (uint64_t)mib << 20;
    return 1;
}

enum {
    OPT_EXERCISE = 256, OPT_REFERENCE, OPT_DIFF, OPT_JSON, OPT_EACH,
    OPT_TIMEOUT, OPT_CPU, OPT_MEMORY, OPT_OUTPUT_LIMIT, OPT_PROCESSES,
    OPT_NO_VALGRIND, OPT_CC, OPT_CSV, OPT_GRADESCOPE, OPT_POINTS,
    OPT_SANDBOX, OPT_DISK, OPT_CHECK, OPT_LANG, OPT_FEEDBACK
};

static int parse_option(int c, grade_request *req)
{
    rayo_grade_options *o = &req->options;
    switch (c) {
    case OPT_EXERCISE:
        o->exercise = rayo_grade_exercise_find(optarg);
        if (o->exercise == NULL) {
            const char *names[16];
            size_t count, i;
            const rayo_grade_exercise *all = rayo_grade_exercises(&count);
            for (i = 0; i < count && i < 16; i++)
                names[i] = all[i].name;
            return cli_unknown_exercise("--exercise", optarg, names, i);
        }
        return CLI_EXIT_OK;
    case OPT_REFERENCE: o->reference = optarg; return CLI_EXIT_OK;
    case OPT_DIFF: o->diff = optarg; return CLI_EXIT_OK;
    case OPT_JSON: req->json = 1; return CLI_EXIT_OK;
    case OPT_EACH: req->each = 1; return CLI_EXIT_OK;
    case OPT_NO_VALGRIND: o->valgrind = 0; return CLI_EXIT_OK;
    case OPT_CC: o->cc = optarg; return CLI_EXIT_OK;
    case OPT_CSV: req->csv = optarg; return CLI_EXIT_OK;
    case OPT_GRADESCOPE: req->gradescope = optarg; return CLI_EXIT_OK;
    case OPT_POINTS:
        req->scored = 1;
        return cli_grade_points_parse(optarg, &req->points);
    case OPT_FEEDBACK: req->feedback = optarg; return CLI_EXIT_OK;
    case 'j': {
        unsigned long jobs;
        if (!cli_parse_uint("--jobs", optarg, 1, 256, &jobs))
            return CLI_EXIT_USAGE;
        req->jobs = (unsigned)jobs;
        return CLI_EXIT_OK;
    }
    case OPT_TIMEOUT:
        return parse_seconds("--timeout", optarg, &o->timeout)
                   ? CLI_EXIT_OK : CLI_EXIT_USAGE;
    case OPT_CPU:
        return parse_seconds("--cpu", optarg, &o->cpu) ? CLI_EXIT_OK
                                                       : CLI_EXIT_USAGE;
    case OPT_MEMORY:
        return parse_mib("--memory", optarg, &o->memory) ? CLI_EXIT_OK
                                                         : CLI_EXIT_USAGE;
    case OPT_OUTPUT_LIMIT:
        return parse_mib("--output-limit", optarg, &o->output_limit)
                   ? CLI_EXIT_OK : CLI_EXIT_USAGE;
    case OPT_SANDBOX:
        if (strcmp(optarg, "auto") == 0)
            o->sandbox = RAYO_GRADE_SANDBOX_AUTO;
        else if (strcmp(optarg, "require") == 0)
            o->sandbox = RAYO_GRADE_SANDBOX_REQUIRE;
        else if (strcmp(optarg, "off") == 0)
            o->sandbox = RAYO_GRADE_SANDBOX_OFF;
        else
            return cli_usage_error(_("--sandbox: %s is not a mode; "
                                     "expected auto, require or off"),
                                   cli_quote(optarg));
        return CLI_EXIT_OK;
    case OPT_DISK:
        return parse_mib("--disk", optarg, &o->disk) ? CLI_EXIT_OK
                                                     : CLI_EXIT_USAGE;
    case OPT_CHECK: req->check = 1; return CLI_EXIT_OK;
    case OPT_LANG: return CLI_EXIT_OK; /* read before (lang.c) */
    case OPT_PROCESSES:
        return cli_parse_uint("--processes", optarg, 1, 100000,
                              &o->processes)
                   ? CLI_EXIT_OK : CLI_EXIT_USAGE;
    }
    return CLI_EXIT_USAGE;
}

static int parse_request(int argc, char **argv, grade_request *req)
{
    static const struct option options[] = {
        {"exercise", required_argument, NULL, OPT_EXERCISE},
        {"reference", required_argument, NULL, OPT_REFERENCE},
        {"diff", required_argument, NULL, OPT_DIFF},
        {"json", no_argument, NULL, OPT_JSON},
        {"each", no_argument, NULL, OPT_EACH},
        {"timeout", required_argument, NULL, OPT_TIMEOUT},
        {"cpu", required_argument, NULL, OPT_CPU},
        {"memory", required_argument, NULL, OPT_MEMORY},
        {"output-limit", required_argument, NULL, OPT_OUTPUT_LIMIT},
        {"processes", required_argument, NULL, OPT_PROCESSES},
        {"no-valgrind", no_argument, NULL, OPT_NO_VALGRIND},
        {"cc", required_argument, NULL, OPT_CC},
        {"jobs", required_argument, NULL, 'j'},
        {"csv", required_argument, NULL, OPT_CSV},
        {"gradescope", required_argument, NULL, OPT_GRADESCOPE},
        {"points", required_argument, NULL, OPT_POINTS},
        {"sandbox", required_argument, NULL, OPT_SANDBOX},
        {"disk", required_argument, NULL, OPT_DISK},
        {"check", no_argument, NULL, OPT_CHECK},
        {"lang", required_argument, NULL, OPT_LANG},
        {"feedback", required_argument, NULL, OPT_FEEDBACK},
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0}};
    int c;
    opterr = 0;
    optind = 0;
    while ((c = getopt_long(argc, argv, ":hj:", options, NULL)) != -1) {
        int status;
        if (c == 'h') {
            print_help();
            return -1;
        }
        if (c == '?' || c == ':')
            return cli_bad_option(c, argv, optind);
        status = parse_option(c, req);
        if (status != CLI_EXIT_OK)
            return status;
    }
    if (req->check) {
        if (optind < argc)
            return cli_usage_error(_("--check: grades nothing; no submission "
                                     "is expected"));
        return CLI_EXIT_OK;
    }
    if (optind >= argc)
        return cli_usage_error(_("grade: no submission given; expected "
                                 "SOURCE.c, a folder, or --each DIRECTORY"));
    if (req->each && argc - optind != 1)
        return cli_usage_error(_("grade: --each takes one DIRECTORY, not %d "
                                 "arguments"),
                               argc - optind);
    if (req->each && req->options.diff != NULL)
        return cli_usage_error(_("--diff: applies to one submission, not to "
                                 "--each"));
    if (!req->each && req->feedback != NULL)
        return cli_usage_error(_("--feedback: writes one report per student "
                                 "of --each; for one submission, save the "
                                 "report itself"));
    if (req->each && req->gradescope != NULL)
        return cli_usage_error(_("--gradescope: Gradescope grades one "
                                 "submission per run, not --each; use --csv "
                                 "for a class"));
    if (req->csv != NULL && strcmp(req->csv, "-") == 0 && req->json)
        return cli_usage_error(_("--csv -: standard output already carries "
                                 "the JSON; give --csv a FILE"));
    if (req->gradescope != NULL && strcmp(req->gradescope, "-") == 0 &&
        (req->json || (req->csv != NULL && strcmp(req->csv, "-") == 0)))
        return cli_usage_error(_("--gradescope -: standard output already "
                                 "carries the report; give a FILE"));
    if (req->options.reference != NULL &&
        strcmp(req->options.reference, "course") == 0) {
        const char *name = req->options.exercise->name;
        if (!cli_course_reference(name, req->course_reference,
                                  sizeof req->course_reference))
            return cli_usage_error(_("--reference course: the course's image "
                                     "for %s (referencia-catedra-%s.png) is "
                                     "not installed; looked in "
                                     "$RAYO_DATA_DIR/course and beside the "
                                     "command (../data/course, "
                                     "../share/rayo/course)"),
                                   name, name);
        req->options.reference = req->course_reference;
    }
    return CLI_EXIT_OK;
}

/* ---- text ---- */

/*
 * What the report prints comes partly from outside: folder names from a
 * class's archive, a compiler's quote of the student's source.  In the
 * text report every such string is shown on one line as it would be
 * typed: control bytes as \n, \t, \r or \xHH, a byte that is not
 * valid UTF-8 as \xHH, a bidirectional control as \uHHHH (and, in
 * names, a backslash as \\); other valid UTF-8
 * is kept (one column per character, for the table).
 */
#define STUDENT_COLUMNS 40 /* the widest the table's student column gets */

/* Writes s escaped (names: a name, else a reason line). */
static void print_escaped(FILE *out, const char *s, int names)
{
    while (*s != '\0') {
        char text[8];
        size_t columns;
        s += cli_escape_unit(s, names, text, &columns);
        fputs(text, out);
    }
}

/* How many columns the name s takes escaped. */
static size_t escaped_columns(const char *s)
{
    size_t total = 0;
    while (*s != '\0') {
        char text[8];
        size_t columns;
        s += cli_escape_unit(s, 1, text, &columns);
        total += columns;
    }
    return total;
}

/* Writes the name s escaped in exactly width columns: padded with
   spaces, or cut and ended with "..." when it is wider. */
static void print_column(const char *s, size_t width)
{
    size_t used = 0, room = width;
    if (escaped_columns(s) > width)
        room = width > 3 ? width - 3 : 0;
    while (*s != '\0') {
        char text[8];
        size_t columns, n = cli_escape_unit(s, 1, text, &columns);
        if (used + columns > room)
            break;
        fputs(text, stdout);
        used += columns;
        s += n;
    }
    if (*s != '\0') {
        fputs("...", stdout);
        used += 3;
    }
    for (; used < width; used++)
        putchar(' ');
}

/* The report's first line, in line: how the submission was isolated
   ("sandbox: bubblewrap (...)", or a warning that it was not); NULL for
   --sandbox=off.  Also the second line of Gradescope's output. */
static const char *isolation_line(const char *isolation, char *line,
                                  size_t room)
{
    if (strcmp(isolation, "off") == 0 || isolation[0] == '\0')
        return NULL;
    snprintf(line, room, "%s%s",
             strncmp(isolation, "sandbox: ", 9) == 0 ? "" : "warning: ",
             isolation);
    return line;
}

static void print_isolation(FILE *out, const char *isolation)
{
    char line[600];
    if (isolation_line(isolation, line, sizeof line) != NULL)
        fprintf(out, "%s\n", line);
}

static void print_text(FILE *out, const rayo_grade_report *r)
{
    size_t c, i, failed = 0, skipped = 0, warnings = 0;
    char failed_names[128] = "";
    print_isolation(out, r->isolation);
    for (c = 0; c < RAYO_GRADE_CRITERIA; c++) {
        const rayo_grade_item *item = &r->items[c];
        const char *result = item->result == RAYO_GRADE_FAIL
                                 ? "FAIL"
                                 : rayo_grade_result_name(item->result);
        fprintf(out, "%-10s %-8s ", rayo_grade_criterion_name(c), result);
        print_escaped(out, item->line_count > 0 ? item->lines[0] : "", 0);
        fputc('\n', out);
        for (i = 1; i < item->line_count; i++) {
            fprintf(out, "%-19s ", "");
            print_escaped(out, item->lines[i], 0);
            fputc('\n', out);
        }
        warnings += item->warnings;
        if (item->result == RAYO_GRADE_SKIPPED)
            skipped++;
        if (item->result == RAYO_GRADE_FAIL) {
            size_t n = strlen(failed_names);
            snprintf(failed_names + n, sizeof failed_names - n, "%s%s",
                     failed++ > 0 ? ", " : "",
                     rayo_grade_criterion_name(c));
        }
    }
    /* The PASS and FAIL tokens stay as they are in every language. */
    if (failed > 0) {
        fputs("\nFAIL: ", out);
        fprintf(out,
                _n("%zu of %d criterion failed (%s)",
                   "%zu of %d criteria failed (%s)", RAYO_GRADE_CRITERIA),
                failed, RAYO_GRADE_CRITERIA, failed_names);
    } else {
        fputs("\nPASS: ", out);
        fprintf(out,
                _n("%zu of %d criterion passed", "%zu of %d criteria passed",
                   RAYO_GRADE_CRITERIA),
                RAYO_GRADE_CRITERIA - skipped, RAYO_GRADE_CRITERIA);
    }
    if (skipped > 0)
        fprintf(out, _n(", %zu skipped", ", %zu skipped", skipped), skipped);
    if (warnings > 0)
        fprintf(out, _n(", %zu warning", ", %zu warnings", warnings),
                warnings);
    fputs("\n", out);
}

/* ---- JSON ---- */

static void json_string(const char *s)
{
    cli_json_string(stdout, s);
}

static void print_json(const char *student, const rayo_grade_options *o,
                       const rayo_grade_report *r)
{
    size_t c, i;
    printf("{");
    if (student != NULL) {
        printf("\"student\": ");
        json_string(student);
        printf(", ");
    }
    printf("\"exercise\": ");
    json_string(o->exercise->name);
    printf(", \"sources\": [");
    for (i = 0; i < o->source_count; i++) {
        printf(i > 0 ? ", " : "");
        json_string(o->sources[i]);
    }
    printf("], \"sandbox\": {\"isolated\": %s, \"detail\": ",
           r->isolated ? "true" : "false");
    json_string(strncmp(r->isolation, "sandbox: ", 9) == 0 ? r->isolation + 9
                                                           : r->isolation);
    printf("}, \"result\": \"%s\", \"verdict\": ",
           rayo_grade_result_name(rayo_grade_overall(r)));
    if (r->verdict != NULL)
        json_string(r->verdict);
    else
        printf("null");
    printf(", \"criteria\": [");
    for (c = 0; c < RAYO_GRADE_CRITERIA; c++) {
        const rayo_grade_item *item = &r->items[c];
        printf("%s{\"name\": \"%s\", \"result\": \"%s\", \"reasons\": [",
               c > 0 ? ", " : "", rayo_grade_criterion_name(c),
               rayo_grade_result_name(item->result));
        for (i = 0; i < item->line_count; i++) {
            printf(i > 0 ? ", " : "");
            json_string(item->lines[i]);
        }
        printf("]}");
    }
    printf("]}");
}

/* ---- files for other tools (--csv, --gradescope) ---- */

/* Whether path is standard output. */
static int is_stdout(const char *path)
{
    return path != NULL && strcmp(path, "-") == 0;
}

/* text (size bytes) into path, whole or not at all; an exit status. */
static int write_whole(const char *path, const char *text, size_t size)
{
    rayo_output *out;
    rayo_error err;
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

/* A memory stream for what will go to path, or NULL (said) without
   memory. */
static FILE *start_export(char **text, size_t *size, const char *path)
{
    FILE *stream;
    *text = NULL;
    *size = 0;
    stream = open_memstream(text, size);
    if (stream == NULL)
        cli_sayf(_("%s: out of memory"), path);
    return stream;
}

/* A memory stream's text, written to path; an exit status. */
static int finish_export(FILE *stream, char **text, size_t *size,
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

/* The --csv and --gradescope files of one submission (report NULL: it
   could not be graded, err says why); an exit status. */
static int export_one(const grade_request *req, const char *student,
                      const rayo_grade_report *report, const rayo_error *err)
{
    const char *message = report == NULL ? err->message : NULL;
    int status = CLI_EXIT_OK;
    char *text;
    size_t size;
    FILE *stream;
    if (req->csv != NULL) {
        if ((stream = start_export(&text, &size, req->csv)) == NULL)
            return CLI_EXIT_NOMEM;
        cli_grade_csv_header(stream);
        cli_grade_csv_row(stream, student, report, message, &req->points);
        status = finish_export(stream, &text, &size, req->csv);
    }
    if (req->gradescope != NULL && status == CLI_EXIT_OK) {
        char line[600];
        if ((stream = start_export(&text, &size, req->gradescope)) == NULL)
            return CLI_EXIT_NOMEM;
        cli_grade_gradescope(stream, report, message,
                             report != NULL
                                 ? isolation_line(report->isolation, line,
                                                  sizeof line)
                                 : NULL,
                             &req->points);
        status = finish_export(stream, &text, &size, req->gradescope);
    }
    return status;
}

/* ---- one submission ---- */

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash != NULL && slash[1] != '\0' ? slash + 1 : path;
}

static int grade_single(int argc, char **argv, int first, grade_request *req)
{
    rayo_grade_report report;
    rayo_error err;
    char **sources = NULL;
    size_t count = 0;
    int exit_status, export_status;
    int quiet = is_stdout(req->csv) || is_stdout(req->gradescope);
    rayo_status status = RAYO_OK;
    rayo_error_clear(&err);
    memset(&report, 0, sizeof report);
    if (first + 1 == argc) {
        status = rayo_grade_sources(argv[first], &sources, &count, &err);
        req->options.sources = (const char *const *)sources;
        req->options.source_count = count;
    } else {
        req->options.sources = (const char *const *)(argv + first);
        req->options.source_count = (size_t)(argc - first);
    }
    if (status == RAYO_OK)
        status = rayo_grade(&req->options, &report, &err);
    if (status != RAYO_OK) {
        rayo_grade_paths_free(sources, count);
        if (err.status == RAYO_ERR_CANCELLED)
            return CLI_EXIT_FAILURE;
        /* The platform still gets a result that says why. */
        export_one(req, base_name(argv[first]), NULL, &err);
        return cli_report(&err);
    }
    if (req->json)
        print_json(NULL, &req->options, &report);
    if (req->json)
        printf("\n");
    else if (!quiet)
        print_text(stdout, &report);
    exit_status = rayo_grade_overall(&report) == RAYO_GRADE_PASS
                      ? CLI_EXIT_OK
                      : CLI_EXIT_FAILURE;
    export_status = export_one(req, base_name(argv[first]), &report, &err);
    rayo_grade_report_free(&report);
    rayo_grade_paths_free(sources, count);
    req->options.sources = NULL;
    req->options.source_count = 0;
    return export_status != CLI_EXIT_OK ? export_status : exit_status;
}

/* ---- a class ---- */

static void print_table_header(size_t width, int scored)
{
    size_t c;
    print_column("student", width);
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
    print_column(student, width);
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
        size_t columns = escaped_columns(roster->students[i].name);
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
        cli_sayf("--feedback: %s: out of memory", p->req->feedback);
        status = CLI_EXIT_FAILURE;
    } else {
        if (report != NULL)
            print_text(stream, report);
        else
            fprintf(stream, "rayo grade could not grade this submission: "
                    "%s\n", error);
        if (fclose(stream) != 0 || text == NULL) {
            cli_sayf("--feedback: %s: out of memory", p->req->feedback);
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
            print_column(student, p->width);
            printf(" error: ");
            print_escaped(stdout, message, 0);
            putchar('\n');
        }
        if (p->csv != NULL)
            cli_grade_csv_row(p->csv, student, NULL, message, &req->points);
        cli_tally_add(&p->tally, NULL);
        if (req->feedback != NULL)
            write_feedback(p, who, NULL, message);
    } else {
        if (req->json)
            print_json(student, g->options, &g->report);
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

static int grade_each(const char *dir, grade_request *req)
{
    cli_roster roster;
    char **folders;
    size_t count, i;
    char *csv_text = NULL;
    size_t csv_size = 0;
    class_printer p;
    rayo_error err;
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
        cli_sayf("%s: out of memory", dir);
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
    p.quiet = is_stdout(req->csv);
    if (req->csv != NULL) {
        p.csv = start_export(&csv_text, &csv_size, req->csv);
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
        print_isolation(stdout, isolation);
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
            int written = finish_export(p.csv, &csv_text, &csv_size,
                                        req->csv);
            if (written != CLI_EXIT_OK)
                status = written;
        }
    }
    cli_tally_free(&p.tally);
    free(folders);
    cli_roster_free(&roster);
    return status;
}

/* Submissions and --reference that cannot be read are bad input (exit
   2, as in every command), told apart here from the grading's own I/O. */
static int check_inputs(int argc, char **argv, int first,
                        const grade_request *req)
{
    int i, status = CLI_EXIT_OK;
    for (i = first; i < argc && status == CLI_EXIT_OK; i++)
        status = cli_check_input(argv[i], req->each ? CLI_INPUT_FOLDER
                                                    : CLI_INPUT_ANY);
    if (status == CLI_EXIT_OK && req->options.reference != NULL)
        status = cli_check_input(req->options.reference, CLI_INPUT_FILE);
    return status;
}

int cli_grade(int argc, char **argv)
{
    grade_request req;
    int status;
    memset(&req, 0, sizeof req);
    rayo_grade_options_init(&req.options);
    cli_grade_points_default(&req.points);
    status = parse_request(argc, argv, &req);
    if (status != CLI_EXIT_OK)
        return status < 0 ? CLI_EXIT_OK : status;
    if ((status = check_inputs(argc, argv, optind, &req)) != CLI_EXIT_OK)
        return status;
    /* --no-valgrind: the criterion is not graded, so not counted,
       unless --points gives it points all the same. */
    if (!req.options.valgrind &&
        !(req.points.given & (1u << RAYO_GRADE_VALGRIND)))
        req.points.points[RAYO_GRADE_VALGRIND] = 0;
    if (req.check || req.options.sandbox == RAYO_GRADE_SANDBOX_REQUIRE) {
        char text[512];
        int isolated = rayo_grade_sandbox_check(&req.options, text,
                                                sizeof text);
        if (req.check) {
            printf("%s\n", text);
            return isolated ? CLI_EXIT_OK : CLI_EXIT_USAGE;
        }
        if (!isolated)
            return cli_usage_error(_("grade: --sandbox=require: %s; refusing "
                                     "to grade"), text);
    }
    req.options.cancelled = stop_requested;
    cli_interrupt_catch();
    status = req.each ? grade_each(argv[optind], &req)
                      : grade_single(argc, argv, optind, &req);
    if (cli_interrupted() != 0)
        return cli_interrupt_exit();
    return status;
}

/* cli_parse.h: the options parsed as `rayo grade` parses them, nothing
 * run. */
int cli_parse_grade(int argc, char **argv)
{
    grade_request req;
    int status;
    memset(&req, 0, sizeof req);
    rayo_grade_options_init(&req.options);
    status = parse_request(argc, argv, &req);
    return status < 0 ? CLI_EXIT_OK : status;
}
