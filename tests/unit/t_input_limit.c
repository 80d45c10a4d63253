/*
 * t_input_limit.c - the readers' limit on bytes read (limits.h:
 * RAYO_MAX_INPUT_BYTES), on a pipe, where the size is not known in
 * advance: an input of exactly the limit is read whole; one byte more is
 * RAYO_ERR_LIMIT naming the byte, not a hang on endless input.  The
 * limit of the source is lowered for the test (the 8 GiB of the real one
 * are tested on sparse regular files by tests/cli/limits.t).  Not a
 * test of any image format.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "../../src/formats/read_source.h"
#include "rayo/limits.h"
#include "tap.h"

#define PIPED 60000 /* fits in a pipe's buffer, so no writer thread */

/* Opens a source on a pipe that holds PIPED bytes and is closed. */
static int open_piped(rayo_source *src, rayo_error *err)
{
    static unsigned char bytes[PIPED];
    static char path[64]; /* the source keeps a pointer to its name */
    int fds[2];
    if (pipe(fds) != 0)
        return 0;
    memset(bytes, 'x', sizeof bytes);
    if (write(fds[1], bytes, sizeof bytes) != (ssize_t)sizeof bytes)
        return 0;
    close(fds[1]);
    snprintf(path, sizeof path, "/proc/self/fd/%d", fds[0]);
    if (rayo_source_open_file(src, path, err) != RAYO_OK)
        return 0;
    close(fds[0]);
    return 1;
}

int main(void)
{
    rayo_source src;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    uint64_t count = 0;
    rayo_status status;

    ok(open_piped(&src, &err), "a pipe opens as a source");
    is_int(src.size_known, 0, "a pipe's size is not known in advance");
    is_int(src.limit == RAYO_MAX_INPUT_BYTES, 1,
           "the limit is RAYO_MAX_INPUT_BYTES");
    src.limit = PIPED;
    status = rayo_source_count_rest(&src, &count, &err);
    is_int(status, RAYO_OK, "exactly the limit: read whole");
    is_int((long long)count, PIPED, "exactly the limit: every byte counted");
    rayo_source_close(&src);

    ok(open_piped(&src, &err), "the pipe again");
    src.limit = PIPED - 1;
    status = rayo_source_count_rest(&src, &count, &err);
    is_int(status, RAYO_ERR_LIMIT, "one byte over the limit: RAYO_ERR_LIMIT");
    ok(strncmp(err.message, "/proc/self/fd/", 14) == 0 &&
           strstr(err.message, ": byte 59999: found more data; expected an "
                               "input of at most 59999 bytes") != NULL &&
           strchr(err.message, '\n') == NULL,
       "one line naming the input, the byte and the limit");
    rayo_source_close(&src);

    ok(open_piped(&src, &err), "the pipe again");
    src.limit = 1000;
    {
        unsigned char buffer[2000];
        size_t got;
        rayo_source_read(&src, buffer, sizeof buffer, &got);
        is_int((long long)got, 1000, "a read stops at the limit");
        is_int(src.over_limit, 1, "and marks the source as over it");
        status = rayo_source_end_error(&src, "more", &err);
        is_int(status, RAYO_ERR_LIMIT, "the end is reported as the limit");
    }
    rayo_source_close(&src);
    return tap_done();
}
