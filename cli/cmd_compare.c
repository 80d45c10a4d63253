/*
 * cmd_compare.c - `rayo compare REFERENCE IMAGE`: reads both images (the
 * image with its samples out of range clamped and counted, the reference
 * strictly), compares them (compare.h: masks or values) and prints the
 * report, as text or JSON, and optionally writes the difference picture.
 *
 * Exit status: 0 identical or consistent, 1 inconsistent, 2 unreadable
 * input or bad options (and 1 for an output failure of --diff).  A --diff
 * that names an input (the same name, or the same file through a link)
 * is refused before anything is read.  course:ej1, course:ej2 and
 * course:ej3 name the course's reference images (course_data.c).  When
 * the two pictures are of different kinds (black and white, gray,
 * colour) the report says so, naming the course's exercise; when the
 * image is the course's and the reference is not, one line warns that
 * the operands look swapped.  The
 * verdict logic is all in the library; this file only reads, calls and
 * prints.
 */
#define _POSIX_C_SOURCE 200809L

#include <getopt.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cli_parse.h"
#include "output_guard.h"

typedef struct compare_request {
    const char *reference, *image, *diff;
    const char *operands[2]; /* REFERENCE and IMAGE as given */
    char course_paths[2][4096]; /* course:NAME operands, resolved */
    rayo_compare_options options;
    int json;
} compare_request;

static void print_help(void)
{
    printf(
        _("usage: rayo compare REFERENCE IMAGE [--tolerance PX] [--levels N]\n"
          "                    [--exercise NAME] [--diff OUT.png] [--json]\n\n"
          "Tells whether IMAGE shows what REFERENCE shows and, if not, what "
          "is likely\nwrong.  course:ej1, course:ej2 and course:ej3 name the "
          "course's reference\nimages, installed with rayo (a file of that "
          "very name wins).  Two bilevel images (PBM, or only black and "
          "white pixels) are compared as\nblack/white masks; when either is "
          "gray or colour, values are compared (see\nbelow).  An image of "
          "another size is laid on the reference centred.\n\n"
          "Masks: it prints the sizes, the mismatched pixels, the IoU of the "
          "black\nregions, the farthest mismatch from the reference's outline "
          "(distance to the\nnearest reference pixel of the other colour), "
          "the offset and scale between the\nblack shapes, and a verdict.\n"
          "Gray and colour: per channel the pixels off by more than --levels, "
          "the largest\ndifference, RMSE and PSNR; where the differing pixels "
          "lie: at the reference's\noutlines and shadow edges, in shading "
          "where the reference takes their value\nwithin the tolerance, or "
          "unexplained; and a verdict.\n\n"
          "Verdicts:\n"
          "  identical     every pixel agrees (values: every sample within "
          "--levels)\n"
          "  consistent    every mismatch within the tolerance of the "
          "outline (values:\n"
          "                every difference explained), the shapes agreeing "
          "there (the\n"
          "                mismatches at most 75%% of the pixels near the "
          "outline, and\n"
          "                at most half of chance), and no whole-pixel shift "
          "explains them\n"
          "  inconsistent  anything else; then a diagnosis when one fits: "
          "flipped,\n"
          "                inverted, transposed, shifted, scaled, different "
          "size, empty,\n"
          "                not a sphere, another sphere; for values also "
          "channels in\n"
          "                another order, an offset, values wrapped past 255, "
          "and the\n"
          "                course's typical mistakes (no shadows, no ambient, "
          "...) when\n"
          "                the reference shows the course's scene 2 or 3\n\n"
          "options:\n"
          "      --tolerance PX  pixels a mismatch may be from the outline; "
          "values: from an\n"
          "                      edge or the same value (default 2)\n"
          "      --levels N      gray and colour: levels (of 255) a value may "
          "be off\n"
          "                      and still agree (0-255, default 1)\n"
          "      --exercise NAME the course exercise whose mistakes to try "
          "(ej2, ej3; ej1's\n"
          "                      images are masks), or none; default: the "
          "one whose\n"
          "                      scene the reference shows\n"
          "      --diff OUT.png  write the difference picture (reference's "
          "size; not\n"
          "                      an input):\n"
          "                        black, white  both agree\n"
          "                        red           black only in the reference "
          "(missing)\n"
          "                        blue          black only in the image "
          "(extra)\n"
          "                      gray and colour: the reference dimmed, "
          "differences\n"
          "                      painted amber (explained) or red "
          "(unexplained),\n"
          "                      brighter the larger\n"
          "      --json          the report as one JSON object\n"
          "      --lang es|en    the language of messages (default: from the\n"
          "                      environment: LANGUAGE, LC_ALL, LC_MESSAGES, "
          "LANG)\n"
          "  -h, --help          this help\n\n"
          "exit status: 0 identical or consistent, 1 inconsistent or --diff "
          "could not be\nwritten, 2 bad options or an input that cannot be "
          "read (missing, unreadable,\na directory, malformed or too "
          "large).\n"));
}

static int parse_request(int argc, char **argv, compare_request *req)
{
    static const struct option options[] = {
        {"tolerance", required_argument, NULL, 't'},
        {"levels", required_argument, NULL, 'l'},
        {"exercise", required_argument, NULL, 'e'},
        {"diff", required_argument, NULL, 'd'},
        {"json", no_argument, NULL, 'j'},
        {"lang", required_argument, NULL, 'L'},
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0}};
    int c;
    opterr = 0;
    optind = 0;
    while ((c = getopt_long(argc, argv, ":h", options, NULL)) != -1) {
        switch (c) {
        case 't':
            if (!cli_parse_double("--tolerance", optarg,
                                  &req->options.tolerance))
                return CLI_EXIT_USAGE;
            if (!(req->options.tolerance >= 0))
                return cli_usage_error(_("--tolerance: %s is negative; "
                                         "expected pixels, 0 or more"),
                                       cli_quote(optarg));
            break;
        case 'd':
            req->diff = optarg;
            break;
        case 'l': {
            unsigned long levels;
            if (!cli_parse_uint("--levels", optarg, 0, 255, &levels))
                return CLI_EXIT_USAGE;
            req->options.levels = (unsigned)levels;
            break;
        }
        case 'e':
            if (strcmp(optarg, "none") == 0) {
                req->options.course = RAYO_COMPARE_COURSE_NONE;
            } else if (rayo_course_find(optarg) == RAYO_COURSE_EXERCISES) {
                const char *names[RAYO_COURSE_EXERCISES + 1];
                unsigned i;
                for (i = 0; i < RAYO_COURSE_EXERCISES; i++)
                    names[i] = rayo_course_name((rayo_course_exercise)i);
                names[i] = "none";
                return cli_unknown_exercise("--exercise", optarg, names,
                                            RAYO_COURSE_EXERCISES + 1);
            } else {
                req->options.course = (int)rayo_course_find(optarg);
            }
            break;
        case 'j':
            req->json = 1;
            break;
        case 'L': /* --lang: read before (lang.c) */
            break;
        case 'h':
            print_help();
            return -1;
        default:
            return cli_bad_option(c, argv, optind);
        }
    }
    if (argc - optind != 2)
        return cli_wrong_operands("compare", argc - optind,
                                  N_("REFERENCE and IMAGE"));
    req->reference = req->operands[0] = argv[optind];
    req->image = req->operands[1] = argv[optind + 1];
    if (strcmp(req->reference, "-") == 0 && strcmp(req->image, "-") == 0)
        return cli_usage_error(_("compare: only one of REFERENCE and IMAGE "
                                 "can be '-' (standard input)"));
    if ((c = cli_image_operand(req->reference, req->course_paths[0],
                               sizeof req->course_paths[0],
                               &req->reference)) != CLI_EXIT_OK ||
        (c = cli_image_operand(req->image, req->course_paths[1],
                               sizeof req->course_paths[1], &req->image)) !=
            CLI_EXIT_OK)
        return c;
    if (req->diff != NULL && (cli_same_file(req->diff, req->reference) ||
                              cli_same_file(req->diff, req->image)))
        return cli_usage_error(cli_same_file(req->diff, req->reference)
                                   ? _("--diff: '%s' is the reference; "
                                       "refusing to overwrite an input, give "
                                       "another file")
                                   : _("--diff: '%s' is the image; refusing "
                                       "to overwrite an input, give another "
                                       "file"),
                               req->diff);
    return CLI_EXIT_OK;
}

static int print_report(const rayo_compare_report *report, int json)
{
    size_t need = json ? rayo_compare_format_json(report, NULL, 0)
                       : rayo_compare_format_text(report, NULL, 0);
    char *text = malloc(need + 1);
    if (text == NULL) {
        cli_say(_("compare: out of memory for the report"));
        return CLI_EXIT_NOMEM;
    }
    if (json)
        rayo_compare_format_json(report, text, need + 1);
    else
        rayo_compare_format_text(report, text, need + 1);
    fputs(text, stdout);
    free(text);
    return CLI_EXIT_OK;
}

static int write_diff(const char *path, const rayo_image *reference,
                      const rayo_image *image,
                      const rayo_compare_options *options)
{
    rayo_output *out;
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    rayo_error_clear(&err);
    if (cli_output_open(&out, path, &err) != RAYO_OK)
        return cli_report(&err);
    if (rayo_compare_write_diff(reference, image, options, out, &err) ==
        RAYO_OK)
        cli_output_commit(out, &err);
    else
        cli_output_abort(out);
    return cli_report(&err);
}

/* Which of the course's images operand i is: named course:ejN, or
 * showing the same picture as one. */
static rayo_course_exercise course_image(const compare_request *req, int i,
                                         const rayo_image *image)
{
    if (req->course_paths[i][0] != '\0')
        return rayo_course_find(req->operands[i] + strlen("course:"));
    return cli_course_picture(image);
}

/* The kinds of both pictures into the report, and one line when the
 * operands look swapped: the image is the course's and the reference is
 * not (the comparison is still made as asked). */
static void note_kinds(const compare_request *req, const rayo_image *reference,
                       const rayo_image *image, rayo_compare_report *report)
{
    rayo_course_exercise ref_course = course_image(req, 0, reference);
    rayo_course_exercise image_course =
        ref_course < RAYO_COURSE_EXERCISES ? RAYO_COURSE_EXERCISES
                                           : course_image(req, 1, image);
    rayo_compare_note_kinds(report, reference, image, ref_course);
    if (image_course < RAYO_COURSE_EXERCISES)
        cli_sayf(_("compare: warning: the arguments look swapped: IMAGE, "
                   "the second, is the course's image of exercise %d, and "
                   "REFERENCE, the first, is not one of the course's; the "
                   "reference comes first: rayo compare course:ej%d %s; "
                   "compared as asked"),
                 (int)image_course + 1, (int)image_course + 1,
                 cli_quote(req->operands[0]));
}

static int compare_images(const compare_request *req,
                          const rayo_image *reference,
                          const rayo_image *image, uint64_t reference_surplus,
                          uint64_t image_surplus,
                          const rayo_read_report *clamped)
{
    rayo_compare_report report;
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    int status;
    rayo_compare_options options = req->options;
    rayo_error_clear(&err);
    options.lossy = clamped->format == RAYO_FORMAT_JPEG;
    if (rayo_compare_images(reference, image, &options, &report, &err) !=
        RAYO_OK)
        return cli_report(&err);
    report.reference_surplus = reference_surplus;
    report.image_surplus = image_surplus;
    rayo_compare_note_clamped(&report, clamped);
    note_kinds(req, reference, image, &report);
    if (req->diff != NULL &&
        (status = write_diff(req->diff, reference, image, &req->options)) !=
            CLI_EXIT_OK)
        return status;
    if ((status = print_report(&report, req->json)) != CLI_EXIT_OK)
        return status;
    if ((status = cli_flush_text(stdout, _("standard output"))) != CLI_EXIT_OK)
        return status;
    return report.verdict == RAYO_VERDICT_INCONSISTENT ? CLI_EXIT_FAILURE
                                                        : CLI_EXIT_OK;
}

/* One input read on a thread of its own, so both files are read at
 * once (two plain 4096x4096 PBMs are 34 MB of text). */
typedef struct input {
    const char *path;
    int clamp; /* the image: samples out of range clamped and counted */
    rayo_image image;
    rayo_read_report read;
    rayo_error err;
    rayo_status status;
} input;

/* The pixels a file held beyond its raster (a part of one counts). */
static uint64_t surplus_pixels(const input *in)
{
    unsigned per = in->image.info.channels > 0 ? in->image.info.channels : 1;
    return (in->read.trailing_samples + per - 1) / per;
}

static void *read_input(void *context)
{
    input *in = context;
    rayo_error_init(&in->err, cli_lang());
    rayo_read_options options;
    memset(&options, 0, sizeof options);
    options.clamp = in->clamp;
    in->status = rayo_image_read_file_with(in->path, &options, &in->image,
                                           &in->read, &in->err);
    return NULL;
}

/* Reads both; on failure reports the reference's error first. */
static int read_both(input *ref, input *img)
{
    pthread_t thread;
    int threaded = pthread_create(&thread, NULL, read_input, ref) == 0;
    if (!threaded)
        read_input(ref);
    read_input(img);
    if (threaded)
        pthread_join(thread, NULL);
    if (ref->status == RAYO_OK && img->status == RAYO_OK)
        return CLI_EXIT_OK;
    rayo_image_free(&ref->image);
    rayo_image_free(&img->image);
    return cli_unreadable(ref->status != RAYO_OK ? &ref->err : &img->err);
}

int cli_compare(int argc, char **argv)
{
    compare_request req;
    input reference, image;
    int status;
    memset(&req, 0, sizeof req);
    memset(&reference, 0, sizeof reference);
    memset(&image, 0, sizeof image);
    rayo_compare_options_init(&req.options);
    req.options.lang = cli_lang();
    status = parse_request(argc, argv, &req);
    if (status != CLI_EXIT_OK)
        return status < 0 ? CLI_EXIT_OK : status;
    reference.path = req.reference;
    image.path = req.image;
    image.clamp = 1; /* a student's unclamped values are a diagnosis */
    if ((status = read_both(&reference, &image)) != CLI_EXIT_OK)
        return status;
    status = compare_images(&req, &reference.image, &image.image,
                            surplus_pixels(&reference), surplus_pixels(&image),
                            &image.read);
    rayo_image_free(&reference.image);
    rayo_image_free(&image.image);
    return status;
}

/* cli_parse.h: the options parsed as `rayo compare` parses them, nothing
 * run. */
int cli_parse_compare(int argc, char **argv)
{
    compare_request req;
    int status;
    memset(&req, 0, sizeof req);
    rayo_compare_options_init(&req.options);
    status = parse_request(argc, argv, &req);
    return status < 0 ? CLI_EXIT_OK : status;
}
