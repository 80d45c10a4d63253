/*
 * cli_parse.h - the option parsing of each `rayo` subcommand, callable
 * without running the command: the command's seam for the command-line
 * fuzz target (fuzz/fuzz_cli.c), which links the command's objects.
 *
 * Each function parses argv as the subcommand would (argv[0] is the
 * subcommand's name), checks what the command checks before it touches
 * a file, and returns the exit status the command would return at that
 * point: 0 when the command would go on, 2 for a usage error, and 0
 * after --help or --version.  Nothing is read, rendered or written
 * (messages go to stdout and stderr, as the command prints them).  Each
 * is defined at the end of its cmd_*.c, beside the parser it runs.
 */
#ifndef RAYO_CLI_PARSE_H
#define RAYO_CLI_PARSE_H

int cli_parse_render(int argc, char **argv);
int cli_parse_convert(int argc, char **argv);
int cli_parse_compare(int argc, char **argv);
int cli_parse_view(int argc, char **argv);
int cli_parse_grade(int argc, char **argv);

#endif
