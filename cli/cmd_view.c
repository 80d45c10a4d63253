/*
 * cmd_view.c - `rayo view FILE`: an image in the terminal, as text
 * (preview.h), scaled to fit the width.
 *
 * Width: --cols N, else $COLUMNS when it is a number, else 80.  Blocks by
 * default; --braille for finer detail, --ascii for terminals without
 * Unicode.  `rayo render --preview` uses the same library call.
 */
#define _POSIX_C_SOURCE 200809L

#include <getopt.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

static void print_help(void)
{
    printf("usage: rayo view FILE [--cols N] [--braille | --ascii]\n\n"
           "Shows FILE (PBM, PGM, PPM or PNG; '-' = standard input) in the "
           "terminal, shrunk\nto fit the width: black pixels are drawn as "
           "ink, in Unicode half blocks\n(two pixels a character cell), "
           "Braille patterns (2x4) or ASCII ('#' black,\n'+' partly black). "
           "Gray and colour are shown black below half the maximum.\n\n"
           "options:\n"
           "      --cols N     at most N characters a line (default: "
           "$COLUMNS, else 80)\n"
           "      --braille    Braille patterns: the finest detail\n"
           "      --ascii      plain ASCII, for terminals without Unicode\n"
           "  -h, --help       this help\n\n"
           "exit status: 0 success, 1 output failure, 2 unreadable input or "
           "bad options.\n");
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

int cli_print_preview(const rayo_image *image,
                      const rayo_preview_options *options, FILE *stream)
{
    char *text;
    size_t length;
    rayo_error err;
    rayo_error_clear(&err);
    if (rayo_preview_render(image, options, &text, &length, NULL, NULL,
                            &err) != RAYO_OK)
        return cli_report(&err);
    fwrite(text, 1, length, stream);
    free(text);
    return cli_flush_text(stream, stream == stdout ? "standard output"
                                                   : "standard error");
}

static int parse_options(int argc, char **argv,
                         rayo_preview_options *options, const char **file)
{
    static const struct option long_options[] = {
        {"cols", required_argument, NULL, 'c'},
        {"ascii", no_argument, NULL, 'a'},
        {"braille", no_argument, NULL, 'b'},
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
        case 'h':
            print_help();
            return -1;
        default:
            return cli_bad_option(c, argv, optind);
        }
    }
    if (argc - optind != 1)
        return cli_wrong_operands("view", argc - optind, "one FILE");
    *file = argv[optind];
    return CLI_EXIT_OK;
}

int cli_view(int argc, char **argv)
{
    rayo_preview_options options;
    rayo_image image;
    rayo_error err;
    const char *file = NULL;
    int status;
    rayo_preview_options_init(&options);
    options.columns = cli_terminal_columns();
    status = parse_options(argc, argv, &options, &file);
    if (status != CLI_EXIT_OK)
        return status < 0 ? CLI_EXIT_OK : status;
    rayo_error_clear(&err);
    memset(&image, 0, sizeof image);
    if (rayo_image_read_file(file, &image, NULL, &err) != RAYO_OK)
        return cli_unreadable(&err);
    status = cli_print_preview(&image, &options, stdout);
    rayo_image_free(&image);
    return status;
}
