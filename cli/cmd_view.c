/*
 * cmd_view.c - `rayo view FILE`: an image in the terminal, as text
 * (preview.h), scaled to fit the width.
 *
 * Width: --cols N, else $COLUMNS when it is a number, else 80.  Blocks by
 * default: gray and colour images in colour blocks when standard output
 * is a terminal (24-bit when $COLORTERM says so, else 256 colours; none
 * under $NO_COLOR; --color=WHEN decides otherwise), bilevel images and
 * everything else as the black/white silhouette.  --braille for finer
 * detail, --ascii for terminals without Unicode (both silhouettes).
 * `rayo render --preview` draws the same picture (render_preview.c).
 */
#define _POSIX_C_SOURCE 200809L

#include <getopt.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "cli_parse.h"
#include "render_preview.h"

static void print_help(void)
{
    printf(_("usage: rayo view FILE [--cols N] [--braille | --ascii] "
             "[--color[=WHEN]]\n\n"
             "Shows FILE (PBM, PGM, PPM or PNG; '-' = standard input) in the "
             "terminal, shrunk\nto fit the width, two pixels a character "
             "cell (Unicode half blocks).\n\n"
             "Gray and colour images are drawn in colour, each half the mean "
             "of the pixels it\ncovers: 24-bit colour when $COLORTERM is "
             "'truecolor' or '24bit', else xterm's\n256 colours.  Only on a "
             "terminal, and not when $NO_COLOR is set (--color\nchanges "
             "that).  Otherwise, and for bilevel images, the picture is a "
             "black/white\nsilhouette (gray and colour black below half the "
             "maximum), black pixels drawn\nas ink: half blocks, Braille "
             "patterns (2x4) or ASCII ('#' black, '+' partly).\n\n"
             "options:\n"
             "      --cols N     at most N characters a line (default: "
             "$COLUMNS, else 80)\n"
             "      --braille    Braille patterns: the finest detail "
             "(silhouette)\n"
             "      --ascii      plain ASCII, for terminals without Unicode "
             "(silhouette)\n"
             "      --color[=WHEN]  auto (default: colour on a terminal "
             "without $NO_COLOR),\n"
             "                   always (into files and pipes too, as for "
             "'less -R') or never\n"
             "      --lang es|en the language of messages (default: from the\n"
             "                   environment: LANGUAGE, LC_ALL, LC_MESSAGES, "
             "LANG)\n"
             "  -h, --help       this help\n\n"
             "FILE may be course:ej1, course:ej2 or course:ej3, the course's "
             "reference images\n(a file of that very name wins).\n\n"
             "exit status: 0 success, 1 the output could not be written, 2 bad "
             "options or an\ninput that cannot be read (missing, unreadable, "
             "a directory, malformed or\ntoo large).\n"));
}

/* The columns of the terminal: $COLUMNS when it is a sensible number. */
unsigned cli_terminal_columns(void)
{
    const char *env = getenv("COLUMNS");
    char *end;
    unsigned long v;
    if (env == NULL || *env < '0' || *env > '9')
        return 80;
    v = strtoul(env, &end, 10);
    if (*end != '\0' || v < 1 || v > 10000)
        return 80;
    return (unsigned)v;
}

rayo_preview_color cli_preview_color(FILE *stream, cli_color_when when)
{
    const char *no_color = getenv("NO_COLOR"), *term = getenv("COLORTERM");
    if (when == CLI_COLOR_NEVER)
        return RAYO_PREVIEW_COLOR_NONE;
    if (when == CLI_COLOR_AUTO &&
        ((no_color != NULL && *no_color != '\0') || !isatty(fileno(stream))))
        return RAYO_PREVIEW_COLOR_NONE;
    if (term != NULL &&
        (strcmp(term, "truecolor") == 0 || strcmp(term, "24bit") == 0))
        return RAYO_PREVIEW_COLOR_TRUECOLOR;
    return RAYO_PREVIEW_COLOR_256;
}

/* --color's WHEN (none: always); 0 and a message for anything else. */
static int parse_color(const char *text, cli_color_when *when)
{
    if (text == NULL || strcmp(text, "always") == 0)
        *when = CLI_COLOR_ALWAYS;
    else if (strcmp(text, "auto") == 0)
        *when = CLI_COLOR_AUTO;
    else if (strcmp(text, "never") == 0)
        *when = CLI_COLOR_NEVER;
    else {
        cli_usage_error(_("--color: %s; expected auto, always or never"),
                        cli_quote(text));
        return 0;
    }
    return 1;
}

int cli_print_preview(const rayo_image *image,
                      const rayo_preview_options *options, FILE *stream)
{
    char *text;
    size_t length;
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    rayo_error_clear(&err);
    if (rayo_preview_render(image, options, &text, &length, NULL, NULL,
                            &err) != RAYO_OK)
        return cli_report(&err);
    fwrite(text, 1, length, stream);
    free(text);
    return cli_flush_text(stream, stream == stdout ? _("standard output")
                                                   : _("standard error"));
}

/* Options into *options, colour included (for the style, cli_view
 * looks at the image). */
static int parse_options(int argc, char **argv,
                         rayo_preview_options *options, const char **file)
{
    cli_color_when when = CLI_COLOR_AUTO;
    static const struct option long_options[] = {
        {"cols", required_argument, NULL, 'c'},
        {"ascii", no_argument, NULL, 'a'},
        {"braille", no_argument, NULL, 'b'},
        {"color", optional_argument, NULL, 'C'},
        {"lang", required_argument, NULL, 'L'},
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0}};
    unsigned long cols;
    int c;
    opterr = 0;
    optind = 0;
    while ((c = getopt_long(argc, argv, ":h", long_options, NULL)) != -1) {
        switch (c) {
        case 'c':
            if (!cli_parse_uint("--cols", optarg, 1, 10000, &cols))
                return CLI_EXIT_USAGE;
            options->columns = (unsigned)cols;
            break;
        case 'a':
            options->style = RAYO_PREVIEW_ASCII;
            break;
        case 'b':
            options->style = RAYO_PREVIEW_BRAILLE;
            break;
        case 'C':
            if (!parse_color(optarg, &when))
                return CLI_EXIT_USAGE;
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
    if (argc - optind != 1)
        return cli_wrong_operands("view", argc - optind, N_("one FILE"));
    *file = argv[optind];
    options->color = cli_preview_color(stdout, when);
    return CLI_EXIT_OK;
}

int cli_view(int argc, char **argv)
{
    rayo_preview_options options;
    rayo_image image;
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    const char *file = NULL;
    char course_path[4096];
    int status;
    rayo_preview_options_init(&options);
    options.columns = cli_terminal_columns();
    status = parse_options(argc, argv, &options, &file);
    if (status != CLI_EXIT_OK)
        return status < 0 ? CLI_EXIT_OK : status;
    status = cli_image_operand(file, course_path, sizeof course_path, &file);
    if (status != CLI_EXIT_OK)
        return status;
    rayo_error_clear(&err);
    memset(&image, 0, sizeof image);
    if (rayo_image_read_file(file, &image, NULL, &err) != RAYO_OK)
        return cli_unreadable(&err);
    /* Colour blocks for gray and colour; a bilevel image's silhouette is
     * already all it holds. */
    if (options.style == RAYO_PREVIEW_BLOCKS &&
        image.info.sample != RAYO_SAMPLE_BIT)
        options.style = RAYO_PREVIEW_COLOR_BLOCKS;
    status = cli_print_preview(&image, &options, stdout);
    rayo_image_free(&image);
    return status;
}

/* cli_parse.h: the options parsed as `rayo view` parses them, nothing
 * run. */
int cli_parse_view(int argc, char **argv)
{
    rayo_preview_options options;
    const char *file = NULL;
    int status;
    rayo_preview_options_init(&options);
    options.columns = 80;
    status = parse_options(argc, argv, &options, &file);
    return status < 0 ? CLI_EXIT_OK : status;
}
