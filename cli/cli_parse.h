/*
 * cli_parse.h - the option parsing of each `rayo` subcommand, callable
 * without running the command: for the command-line fuzz target
 * (fuzz_cli.c).
 *
 * Each function parses argv as the subcommand would (argv[0] is the
 * subcommand's name), checks what the command checks before it touches
 * a file, and returns the exit status the command would return at that
 * point: 0 when the command would go on, 2 for a usage error, and 0
 * after --help or --version.  Nothing is read, rendered or written
 * (messages go to stdout and stderr, as the command prints them).  The
 * implementations (fuzz/cli_parse_*.c) include the subcommand's source
 * file, so the fuzzer tests the very code `rayo` runs, with no change to
 * cli/.  Not for use outside fuzz/.
 */
#ifndef RAYO_FUZZ_CLI_PARSE_H
#define RAYO_FUZZ_CLI_PARSE_H

int fuzz_parse_render(int argc, char **argv);
int fuzz_parse_convert(int argc, char **argv);
int fuzz_parse_compare(int argc, char **argv);
int fuzz_parse_view(int argc, char **argv);
int fuzz_parse_grade(int argc, char **argv);

#endif
