/*
 * valgrind_log.c - valgrind's log read as bytes (valgrind_log.h): lines
 * of any length, NUL bytes counted, never a C string that a NUL would
 * cut short, and the signs that the program wrote into the log.
 *
 * The log comes through a socket that the program cannot reach (the
 * descriptor is in the range valgrind keeps for itself, run/process.c), so
 * those signs should never appear; they are looked for all the same,
 * because what the program could write there would otherwise become the
 * grader's verdict.  What the lines mean is valgrind.c's business.
 */
#include <string.h>

#include "valgrind_log.h"

/* A frame "==123== ", "--123-- " or "**123** " at the line's start:
   its length, and the PID; 0 when there is none. */
static size_t frame(const char *p, size_t n, long *pid)
{
    size_t i = 2;
    long value = 0;
    char mark;
    if (n < 5 || (p[0] != '=' && p[0] != '-' && p[0] != '*') ||
        p[1] != p[0])
        return 0;
    mark = p[0];
    while (i < n && p[i] >= '0' && p[i] <= '9' && i < 14) {
        value = value * 10 + (p[i] - '0');
        i++;
    }
    if (i == 2 || i + 2 > n || p[i] != mark || p[i + 1] != mark)
        return 0;
    i += 2;
    if (i < n && p[i] != ' ')
        return 0;
    *pid = value;
    return i;
}

int vg_next_line(const char *data, size_t size, size_t *pos, vg_line *line)
{
    const char *start, *end;
    size_t skip;
    if (*pos >= size)
        return 0;
    start = data + *pos;
    end = memchr(start, '\n', size - *pos);
    line->text = start;
    line->length = end != NULL ? (size_t)(end - start) : size - *pos;
    *pos += line->length + (end != NULL ? 1 : 0);
    line->pid = -1;
    skip = frame(start, line->length, &line->pid);
    if (skip == 0)
        line->pid = -1;
    while (skip < line->length && start[skip] == ' ')
        skip++;
    line->body = start + skip;
    line->body_length = line->length - skip;
    return 1;
}

int vg_begins(const vg_line *line, const char *word)
{
    size_t n = strlen(word);
    return line->body_length >= n && memcmp(line->body, word, n) == 0;
}

const char *vg_find(const vg_line *line, const char *word)
{
    size_t n = strlen(word), i;
    if (n == 0 || line->body_length < n)
        return NULL;
    for (i = 0; i + n <= line->body_length; i++)
        if (line->body[i] == word[0] && memcmp(line->body + i, word, n) == 0)
            return line->body + i;
    return NULL;
}

void vg_copy(const char *text, size_t length, char *out, size_t room)
{
    size_t i;
    if (room == 0)
        return;
    if (length > room - 1)
        length = room - 1;
    for (i = 0; i < length; i++)
        out[i] = text[i] != '\0' ? text[i] : ' ';
    out[length] = '\0';
}

/* The system calls through which a descriptor can be written, or copied
   to be written later. */
static int writes(const char *name, size_t n)
{
    static const char *const prefixes[] = {"write", "pwrite", "send",
                                           "splice", "vmsplice", "tee",
                                           "dup", "sendfile"};
    size_t k;
    for (k = 0; k < sizeof prefixes / sizeof prefixes[0]; k++) {
        size_t m = strlen(prefixes[k]);
        if (n >= m && memcmp(name, prefixes[k], m) == 0)
            return 1;
    }
    return 0;
}

/* "Warning: invalid file descriptor N in syscall NAME()": N when NAME
   writes, else -1. */
static long refused_write(const vg_line *line)
{
    static const char head[] = "Warning: invalid file descriptor ";
    static const char middle[] = " in syscall ";
    const char *p, *end = line->body + line->body_length;
    long fd = 0;
    if (!vg_begins(line, head))
        return -1;
    p = line->body + sizeof head - 1;
    while (p < end && *p >= '0' && *p <= '9' && fd < 100000000)
        fd = fd * 10 + (*p++ - '0');
    if ((size_t)(end - p) < sizeof middle - 1 ||
        memcmp(p, middle, sizeof middle - 1) != 0)
        return -1;
    p += sizeof middle - 1;
    return writes(p, (size_t)(end - p)) ? fd : -1;
}

/* valgrind's report of its own crash begins at a line like these. */
static int panic_line(const vg_line *line)
{
    return line->pid < 0 &&
           ((line->length >= 10 && memcmp(line->text, "valgrind: ", 10) == 0) ||
            (line->length >= 15 &&
             memcmp(line->text, "host stacktrace", 15) == 0));
}

#define TRACKED 256

/* valgrind's own complaints, unframed, about debug information it cannot
   read: clang 14's DWARF 5 ("### unhandled dwarf2 abbrev form code 0x25",
   "get_Form_szB: unhandled 27 (DW_FORM_addrx)") under valgrind 3.19.  They
   carry no verdict, so a program that wrote one would gain nothing. */
static int debuginfo_notice(const vg_line *line)
{
    static const char *const starts[] = {"### unhandled dwarf2 ",
                                         "get_Form_szB: unhandled "};
    size_t i;
    for (i = 0; i < sizeof starts / sizeof *starts; i++) {
        size_t n = strlen(starts[i]);
        if (line->length >= n && memcmp(line->text, starts[i], n) == 0)
            return 1;
    }
    return 0;
}

void vg_check(const char *data, size_t size, int log_fd, vg_signs *signs)
{
    long summaries[TRACKED];
    size_t count = 0, pos = 0, k;
    vg_line line;
    memset(signs, 0, sizeof *signs);
    signs->touched_fd = -1;
    signs->nul = size > 0 && memchr(data, '\0', size) != NULL;
    while (vg_next_line(data, size, &pos, &line)) {
        long fd;
        if (!signs->panic && panic_line(&line)) {
            signs->panic = 1;
            signs->panic_at = (size_t)(line.text - data);
        }
        if (line.pid < 0) {
            if (!signs->panic && line.length > 0 && !debuginfo_notice(&line))
                signs->unframed = 1;
            continue;
        }
        fd = refused_write(&line);
        if (fd >= log_fd && log_fd >= 0 && signs->touched_fd < 0)
            signs->touched_fd = (int)fd;
        if (!vg_begins(&line, "ERROR SUMMARY: "))
            continue;
        for (k = 0; k < count; k++)
            if (summaries[k] == line.pid)
                signs->duplicate = 1;
        if (count < TRACKED)
            summaries[count++] = line.pid;
    }
}

int vg_framed_text(const char *data, size_t size)
{
    size_t pos = 0;
    vg_line line;
    if (data == NULL)
        return 0;
    while (vg_next_line(data, size, &pos, &line))
        if (line.pid >= 0 && line.text[0] == '=')
            return 1;
    return 0;
}
