/*
 * parse.c - turning option values into numbers, strictly.
 *
 * strtoul/strtod accept leading spaces, partial numbers ("12abc"),
 * "nan" and "inf"; the command does not.  A value must be a whole number
 * (or a finite decimal) and nothing else, and every refusal names the
 * option, the value and what is accepted.
 */
#define _POSIX_C_SOURCE 200809L

#include <ctype.h>
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"

int cli_usage_error(const char *format, ...)
{
    va_list args;
    va_start(args, format);
    cli_vsayf(format, args);
    va_end(args);
    return CLI_EXIT_USAGE;
}

int cli_report(const rayo_error *err)
{
    switch (err->status) {
    case RAYO_OK:
        return CLI_EXIT_OK;
    case RAYO_ERR_PIPE:
        /* Die of SIGPIPE, quietly, like every filter whose reader left. */
        fflush(stdout);
        signal(SIGPIPE, SIG_DFL);
        raise(SIGPIPE);
        return CLI_EXIT_FAILURE;
    case RAYO_ERR_INVALID:
    case RAYO_ERR_FORMAT:
    case RAYO_ERR_LIMIT:
        cli_say(err->message);
        return CLI_EXIT_USAGE;
    case RAYO_ERR_NOMEM:
        /* Its own status (not an output's 1), and what to change. */
        if (strcmp(err->message,
                   rayo_gettext(err->lang, "out of memory")) == 0)
            cli_say(_("out of memory: the machine's memory, or the address "
                      "space that ulimit -v allows, is too small for this"));
        else
            cli_sayf(_("%s: the machine's memory, or the address space "
                       "that ulimit -v allows, is too small for this"),
                     err->message);
        return CLI_EXIT_NOMEM;
    case RAYO_ERR_IO:
    case RAYO_ERR_CANCELLED:
        break;
    }
    cli_say(err->message);
    return CLI_EXIT_FAILURE;
}

int cli_bad_option(int option, char **argv, int index)
{
    const char *word = argv[index - 1];
    if (option == ':')
        return cli_usage_error(_("%s: %s needs a value; see 'rayo --help'"),
                               argv[0], cli_quote(word));
    return cli_usage_error(_("%s: unknown option %s; see 'rayo --help'"),
                           argv[0], cli_quote(word));
}

int cli_wrong_operands(const char *command, int found, const char *what)
{
    return cli_usage_error(_n("%s: expected %s, got %d argument; see 'rayo "
                              "%s --help'",
                              "%s: expected %s, got %d arguments; see 'rayo "
                              "%s --help'",
                              (unsigned long)found),
                           command, _(what), found, command);
}

static int looks_numeric_start(const char *text)
{
    return *text != '\0' && !isspace((unsigned char)*text);
}

int cli_parse_uint(const char *option, const char *text, unsigned long min,
                   unsigned long max, unsigned long *value)
{
    char *end;
    unsigned long v;
    const char *p = text;
    if (*p == '+')
        p++;
    if (!isdigit((unsigned char)*p)) {
        cli_usage_error(_("%s: %s is not a whole number; expected %lu to "
                          "%lu"),
                        option, cli_quote(text), min, max);
        return 0;
    }
    errno = 0;
    v = strtoul(p, &end, 10);
    if (*end != '\0') {
        cli_usage_error(_("%s: %s is not a whole number; expected %lu to "
                          "%lu"),
                        option, cli_quote(text), min, max);
        return 0;
    }
    if (errno == ERANGE || v < min || v > max) {
        cli_usage_error(_("%s: %s is out of range; expected %lu to %lu"),
                        option, cli_quote(text), min, max);
        return 0;
    }
    *value = v;
    return 1;
}

/* Parses one finite number from [text, text+length); 1 on success. */
static int parse_finite(const char *text, size_t length, double *value)
{
    char buffer[64];
    char *end;
    if (length == 0 || length >= sizeof buffer)
        return 0;
    memcpy(buffer, text, length);
    buffer[length] = '\0';
    if (!looks_numeric_start(buffer))
        return 0;
    errno = 0;
    *value = strtod(buffer, &end);
    return *end == '\0' && isfinite(*value) && errno != ERANGE;
}

int cli_parse_double(const char *option, const char *text, double *value)
{
    if (parse_finite(text, strlen(text), value))
        return 1;
    cli_usage_error(_("%s: %s is not a finite number"), option,
                    cli_quote(text));
    return 0;
}

int cli_parse_numbers(const char *option, const char *text, size_t count,
                      const char *shape, double *values)
{
    const char *p = text;
    size_t n = 0;
    for (;;) {
        const char *comma = strchr(p, ',');
        size_t length = comma ? (size_t)(comma - p) : strlen(p);
        double v;
        if (!parse_finite(p, length, &v)) {
            char item[64];
            snprintf(item, sizeof item, "%.*s",
                     (int)(length < 63 ? length : 63), p);
            cli_usage_error(_("%s: %s in %s is not a finite number; "
                              "expected %s"),
                            option, cli_quote(item), cli_quote(text), shape);
            return 0;
        }
        if (n < count)
            values[n] = v;
        n++;
        if (comma == NULL)
            break;
        p = comma + 1;
    }
    if (n != count) {
        cli_usage_error(_n("%s: %s has %lu number; expected %lu: %s",
                           "%s: %s has %lu numbers; expected %lu: %s",
                           (unsigned long)n),
                        option, cli_quote(text), (unsigned long)n,
                        (unsigned long)count, shape);
        return 0;
    }
    return 1;
}

int cli_stdout_is_terminal(void)
{
    return isatty(STDOUT_FILENO);
}
