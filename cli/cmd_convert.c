/*
 * cmd_convert.c - `rayo convert IN OUT`: read any image rayo reads, write
 * it in the format OUT's extension (or --format) names.
 *
 * The reading, the layout conversions and the writing are the library's
 * (reader.h, image_convert.h, writer.h); this file picks the format,
 * converts the layout when the target cannot hold it (colour or gray to
 * PBM is thresholded at half the maximum, colour to PGM is luminance,
 * bilevel or gray to PPM is repeated), and reports.  Netpbm keeps the
 * input's encoding (plain stays plain, raw stays raw; a PNG becomes raw)
 * unless --plain or --raw says otherwise.  The output file is written
 * only after the input was read whole, and appears whole or not at all.
 * An OUT of '-' on a terminal gets the picture `rayo view` draws, and a
 * line on how to save the image, never its bytes.
 */
#define _POSIX_C_SOURCE 200809L

#include <getopt.h>
#include <string.h>

#include "cli.h"
#include "cli_parse.h"
#include "output_guard.h"
#include "render_preview.h"

typedef struct convert_request {
    const char *input;
    const char *output;
    const char *format; /* NULL: from the output's name */
    int plain, raw;     /* --plain, --raw; neither: the input's encoding */
    unsigned long quality; /* --quality, JPEG: 0 for libjpeg's 90 */
    int verbose;
    char course_path[4096]; /* IN as course:NAME, resolved */
} convert_request;

static void print_help(void)
{
    printf(
        _("usage: rayo convert [OPTIONS] IN OUT\n\n"
          "Reads IN (PBM, PGM, PPM plain or raw, PNG, BMP or JPEG; the format "
          "is\nrecognised from the content) and writes it to OUT in the format "
          "of OUT's\nextension (.pbm, .pgm, .ppm, .png, .bmp, .jpg) or of "
          "--format.  '-' is\nstandard input or output; IN may be course:ej1, "
          "course:ej2 or course:ej3,\nthe course's reference images.\n\n"
          "When the target cannot hold the image as it is, it is converted:\n"
          "  to PBM  black where the pixel is darker than half the maximum\n"
          "          (colour: 2(299r+587g+114b) < 1000 maxval)\n"
          "  to PGM  colour becomes its luminance (299r+587g+114b)/1000, "
          "rounded;\n"
          "          bilevel becomes 0 (black) and 255 (white)\n"
          "  to PPM  gray is repeated in the three channels; bilevel as above\n"
          "  to PNG  kept as it is (bilevel as 1-bit gray)\n"
          "  to BMP  colour as 24 bits (B, G, R, rows bottom up, as the "
          "course's TP1);\n"
          "          gray and bilevel through a palette of 8 and 1 bits\n"
          "  to JPEG colour as colour, gray and bilevel as gray; lossy "
          "(--quality)\n"
          "Transparent PNG pixels are composited over white.\n\n"
          "options:\n"
          "      --format FMT   pbm, pgm, ppm, png, bmp or jpeg; needed for a "
          "'-' OUT\n"
          "                     unless the Netpbm format that holds the image "
          "as it is\n"
          "                     will do (PBM bilevel, PGM gray, PPM colour)\n"
          "      --plain        plain Netpbm (P1-P3, ASCII)\n"
          "      --raw          raw Netpbm (P4-P6); without either, a Netpbm "
          "input's\n"
          "                     encoding is kept, and a PNG, BMP or JPEG "
          "becomes raw\n"
          "      --quality N    JPEG quality, 1-100 (default 90)\n"
          "  -v, --verbose      on stderr: what was read (format, size, "
          "maxval, bytes\n"
          "                     after the image) and what was written\n"
          "      --lang es|en   the language of messages (default: from the\n"
          "                     environment: LANGUAGE, LC_ALL, LC_MESSAGES, "
          "LANG)\n"
          "  -h, --help         this help\n\n"
          "exit status: 0 success, 1 OUT could not be written, 2 bad options "
          "or an input\nthat cannot be read (missing, unreadable, a "
          "directory, malformed or too\nlarge; one line on stderr names the "
          "file and why).  OUT is never left\nhalf-written.\n"));
}

static int parse_request(int argc, char **argv, convert_request *req)
{
    static const struct option options[] = {
        {"format", required_argument, NULL, 'F'},
        {"plain", no_argument, NULL, 'p'},
        {"raw", no_argument, NULL, 'r'},
        {"quality", required_argument, NULL, 'Q'},
        {"verbose", no_argument, NULL, 'v'},
        {"lang", required_argument, NULL, 'L'},
        {"help", no_argument, NULL, 'h'},
        {NULL, 0, NULL, 0}};
    int c;
    opterr = 0;
    optind = 0;
    while ((c = getopt_long(argc, argv, ":vh", options, NULL)) != -1) {
        switch (c) {
        case 'F':
            req->format = optarg;
            break;
        case 'p':
            req->plain = 1;
            break;
        case 'r':
            req->raw = 1;
            break;
        case 'Q':
            if (!cli_parse_uint("--quality", optarg, 1, 100, &req->quality))
                return CLI_EXIT_USAGE;
            break;
        case 'v':
            req->verbose = 1;
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
    if (req->plain && req->raw)
        return cli_usage_error(_("--plain and --raw: give one of them"));
    if (argc - optind != 2)
        return cli_wrong_operands("convert", argc - optind, N_("IN and OUT"));
    req->input = argv[optind];
    req->output = argv[optind + 1];
    c = cli_image_operand(req->input, req->course_path,
                          sizeof req->course_path, &req->input);
    return c;
}

/* info is NULL unless OUT is '-' without --format. */
static int choose_format(const convert_request *req,
                         const rayo_image_info *info, rayo_format *format)
{
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    if (req->format != NULL) {
        if (rayo_format_parse(req->format, format, &err) != RAYO_OK)
            return cli_usage_error(_("--format: %s is not a format; "
                                     "expected pbm, pgm, ppm, png, bmp or "
                                     "jpeg"),
                                   cli_quote(req->format));
    } else if (info != NULL) {
        *format = rayo_format_netpbm_for(info);
    } else if (rayo_format_from_path(req->output, format, &err) != RAYO_OK) {
        return cli_usage_error(_("convert: %s"), err.message);
    }
    if ((req->plain || req->raw) && !rayo_format_is_netpbm(*format))
        return cli_usage_error(_("%s: applies only to PBM, PGM and PPM, "
                                 "not %s"),
                               req->plain ? "--plain" : "--raw",
                               rayo_format_name(*format));
    return CLI_EXIT_OK;
}

/* Plain or raw: as asked, else as the input was (a PNG: raw); and no
   binary on a terminal. */
static int choose_encoding(const convert_request *req,
                           const rayo_read_report *report,
                           rayo_write_options *options)
{
    options->plain = req->plain ||
                     (!req->raw && rayo_format_is_netpbm(report->format) &&
                      report->plain);
    return CLI_EXIT_OK;
}

/* OUT is '-' on a terminal: the picture `rayo view` draws, and how to
   save the image instead. */
static int show_on_terminal(const rayo_image *image)
{
    rayo_preview_options options;
    int status;
    rayo_preview_options_init(&options);
    options.columns = cli_terminal_columns();
    if (image->info.sample != RAYO_SAMPLE_BIT)
        options.style = RAYO_PREVIEW_COLOR_BLOCKS;
    options.color = cli_preview_color(stdout, CLI_COLOR_AUTO);
    status = cli_print_preview(image, &options, stdout);
    if (status == CLI_EXIT_OK)
        cli_say(_("this is a picture of the image, because standard output "
                  "is a terminal; to save it, give OUT a file name, as in "
                  "'rayo convert IN esfera.png'"));
    return status;
}

/* The image in a layout the format holds: converted into *converted, or
   image itself when it already fits. */
static rayo_status fit_layout(const rayo_image *image, rayo_format format,
                              rayo_image *converted, const rayo_image **fit,
                              rayo_error *err)
{
    const rayo_image_info *info = &image->info;
    rayo_status status = RAYO_OK;
    *fit = image;
    switch (format) {
    case RAYO_FORMAT_PBM:
        if (info->sample != RAYO_SAMPLE_BIT)
            status = rayo_image_to_bit(image, converted, err);
        break;
    case RAYO_FORMAT_PGM:
        if (info->sample == RAYO_SAMPLE_BIT || info->channels != 1)
            status = rayo_image_to_gray(image, converted, err);
        break;
    case RAYO_FORMAT_PPM:
        if (info->channels != 3)
            status = rayo_image_to_rgb(image, converted, err);
        break;
    case RAYO_FORMAT_PNG:
    case RAYO_FORMAT_BMP:
    case RAYO_FORMAT_JPEG:
        return RAYO_OK;
    }
    if (status == RAYO_OK && converted->pixels != NULL)
        *fit = converted;
    return status;
}

static const char *layout_name(const rayo_image_info *info)
{
    if (info->sample == RAYO_SAMPLE_BIT)
        return _("bilevel");
    return info->channels == 1 ? _("gray") : _("RGB");
}

/* "plain pbm", "raw ppm", "png" into text. */
static const char *encoding_name(rayo_format format, int plain, char *text,
                                 size_t room)
{
    if (!rayo_format_is_netpbm(format))
        return rayo_format_name(format);
    if (plain)
        snprintf(text, room, _("plain %s"), rayo_format_name(format));
    else
        snprintf(text, room, _("raw %s"), rayo_format_name(format));
    return text;
}

static void report_read(const convert_request *req, const rayo_image *image,
                        const rayo_read_report *report)
{
    const rayo_image_info *info = &image->info;
    const char *name =
        strcmp(req->input, "-") == 0 ? _("standard input") : req->input;
    unsigned long long bytes = report->trailing_bytes;
    char text[64];
    const char *kind =
        encoding_name(report->format, report->plain, text, sizeof text);
    cli_sayf(bytes > 0 ? _n("%s: %s, %lux%lu, %s, maxval %u; %llu byte after "
                            "the image (ignored)",
                            "%s: %s, %lux%lu, %s, maxval %u; %llu bytes "
                            "after the image (ignored)",
                            (unsigned long)bytes)
                       : _n("%s: %s, %lux%lu, %s, maxval %u; %llu byte after "
                            "the image",
                            "%s: %s, %lux%lu, %s, maxval %u; %llu bytes "
                            "after the image",
                            (unsigned long)bytes),
             name, kind, (unsigned long)info->width,
             (unsigned long)info->height, layout_name(info), info->maxval,
             bytes);
}

static void report_written(const convert_request *req, const rayo_image *fit,
                           const rayo_write_options *options)
{
    char kind[64];
    cli_sayf(_("%s: wrote %s, %s, maxval %u"),
             strcmp(req->output, "-") == 0 ? _("standard output") : req->output,
             encoding_name(options->format, options->plain, kind, sizeof kind),
             layout_name(&fit->info), fit->info.maxval);
}

static rayo_status write_image(const convert_request *req,
                               const rayo_image *fit,
                               const rayo_write_options *options,
                               rayo_error *err)
{
    rayo_output *out;
    rayo_status status = cli_output_open(&out, req->output, err);
    if (status != RAYO_OK)
        return status;
    status = rayo_image_write(fit, out, options, err);
    if (status != RAYO_OK) {
        cli_output_abort(out);
        return status;
    }
    return cli_output_commit(out, err);
}

/* Everything after the options: read, fit, write. */
static int convert(const convert_request *req)
{
    rayo_image image, converted;
    const rayo_image *fit;
    rayo_read_report report;
    rayo_write_options options;
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    int exit_status;
    /* Only a '-' OUT without --format waits for the image to decide. */
    int decided = req->format != NULL || strcmp(req->output, "-") != 0;
    memset(&converted, 0, sizeof converted);
    memset(&options, 0, sizeof options);
    options.quality = (unsigned)req->quality;
    rayo_error_clear(&err);
    if (decided) {
        exit_status = choose_format(req, NULL, &options.format);
        if (exit_status != CLI_EXIT_OK)
            return exit_status;
    }
    if (rayo_image_read_file(req->input, &image, &report, &err) != RAYO_OK)
        return cli_unreadable(&err);
    if (req->verbose)
        report_read(req, &image, &report);
    if (strcmp(req->output, "-") == 0 && cli_stdout_is_terminal()) {
        exit_status = show_on_terminal(&image);
        rayo_image_free(&image);
        return exit_status;
    }
    exit_status = decided ? CLI_EXIT_OK
                          : choose_format(req, &image.info, &options.format);
    if (exit_status == CLI_EXIT_OK)
        exit_status = choose_encoding(req, &report, &options);
    if (exit_status == CLI_EXIT_OK &&
        (fit_layout(&image, options.format, &converted, &fit, &err) !=
             RAYO_OK ||
         write_image(req, fit, &options, &err) != RAYO_OK))
        exit_status = cli_report(&err);
    else if (exit_status == CLI_EXIT_OK && req->verbose)
        report_written(req, fit, &options);
    rayo_image_free(&converted);
    rayo_image_free(&image);
    return exit_status;
}

int cli_convert(int argc, char **argv)
{
    convert_request req;
    int exit_status;
    memset(&req, 0, sizeof req);
    exit_status = parse_request(argc, argv, &req);
    if (exit_status != CLI_EXIT_OK)
        return exit_status < 0 ? CLI_EXIT_OK : exit_status;
    return convert(&req);
}

/* cli_parse.h: the options parsed as `rayo convert` parses them, nothing
 * run. */
int cli_parse_convert(int argc, char **argv)
{
    convert_request req;
    rayo_format format;
    int status;
    memset(&req, 0, sizeof req);
    status = parse_request(argc, argv, &req);
    if (status == CLI_EXIT_OK &&
        (req.format != NULL || strcmp(req.output, "-") != 0))
        status = choose_format(&req, NULL, &format);
    return status < 0 ? CLI_EXIT_OK : status;
}
