/*
 * fuzz_cli.c - fuzz target: the command line of every `rayo` subcommand.
 *
 * The first byte picks the subcommand (render, convert, compare, view,
 * grade); the rest, split at NUL bytes, are its arguments.  The
 * subcommand's own parser runs on them (cli/cli_parse.h, the command's
 * seam, found through the fuzz rules' -Icli: nothing is read,
 * rendered or written) and must return an exit status the command
 * documents: 0 to go on (or after --help), 2 for a usage error.  Run the
 * fuzzer with -close_fd_mask=3: the parsers print their messages.
 */
#include <stdlib.h>
#include <string.h>

#include "cli_parse.h"
#include "fuzz.h"

#define MAX_ARGUMENTS 64
#define MAX_INPUT 8192

typedef struct subcommand {
    const char *name;
    int (*parse)(int argc, char **argv);
} subcommand;

static const subcommand subcommands[] = {
    {"render", cli_parse_render},   {"convert", cli_parse_convert},
    {"compare", cli_parse_compare}, {"view", cli_parse_view},
    {"grade", cli_parse_grade},
};
#define SUBCOMMAND_COUNT (sizeof subcommands / sizeof subcommands[0])

/* Splits text (size bytes, NUL-terminated at text[size]) into argv after
 * argv[0]; returns argc. */
static int split_arguments(char *text, size_t size, char **argv)
{
    int argc = 1;
    size_t at = 0;
    while (at < size && argc <= MAX_ARGUMENTS) {
        argv[argc++] = text + at;
        at += strlen(text + at) + 1;
    }
    argv[argc] = NULL;
    return argc;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *argv[MAX_ARGUMENTS + 2];
    char *text;
    const subcommand *command;
    int argc, status;
    if (size == 0 || size > MAX_INPUT)
        return 0;
    command = &subcommands[data[0] % SUBCOMMAND_COUNT];
    text = malloc(size);
    if (text == NULL)
        return 0;
    memcpy(text, data + 1, size - 1);
    text[size - 1] = '\0';
    argv[0] = (char *)command->name;
    argc = split_arguments(text, size - 1, argv);
    status = command->parse(argc, argv);
    free(text);
    if (status != 0 && status != 2)
        abort();
    return 0;
}
