/*
 * cli_parse_render.c - `rayo render`'s option parsing, for the fuzzer
 * (cli_parse.h).  It includes cli/cmd_render.c so that the parser under
 * test is the command's own, static functions and all; it sets the
 * defaults cli_render sets, parses, and chooses the output format (which
 * only stat()s the output's name).  No scene is loaded and nothing is
 * rendered.
 */
#include "../cli/cmd_render.c"

#include "cli_parse.h"

int fuzz_parse_render(int argc, char **argv)
{
    render_request *req = calloc(1, sizeof *req);
    rayo_format format;
    int status;
    if (req == NULL)
        return CLI_EXIT_FAILURE;
    req->width = RAYO_SEED_WIDTH;
    req->height = RAYO_SEED_HEIGHT;
    req->fov = RAYO_SEED_FOV;
    req->origin = rayo_vec3_make(0, 0, 0);
    req->output = "-";
    status = parse_request(argc, argv, req);
    if (status == CLI_EXIT_OK)
        status = choose_format(req, &format);
    free(req);
    return status < 0 ? CLI_EXIT_OK : status;
}
