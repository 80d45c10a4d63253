/*
 * cli_parse_grade.c - `rayo grade`'s option parsing, for the fuzzer
 * (cli_parse.h).  It includes cli/cmd_grade.c so that the parser under
 * test is the command's own.  Nothing is compiled or run.
 */
#include "../cli/cmd_grade.c"

#include "cli_parse.h"

int fuzz_parse_grade(int argc, char **argv)
{
    grade_request req;
    int status;
    memset(&req, 0, sizeof req);
    rayo_grade_options_init(&req.options);
    status = parse_request(argc, argv, &req);
    return status < 0 ? CLI_EXIT_OK : status;
}
