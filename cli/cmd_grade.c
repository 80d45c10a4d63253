/*
 * cmd_grade.c - `rayo grade`: grade one submission (files or a folder)
 * or, with --each, every submission folder in a directory, and print the
 * report as text or JSON.
 *
 * All the checking is library code (grade.h); this file parses options,
 * grades one submission (a class: grade_each.c), has the report printed
 * (grade_print.c) and picks the exit status: 0 when everything
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
#include "grade_export.h"
#include "grade_print.h"
#include "grade_request.h"
#include "interrupt.h"

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
        printf("  %-8s %s\n", exercises[i].name, _(exercises[i].title));
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

/* ---- one submission ---- */

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash != NULL && slash[1] != '\0' ? slash + 1 : path;
}

static int grade_single(int argc, char **argv, int first, grade_request *req)
{
    rayo_grade_report report;
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    char **sources = NULL;
    size_t count = 0;
    int exit_status, export_status;
    int quiet =
        cli_grade_is_stdout(req->csv) || cli_grade_is_stdout(req->gradescope);
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
        cli_grade_export_one(req, base_name(argv[first]), NULL, &err);
        return cli_report(&err);
    }
    if (req->json)
        cli_grade_print_json(NULL, &req->options, &report);
    if (req->json)
        printf("\n");
    else if (!quiet)
        cli_grade_print_text(stdout, &report);
    exit_status = rayo_grade_overall(&report) == RAYO_GRADE_PASS
                      ? CLI_EXIT_OK
                      : CLI_EXIT_FAILURE;
    export_status =
        cli_grade_export_one(req, base_name(argv[first]), &report, &err);
    rayo_grade_report_free(&report);
    rayo_grade_paths_free(sources, count);
    req->options.sources = NULL;
    req->options.source_count = 0;
    return export_status != CLI_EXIT_OK ? export_status : exit_status;
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
    req.options.lang = cli_lang();
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
    status = req.each ? cli_grade_each(argv[optind], &req)
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
