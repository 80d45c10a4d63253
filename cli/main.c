/*
 * main.c - the `rayo` command: picks the subcommand and hands over.
 *
 * `rayo` alone, or `rayo` followed by options, is `rayo render`: with no
 * arguments it does exactly what the assignment asks, the seed's sphere as
 * plain PBM on standard output.  Every subcommand lives in a file of its
 * own (cmd_*.c) and parses its own options; the language of every
 * message is chosen first (lang.c), and a mistyped command is answered
 * with the known ones and the nearest.
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
    {"render", cli_render,
     N_("trace rays through a scene into an image (default)")},
    {"convert", cli_convert,
     N_("convert an image between PBM, PGM, PPM and PNG")},
    {"compare", cli_compare,
     N_("compare an image with a reference and say what is wrong")},
    {"view", cli_view, N_("show an image in the terminal")},
    {"grade", cli_grade, N_("check a student's submission as the course does")},
};
#define SUBCOMMAND_COUNT (sizeof subcommands / sizeof subcommands[0])

static void print_overview(void)
{
    size_t i;
    fputs(_("usage: rayo [render] [OPTIONS]\n"
            "       rayo COMMAND [OPTIONS] [ARGS]\n\n"
            "rayo is a small, exact ray tracer.  With no arguments it renders "
            "the sphere of\nthe course's first assignment as plain PBM on "
            "standard output.\n\ncommands:\n"),
          stdout);
    for (i = 0; i < SUBCOMMAND_COUNT; i++)
        printf("  %-9s %s\n", subcommands[i].name, _(subcommands[i].summary));
    fputs(_("\n'rayo COMMAND --help' describes a command; 'man rayo' has it "
            "all.\n--lang es|en picks the language (default: from LANGUAGE, "
            "LC_ALL, LC_MESSAGES\nor LANG).\n\n"),
          stdout);
}

/* An unknown command: the known ones, and the nearest when one is. */
static int unknown_command(const char *word)
{
    const char *names[SUBCOMMAND_COUNT];
    const char *nearest;
    size_t i;
    for (i = 0; i < SUBCOMMAND_COUNT; i++)
        names[i] = subcommands[i].name;
    nearest = cli_nearest(word, names, SUBCOMMAND_COUNT);
    if (nearest != NULL)
        return cli_usage_error(_("unknown command %s; did you mean %s? The "
                                 "commands are render, convert, compare, "
                                 "view and grade"),
                               cli_quote(word), nearest);
    return cli_usage_error(_("unknown command %s; the commands are render, "
                             "convert, compare, view and grade; see 'rayo "
                             "--help'"),
                           cli_quote(word));
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
    if (cli_lang_init(&argc, argv) != CLI_EXIT_OK)
        return CLI_EXIT_USAGE;
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
            return unknown_command(argv[1]);
    }
    argv[0] = "render";
    return cli_render(argc, argv);
}
