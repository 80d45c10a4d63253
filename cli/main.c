/*
 * main.c - the `rayo` command: picks the subcommand and hands over.
 *
 * `rayo` alone, or `rayo` followed by options, is `rayo render`: with no
 * arguments it does exactly what the assignment asks, the seed's sphere as
 * plain PBM on standard output.  Every subcommand lives in a file of its
 * own (cmd_*.c) and parses its own options.
 */
#include <signal.h>
#include <string.h>
#if defined(__GLIBC__)
#include <malloc.h> /* mallopt, M_ARENA_MAX */
#endif

#include "cli.h"

typedef struct subcommand {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} subcommand;

static const subcommand subcommands[] = {
    {"render", cli_render, "trace rays through a scene into an image (default)"},
    {"convert", cli_convert, "convert an image between PBM, PGM, PPM and PNG"},
    {"compare", cli_compare, "compare an image with a reference and say what is wrong"},
    {"view", cli_view, "show an image in the terminal"},
    {"grade", cli_grade, "check a student's submission as the course does"},
};
#define SUBCOMMAND_COUNT (sizeof subcommands / sizeof subcommands[0])

static void print_overview(void)
{
    size_t i;
    printf("usage: rayo [render] [OPTIONS]\n"
           "       rayo COMMAND [OPTIONS] [ARGS]\n\n"
           "rayo is a small, exact ray tracer.  With no arguments it renders "
           "the sphere of\nthe course's first assignment as plain PBM on "
           "standard output.\n\ncommands:\n");
    for (i = 0; i < SUBCOMMAND_COUNT; i++)
        printf("  %-9s %s\n", subcommands[i].name, subcommands[i].summary);
    printf("\n'rayo COMMAND --help' describes a command; 'man rayo' has it "
           "all.\n\n");
}

int main(int argc, char **argv)
{
    size_t i;
    /* Write errors come back as EPIPE or EFBIG instead of killing us, so
       a partial output file is always removed; cli_report decides what
       to say. */
    signal(SIGPIPE, SIG_IGN);
    signal(SIGXFSZ, SIG_IGN);
#if defined(M_ARENA_MAX)
    /* One malloc arena for every thread: glibc gives each thread that
       allocates an arena of its own, in heaps that reserve 64 MiB of
       address space each, so that -j 8 reserved 0.5 GiB more than it
       used and an `ulimit -v` sized by the memory failed (the threads
       allocate little while rendering; docs/limits.md). */
    mallopt(M_ARENA_MAX, 1);
#endif
    if (argc > 1) {
        for (i = 0; i < SUBCOMMAND_COUNT; i++)
            if (strcmp(argv[1], subcommands[i].name) == 0) {
                int status = subcommands[i].run(argc - 1, argv + 1);
                /* what compare and grade kept for their next image */
                rayo_compare_release_cache();
                return status;
            }
        if (strcmp(argv[1], "help") == 0) {
            print_overview();
            return cli_render(2, (char *[]){"render", "--help", NULL});
        }
        if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0)
            print_overview();
        if (argv[1][0] != '-')
            return cli_usage_error("unknown command '%s'; see 'rayo --help'",
                                   argv[1]);
    }
    argv[0] = "render";
    return cli_render(argc, argv);
}
