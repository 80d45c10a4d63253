/*
 * cli_parse_compare.c - `rayo compare`'s option parsing, for the fuzzer
 * (cli_parse.h).  It includes cli/cmd_compare.c so that the parser under
 * test is the command's own.  No image is read.
 */
#include "../cli/cmd_compare.c"

#include "cli_parse.h"

int fuzz_parse_compare(int argc, char **argv)
{
    compare_request req;
    int status;
    memset(&req, 0, sizeof req);
    rayo_compare_options_init(&req.options);
    status = parse_request(argc, argv, &req);
    return status < 0 ? CLI_EXIT_OK : status;
}
