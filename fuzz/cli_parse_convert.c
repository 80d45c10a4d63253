/*
 * cli_parse_convert.c - `rayo convert`'s option parsing, for the fuzzer
 * (cli_parse.h).  It includes cli/cmd_convert.c so that the parser under
 * test is the command's own; it parses and, when the command would
 * decide the format before reading (OUT is not '-' or --format is
 * given), chooses it.  The input is not read and nothing is written.
 */
#include "../cli/cmd_convert.c"

#include "cli_parse.h"

int fuzz_parse_convert(int argc, char **argv)
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
