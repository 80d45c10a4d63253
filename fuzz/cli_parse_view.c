/*
 * cli_parse_view.c - `rayo view`'s option parsing, for the fuzzer
 * (cli_parse.h).  It includes cli/cmd_view.c so that the parser under
 * test is the command's own.  No image is read.
 */
#include "../cli/cmd_view.c"

#include "cli_parse.h"

int fuzz_parse_view(int argc, char **argv)
{
    rayo_preview_options options;
    const char *file = NULL;
    int status;
    rayo_preview_options_init(&options);
    options.columns = 80;
    status = parse_options(argc, argv, &options, &file);
    return status < 0 ? CLI_EXIT_OK : status;
}
