/*
 * cmd_render.c - `rayo render`: options to camera and scene, the renderer
 * to a writer, the writer to an output file that appears whole or not at
 * all.
 *
 * With no options it is the assignment: the seed's sphere, 640x480, a
 * 90 degree field of view, plain PBM on standard output.  A scene file
 * with nothing in it, or without a camera, still renders, with one line
 * of warning saying so (an empty picture is rarely what was meant).
 * An image bound for a terminal (standard output on one) is shown as
 * `rayo view` would, with one line saying how to save it, never poured
 * out as bytes.
 */
#define _POSIX_C_SOURCE 200809L

#include <getopt.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cli.h"
#include "cli_parse.h"
#include "interrupt.h"
#include "progress.h"
#include "render_preview.h"

#define MAX_SPHERES_ON_COMMAND_LINE 4096

typedef struct render_request {
    unsigned long width, height;
    double fov;
    rayo_vec3 origin;
    double spheres[MAX_SPHERES_ON_COMMAND_LINE][4];
    size_t sphere_count;
    const char *output;  /* "-" for standard output */
    const char *format;  /* NULL: from the output's extension */
    int raw;
    unsigned long quality; /* --quality, JPEG: 0 for libjpeg's 90 */
    unsigned long threads;
    int quiet; /* --quiet: no progress bar */
    int preview; /* --preview: the image in the terminal afterwards */
    const char *scene_path; /* SCENE argument, or NULL */
    rayo_scene_file file;   /* what it holds, once loaded */
    int width_given, height_given, fov_given, origin_given;
    int shade_given, depth_given;
    rayo_shade_mode shade;
    unsigned long samples; /* 0: the scene's or the default */
    unsigned long depth;
} render_request;

/* The render's progress callback: draws the bar, stops on a signal
   (which the rendering threads see sooner, through options.cancel). */
static int stop_requested(void *context, uint32_t done, uint32_t total)
{
    cli_progress_update(context, done, total);
    return cli_interrupted() != 0;
}

static void print_help(void)
{
    printf(
        _("usage: rayo [render] [OPTIONS]\n"
          "       rayo render SCENE [OPTIONS]\n\n"
          "Traces rays from the camera through each pixel.  With no options: "
          "the\nassignment's sphere (centre 0.5,0.75,1.9, radius 0.8), "
          "640x480, field of view 90,\nblack where a ray hits it, as plain "
          "PBM (P1) on standard output.  SCENE is a\nscene file "
          "(docs/scene-format.md): camera, lights, materials, spheres, "
          "planes,\ntriangles; the options below override its camera and "
          "settings.\n\n"
          "options:\n"
          "  -W, --width N          image width in pixels (1-65536; default "
          "640)\n"
          "  -H, --height N         image height in pixels (1-65536; default "
          "480)\n"
          "                         at most 2^30 pixels in all\n"
          "      --fov DEG          horizontal field of view, degrees, "
          "0 < DEG < 180 (default 90)\n"
          "      --origin X,Y,Z     camera position (default 0,0,0); it looks "
          "down +z, +y up\n"
          "                         (or at the scene's look-at point)\n"
          "      --shade MODE       hit (black/white, PBM), course-gray (PGM), "
          "course-color\n"
          "                         (PPM), phong (PPM) or course-tp1 (PPM); "
          "default: the\n"
          "                         scene's 'shade', else phong for a scene, "
          "hit without one\n"
          "      --samples N        N x N rays per pixel, stratified (1-16; "
          "default 1)\n"
          "      --depth N          phong, course-tp1: mirror bounces followed\n"
          "                         (0-64; default 5)\n"
          "      --sphere CX,CY,CZ,R\n"
          "                         a sphere (repeatable; R > 0); the first "
          "replaces the\n"
          "                         assignment's sphere\n"
          "  -o, --output FILE      write to FILE ('-' = standard output, "
          "the default);\n"
          "                         a file appears whole or not at all\n"
          "      --format FMT       the mode's Netpbm format (pbm, pgm, ppm), "
          "png, bmp or jpeg\n"
          "                         (default: from FILE's extension, else "
          "the mode's\n"
          "                         Netpbm format)\n"
          "      --raw              raw Netpbm (P4-P6) instead of plain "
          "(P1-P3)\n"
          "      --quality N        JPEG quality, 1-100 (default 90)\n"
          "  -j, --threads N        threads reading the scene, building its "
          "hierarchy\n"
          "                         and rendering (default: one per CPU)\n"
          "  -q, --quiet            no progress bar (otherwise drawn on a "
          "terminal's\n"
          "                         stderr for renders longer than a "
          "second)\n"
          "      --preview          then show the image in the terminal, "
          "as 'rayo view'\n"
          "                         does: on stdout, or on stderr when the "
          "image itself\n"
          "                         goes to stdout\n"
          "      --lang es|en       the language of messages (default: from "
          "the\n"
          "                         environment: LANGUAGE, LC_ALL, "
          "LC_MESSAGES, LANG)\n"
          "  -h, --help             this help\n"
          "  -V, --version          the version\n\n"
          "pixels: column i, row j is the point x = i - w/2, y = j - h/2 "
          "(rows from the\ntop); its ray has direction (x, -y, w/(2 "
          "tan(fov/2))), normalised.\n\n"
          "exit status: 0 success, 1 the output could not be written, 2 bad "
          "options or an\ninput that cannot be read (SCENE missing, "
          "unreadable, a directory, malformed).\n"));
}

/* What a request holds before its options: the seed's picture, to
 * standard output. */
static void request_defaults(render_request *req)
{
    req->width = RAYO_SEED_WIDTH;
    req->height = RAYO_SEED_HEIGHT;
    req->fov = RAYO_SEED_FOV;
    req->origin = rayo_vec3_make(0, 0, 0);
    req->output = "-";
}

static int parse_request(int argc, char **argv, render_request *req)
{
    static const struct option options[] = {
        {"width", required_argument, NULL, 'W'},
        {"height", required_argument, NULL, 'H'},
        {"fov", required_argument, NULL, 'f'},
        {"origin", required_argument, NULL, 'O'},
        {"sphere", required_argument, NULL, 's'},
        {"output", required_argument, NULL, 'o'},
        {"format", required_argument, NULL, 'F'},
        {"raw", no_argument, NULL, 'r'},
        {"quality", required_argument, NULL, 'Q'},
        {"threads", required_argument, NULL, 'j'},
        {"quiet", no_argument, NULL, 'q'},
        {"preview", no_argument, NULL, 'P'},
        {"shade", required_argument, NULL, 'S'},
        {"samples", required_argument, NULL, 'N'},
        {"depth", required_argument, NULL, 'D'},
        {"lang", required_argument, NULL, 'L'},
        {"help", no_argument, NULL, 'h'},
        {"version", no_argument, NULL, 'V'},
        {NULL, 0, NULL, 0}};
    int c;
    opterr = 0;
    optind = 0;
    while ((c = getopt_long(argc, argv, ":W:H:o:j:qhV", options, NULL)) != -1) {
        double v[4];
        switch (c) {
        case 'W':
            if (!cli_parse_uint("--width", optarg, 1, RAYO_MAX_DIMENSION,
                                &req->width))
                return CLI_EXIT_USAGE;
            req->width_given = 1;
            break;
        case 'H':
            if (!cli_parse_uint("--height", optarg, 1, RAYO_MAX_DIMENSION,
                                &req->height))
                return CLI_EXIT_USAGE;
            req->height_given = 1;
            break;
        case 'f':
            if (!cli_parse_double("--fov", optarg, &req->fov))
                return CLI_EXIT_USAGE;
            if (!(req->fov > 0 && req->fov < 180))
                return cli_usage_error(_("--fov: %s is out of range; "
                                         "expected degrees strictly between "
                                         "0 and 180"),
                                       cli_quote(optarg));
            req->fov_given = 1;
            break;
        case 'O':
            if (!cli_parse_numbers("--origin", optarg, 3, "X,Y,Z", v))
                return CLI_EXIT_USAGE;
            req->origin = rayo_vec3_make(v[0], v[1], v[2]);
            req->origin_given = 1;
            break;
        case 's':
            if (!cli_parse_numbers("--sphere", optarg, 4, "CX,CY,CZ,R", v))
                return CLI_EXIT_USAGE;
            if (!(v[3] > 0))
                return cli_usage_error(_("--sphere: radius in %s must be "
                                         "greater than 0"),
                                       cli_quote(optarg));
            if (req->sphere_count == MAX_SPHERES_ON_COMMAND_LINE)
                return cli_usage_error(_("--sphere: more than %d spheres; use "
                                         "a scene file"),
                                       MAX_SPHERES_ON_COMMAND_LINE);
            memcpy(req->spheres[req->sphere_count++], v, sizeof v);
            break;
        case 'o':
            req->output = optarg;
            break;
        case 'F':
            req->format = optarg;
            break;
        case 'Q':
            if (!cli_parse_uint("--quality", optarg, 1, 100, &req->quality))
                return CLI_EXIT_USAGE;
            break;
        case 'r':
            req->raw = 1;
            break;
        case 'j':
            if (!cli_parse_uint("--threads", optarg, 1, RAYO_MAX_THREADS,
                                &req->threads))
                return CLI_EXIT_USAGE;
            break;
        case 'S':
            if (rayo_shade_mode_parse(optarg, &req->shade, NULL) != RAYO_OK)
                return cli_usage_error(_("--shade: %s is not accepted; "
                                         "expected hit, course-gray, "
                                         "course-color, phong or "
                                         "course-tp1"),
                                       cli_quote(optarg));
            req->shade_given = 1;
            break;
        case 'N':
            if (!cli_parse_uint("--samples", optarg, 1, RAYO_MAX_SAMPLES,
                                &req->samples))
                return CLI_EXIT_USAGE;
            break;
        case 'D':
            if (!cli_parse_uint("--depth", optarg, 0, RAYO_MAX_DEPTH,
                                &req->depth))
                return CLI_EXIT_USAGE;
            req->depth_given = 1;
            break;
        case 'q':
            req->quiet = 1;
            break;
        case 'P':
            req->preview = 1;
            break;
        case 'L': /* --lang: read before (lang.c) */
            break;
        case 'h':
            print_help();
            return -1;
        case 'V':
            printf("rayo %s\n", RAYO_VERSION);
            return -1;
        default:
            return cli_bad_option(c, argv, optind);
        }
    }
    if (optind < argc)
        req->scene_path = argv[optind++];
    if (optind < argc)
        return cli_usage_error(_("render: unexpected argument %s; see "
                                 "'rayo --help'"),
                               cli_quote(argv[optind]));
    if (req->scene_path != NULL && strcmp(req->output, "-") != 0 &&
        cli_same_file(req->output, req->scene_path))
        return cli_usage_error(_("--output: '%s' is the scene file; refusing "
                                 "to overwrite an input"),
                               req->output);
    if (req->scene_path != NULL && req->sphere_count > 0)
        return cli_usage_error(_("--sphere: cannot be combined with the scene "
                                 "file '%s'; put the sphere in the file"),
                               req->scene_path);
    if ((unsigned long long)req->width * req->height > RAYO_MAX_PIXELS)
        return cli_usage_error(_("--width %lu --height %lu: %llu pixels; "
                                 "expected at most %lu (2^30)"),
                               req->width, req->height,
                               (unsigned long long)req->width * req->height,
                               RAYO_MAX_PIXELS);
    return CLI_EXIT_OK;
}

/* The shading mode asked for: --shade, else the scene's, else hit. */
static rayo_shade_mode effective_shade(const render_request *req)
{
    if (req->shade_given)
        return req->shade;
    return req->scene_path != NULL ? req->file.shade : RAYO_SHADE_HIT;
}

/* The Netpbm format that holds a mode's pixels: PBM, PGM or PPM. */
static rayo_format netpbm_for_shade(rayo_shade_mode mode)
{
    switch (mode) {
    case RAYO_SHADE_HIT:
        break;
    case RAYO_SHADE_COURSE_GRAY:
        return RAYO_FORMAT_PGM;
    case RAYO_SHADE_COURSE_COLOR:
    case RAYO_SHADE_PHONG:
    case RAYO_SHADE_COURSE_TP1:
        return RAYO_FORMAT_PPM;
    }
    return RAYO_FORMAT_PBM;
}

static const char *upper_name(rayo_format format)
{
    static const char *const names[] = {"PBM", "PGM", "PPM", "PNG",
                                        "BMP", "JPEG"};
    return names[format];
}

/* 1 for a regular file or a path that does not exist yet. */
static int is_regular_or_new(const char *path)
{
    struct stat st;
    return stat(path, &st) != 0 || S_ISREG(st.st_mode);
}

static int choose_format(const render_request *req, rayo_format *format)
{
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    rayo_shade_mode mode = effective_shade(req);
    rayo_format netpbm = netpbm_for_shade(mode);
    const char *ext = rayo_format_name(netpbm);
    if (req->format != NULL) {
        if (rayo_format_parse(req->format, format, &err) != RAYO_OK ||
            (*format != netpbm && rayo_format_is_netpbm(*format)))
            return cli_usage_error(_("--format: %s is not accepted; "
                                     "expected %s, png, bmp or jpeg for a %s "
                                     "render"),
                                   cli_quote(req->format), ext,
                                   rayo_shade_mode_name(mode));
    } else if (strcmp(req->output, "-") == 0 ||
               !is_regular_or_new(req->output)) {
        /* Standard output, devices and pipes: the mode's Netpbm format. */
        *format = netpbm;
    } else if (rayo_format_from_path(req->output, format, &err) != RAYO_OK) {
        return cli_usage_error(_("--output: cannot tell the format of '%s' "
                                 "from its extension; expected .%s, .png, "
                                 ".bmp or .jpg, or give --format"),
                               req->output, ext);
    } else if (*format != netpbm && rayo_format_is_netpbm(*format)) {
        return cli_usage_error(_("--output: '%s' is %s, which cannot hold a %s "
                                 "render; expected .%s, .png, .bmp or .jpg"),
                               req->output, upper_name(*format),
                               rayo_shade_mode_name(mode), ext);
    }
    if (req->raw && *format != netpbm)
        return cli_usage_error(_("--raw: applies only to %s output, not %s"),
                               upper_name(netpbm), rayo_format_name(*format));
    return CLI_EXIT_OK;
}

/* The scene file's camera (or the assignment's), with -W -H --fov
 * --origin laid over it. */
static int build_camera(const render_request *req, rayo_camera *camera,
                        rayo_error *err)
{
    rayo_camera_spec spec;
    if (req->scene_path != NULL)
        spec = req->file.camera;
    else
        rayo_camera_spec_init(&spec);
    if (req->scene_path == NULL || req->width_given)
        spec.width = (uint32_t)req->width;
    if (req->scene_path == NULL || req->height_given)
        spec.height = (uint32_t)req->height;
    if (req->scene_path == NULL || req->fov_given)
        spec.fov_degrees = req->fov;
    if (req->scene_path == NULL || req->origin_given)
        spec.origin = req->origin;
    return rayo_camera_spec_build(&spec, camera, err) == RAYO_OK;
}

/* One line when the scene file draws nothing or picks no camera, and one
   for each part of a mesh file it left out. */
static void warn_about_scene(const render_request *req)
{
    const char *name = strcmp(req->scene_path, "-") == 0 ? _("standard input")
                                                         : req->scene_path;
    int empty = rayo_scene_object_count(req->file.scene) == 0;
    int no_camera = !req->file.camera_given && !req->width_given &&
                    !req->height_given && !req->fov_given &&
                    !req->origin_given;
    if (empty && no_camera)
        cli_sayf(_("warning: %s has no objects and no camera; the image is "
                   "the background, %lux%lu"),
                 name, (unsigned long)req->file.camera.width,
                 (unsigned long)req->file.camera.height);
    else if (empty)
        cli_sayf(_("warning: %s has no objects; the image is the background"),
                 name);
    else if (no_camera)
        cli_sayf(_("warning: %s has no camera; using the default one: "
                   "%lux%lu, fov %g, at 0,0,0 looking down +z"),
                 name, (unsigned long)req->file.camera.width,
                 (unsigned long)req->file.camera.height,
                 req->file.camera.fov_degrees);
    if (req->file.mesh_left_out > 0)
        cli_sayf(_n("warning: %s: %llu of its meshes' triangles has its "
                    "corners on one line and was left out (%llu drawn)",
                    "warning: %s: %llu of its meshes' triangles have their "
                    "corners on one line and were left out (%llu drawn)",
                    (unsigned long)req->file.mesh_left_out),
                 name, req->file.mesh_left_out, req->file.mesh_triangles);
    if (req->file.mesh_ignored > 0)
        cli_sayf(_n("warning: %s: %llu OBJ statement that is not 'v' or 'f' "
                    "(normals, texture coordinates, groups, materials) was "
                    "not used",
                    "warning: %s: %llu OBJ statements that are not 'v' or "
                    "'f' (normals, texture coordinates, groups, materials) "
                    "were not used",
                    (unsigned long)req->file.mesh_ignored),
                 name, req->file.mesh_ignored);
}

/* Shading mode, samples and depth: the options', else the scene's. */
static void render_settings(const render_request *req,
                            rayo_render_options *options)
{
    options->shade = effective_shade(req);
    if (req->scene_path != NULL) {
        options->samples = req->file.samples;
        options->depth = req->file.depth;
        options->tp1 = req->file.tp1;
    }
    if (req->samples != 0)
        options->samples = (unsigned)req->samples;
    if (req->depth_given)
        options->depth = (unsigned)req->depth;
}

static int build_scene(render_request *req, rayo_scene **scene,
                       rayo_error *err)
{
    size_t i;
    if (req->scene_path != NULL) {
        *scene = req->file.scene;
        req->file.scene = NULL;
        return 1;
    }
    if (rayo_scene_create(scene, err) != RAYO_OK)
        return 0;
    if (req->sphere_count == 0)
        return rayo_scene_add_sphere(
                   *scene,
                   rayo_vec3_make(RAYO_SEED_CENTER_X, RAYO_SEED_CENTER_Y,
                                  RAYO_SEED_CENTER_Z),
                   RAYO_SEED_RADIUS, err) == RAYO_OK;
    for (i = 0; i < req->sphere_count; i++) {
        const double *s = req->spheres[i];
        if (rayo_scene_add_sphere(*scene, rayo_vec3_make(s[0], s[1], s[2]),
                                  s[3], err) != RAYO_OK)
            return 0;
    }
    return 1;
}

/* Renders into an opened output; leaves committing to the caller. */
static rayo_status render_to(rayo_output *out, const rayo_camera *camera,
                             const rayo_scene *scene,
                             const rayo_render_options *options,
                             const rayo_write_options *write_options,
                             cli_preview *preview, rayo_error *err)
{
    rayo_image_info info = rayo_render_image_info(camera, options);
    rayo_writer *writer;
    rayo_status status =
        rayo_writer_open(&writer, out, &info, write_options, err);
    if (status != RAYO_OK)
        return status;
    if (preview != NULL) /* rows pass through the preview's copy */
        cli_preview_forward(preview, rayo_writer_row_sink, writer);
    status = rayo_render(camera, scene, options,
                         preview ? cli_preview_rows : rayo_writer_row_sink,
                         preview ? (void *)preview : (void *)writer, err);
    if (status != RAYO_OK) {
        rayo_writer_discard(writer);
        return status;
    }
    return rayo_writer_finish(writer, err);
}

int cli_render(int argc, char **argv)
{
    render_request *req = calloc(1, sizeof *req);
    rayo_camera camera;
    rayo_scene *scene = NULL;
    rayo_render_options options;
    rayo_write_options write_options;
    rayo_output *out = NULL;
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    cli_progress progress;
    cli_preview *preview = NULL;
    int exit_status, on_terminal;

    if (req == NULL) {
        cli_say(_("render: out of memory"));
        return CLI_EXIT_NOMEM;
    }
    request_defaults(req);
    rayo_error_clear(&err);
    exit_status = parse_request(argc, argv, req);
    if (exit_status == CLI_EXIT_OK && req->scene_path != NULL &&
        rayo_scene_file_load_threads(&req->file, req->scene_path,
                                     (unsigned)req->threads,
                                     &err) != RAYO_OK)
        exit_status = cli_unreadable(&err);
    if (exit_status == CLI_EXIT_OK)
        exit_status = choose_format(req, &write_options.format);
    if (exit_status != CLI_EXIT_OK) {
        rayo_scene_file_free(&req->file);
        free(req);
        return exit_status < 0 ? CLI_EXIT_OK : exit_status;
    }
    write_options.plain = !req->raw;
    write_options.quality = (unsigned)req->quality;
    if (req->scene_path != NULL)
        warn_about_scene(req);

    if (!build_camera(req, &camera, &err) || !build_scene(req, &scene, &err)) {
        rayo_scene_file_free(&req->file);
        free(req);
        rayo_scene_free(scene);
        return cli_report(&err);
    }
    rayo_render_options_init(&options);
    render_settings(req, &options);
    options.threads = (unsigned)req->threads;
    options.progress = stop_requested;
    options.progress_context = &progress;
    options.cancel = cli_interrupt_cancel; /* within a ray of a signal */
    cli_interrupt_catch();

    on_terminal = strcmp(req->output, "-") == 0 && cli_stdout_is_terminal();
    if (req->preview || on_terminal) {
        rayo_image_info info = rayo_render_image_info(&camera, &options);
        cli_preview_create(&preview, &info, &err);
    }
    if (err.status == RAYO_OK && !on_terminal)
        rayo_output_open(&out, req->output, &err);
    /* No bar amid an image going to a terminal as text (-o /dev/tty). */
    cli_progress_init(&progress, req->quiet || (err.status == RAYO_OK &&
                                                out != NULL &&
                                                rayo_output_is_terminal(out)));
    if (err.status == RAYO_OK && on_terminal) {
        rayo_render(&camera, scene, &options, cli_preview_rows, preview, &err);
    } else if (err.status == RAYO_OK) {
        if (render_to(out, &camera, scene, &options, &write_options,
                      preview, &err) == RAYO_OK &&
            cli_interrupted() == 0)
            rayo_output_commit(out, &err);
        else
            rayo_output_abort(out);
    }
    cli_progress_finish(&progress);
    if (preview != NULL && err.status == RAYO_OK && cli_interrupted() == 0) {
        /* The image on stdout keeps stdout to itself. */
        exit_status = cli_preview_print(
            preview, strcmp(req->output, "-") == 0 && !on_terminal ? stderr
                                                                   : stdout);
        if (exit_status == CLI_EXIT_OK && on_terminal)
            cli_say(_("this is a picture of the image, because standard "
                      "output is a terminal; to save it, use 'rayo > "
                      "esfera.pbm' or 'rayo -o esfera.png'"));
        if (exit_status != CLI_EXIT_OK) {
            cli_preview_free(preview);
            rayo_scene_free(scene);
            free(req);
            return exit_status;
        }
    }
    cli_preview_free(preview);
    rayo_scene_free(scene);
    free(req);
    if (cli_interrupted() != 0)
        return cli_interrupt_exit();
    return cli_report(&err);
}

/* cli_parse.h: the options parsed as `rayo render` parses them, nothing
 * run. */
int cli_parse_render(int argc, char **argv)
{
    render_request *req = calloc(1, sizeof *req);
    rayo_format format;
    int status;
    if (req == NULL)
        return CLI_EXIT_FAILURE;
    request_defaults(req);
    status = parse_request(argc, argv, req);
    if (status == CLI_EXIT_OK)
        status = choose_format(req, &format);
    free(req);
    return status < 0 ? CLI_EXIT_OK : status;
}
