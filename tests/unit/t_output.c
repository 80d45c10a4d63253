/*
 * t_output.c - rayo_output gets every byte to its destination in order,
 * whatever mix of small writes, large writes and in-place formatting
 * (rayo_output_reserve/advance) it is given, into a regular file (its
 * large buffer) and into a pipe (its pipe-sized one); and it reports what
 * goes wrong: no room on the device, a closed pipe, a reservation larger
 * than the buffer.  It also tells a terminal from the rest
 * (rayo_output_is_terminal), on a pseudo-terminal of its own.
 *
 * The expected stream is generated here from a seeded sequence and the
 * destination read back with plain read(2).
 */
#define _XOPEN_SOURCE 600 /* posix_openpt, grantpt, unlockpt, ptsname */

#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../src/io/output_reserve.h"
#include "rayo.h"
#include "tap.h"

/* Byte i of the stream. */
static unsigned char stream_byte(size_t i)
{
    return (unsigned char)((i * 2654435761u) >> 13);
}

/* Sizes of the pieces, around every buffer and threshold the output has
 * (64 KiB, 1 MiB) and a plain PBM row of the seed (651 bytes). */
static const size_t piece_sizes[] = {
    0,      1,           651,         7,           65535,   65536,
    65537,  3,           200000,      1048575,     1048576, 1048577,
    651,    64 * 1024,   2,           1024 * 1024 - 651,     5};
#define PIECES (sizeof piece_sizes / sizeof piece_sizes[0])

static size_t stream_length(void)
{
    size_t i, n = 0;
    for (i = 0; i < PIECES; i++)
        n += piece_sizes[i];
    return n;
}

/*
 * Writes the stream into out: odd pieces through rayo_output_write, even
 * ones formatted in place when the buffer has room for them.  Returns
 * the status of the first failure; *in_place counts pieces placed.
 */
static rayo_status write_stream(rayo_output *out, int *in_place,
                                rayo_error *err)
{
    static unsigned char piece[1024 * 1024 + 1];
    size_t i, at = 0, j;
    *in_place = 0;
    for (i = 0; i < PIECES; i++) {
        size_t n = piece_sizes[i];
        rayo_status status;
        unsigned char *room = NULL;
        size_t available = 0;
        if (i % 2 == 0) {
            status = rayo_output_reserve(out, n, &room, &available, err);
            if (status != RAYO_OK)
                return status;
            if (room != NULL && available < n)
                return RAYO_ERR_INVALID; /* less room than asked for */
        }
        if (room != NULL) {
            for (j = 0; j < n; j++)
                room[j] = stream_byte(at + j);
            rayo_output_advance(out, n);
            (*in_place)++;
        } else {
            for (j = 0; j < n; j++)
                piece[j] = stream_byte(at + j);
            status = rayo_output_write(out, piece, n, err);
            if (status != RAYO_OK)
                return status;
        }
        at += n;
    }
    return RAYO_OK;
}

/* The stream into out, then commit (or abort on a failure, which is
 * returned); out is gone either way. */
static rayo_status write_stream_and_commit(rayo_output *out, int *in_place,
                                           rayo_error *err)
{
    rayo_status status = write_stream(out, in_place, err);
    if (status != RAYO_OK) {
        rayo_output_abort(out);
        return status;
    }
    return rayo_output_commit(out, err);
}

/* The number of bytes of fd that differ from the stream, or -1 when the
 * length differs. */
static long stream_mismatches(int fd, size_t length)
{
    unsigned char chunk[65536];
    size_t at = 0;
    long bad = 0;
    for (;;) {
        ssize_t n = read(fd, chunk, sizeof chunk), j;
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        for (j = 0; j < n; j++)
            if (at + (size_t)j >= length ||
                chunk[j] != stream_byte(at + (size_t)j))
                bad++;
        at += (size_t)n;
    }
    return at == length ? bad : -1;
}

typedef struct pipe_reader {
    int fd;
    size_t length;
    long mismatches;
} pipe_reader;

static void *read_pipe(void *argument)
{
    pipe_reader *reader = argument;
    reader->mismatches = stream_mismatches(reader->fd, reader->length);
    return NULL;
}

static void test_file(void)
{
    char path[] = "/tmp/rayo-t-output.XXXXXX";
    int fd = mkstemp(path), in_place = 0;
    rayo_output *out;
    rayo_error err;
    rayo_status status;
    if (fd < 0) {
        ok(0, "a temporary file");
        return;
    }
    close(fd);
    status = rayo_output_open(&out, path, &err);
    if (status == RAYO_OK)
        status = write_stream_and_commit(out, &in_place, &err);
    is_int(status, RAYO_OK, "file: every piece written and committed");
    ok(in_place >= 6, "file: pieces formatted in place (%d)", in_place);
    fd = open(path, O_RDONLY);
    is_int(stream_mismatches(fd, stream_length()), 0,
           "file: %lu bytes, all in order", (unsigned long)stream_length());
    close(fd);
    unlink(path);
}

static void test_pipe(void)
{
    int fds[2], in_place = 0;
    pipe_reader reader;
    pthread_t thread;
    rayo_output *out;
    rayo_error err;
    rayo_status status;
    unsigned char *room;
    size_t available;
    if (pipe(fds) != 0) {
        ok(0, "a pipe");
        return;
    }
    reader.fd = fds[0];
    reader.length = stream_length();
    if (pthread_create(&thread, NULL, read_pipe, &reader) != 0) {
        ok(0, "a reading thread");
        return;
    }
    status = rayo_output_open_fd(&out, fds[1], "pipe", &err);
    if (status == RAYO_OK) {
        /* A pipe's buffer holds 64 KiB: no more can be reserved. */
        status = rayo_output_reserve(out, 64 * 1024 + 1, &room, &available,
                                     &err);
        ok(status == RAYO_OK && room == NULL && available == 0,
           "pipe: a reservation larger than the buffer gives no room");
        status = rayo_output_reserve(out, 100, &room, &available, &err);
        ok(status == RAYO_OK && room != NULL && available == 64 * 1024,
           "pipe: an empty buffer offers all its 64 KiB");
        status = write_stream_and_commit(out, &in_place, &err);
    }
    close(fds[1]);
    pthread_join(thread, NULL);
    close(fds[0]);
    is_int(status, RAYO_OK, "pipe: every piece written and committed");
    ok(in_place >= 4, "pipe: pieces formatted in place (%d)", in_place);
    is_int(reader.mismatches, 0, "pipe: %lu bytes, all in order",
           (unsigned long)reader.length);
}

static void test_full_device(void)
{
    int fd = open("/dev/full", O_WRONLY), in_place;
    rayo_output *out;
    rayo_error err;
    rayo_status status;
    if (fd < 0) {
        ok(1, "# SKIP no /dev/full");
        return;
    }
    status = rayo_output_open_fd(&out, fd, "/dev/full", &err);
    if (status == RAYO_OK)
        status = write_stream_and_commit(out, &in_place, &err);
    close(fd);
    is_int(status, RAYO_ERR_IO, "/dev/full: an I/O error");
    ok(strstr(err.message, "/dev/full") != NULL &&
           strstr(err.message, strerror(ENOSPC)) != NULL,
       "/dev/full: the message names the file and the reason");
    printf("# %s\n", err.message);
}

static void test_closed_pipe(void)
{
    int fds[2], in_place;
    rayo_output *out;
    rayo_error err;
    rayo_status status;
    if (pipe(fds) != 0) {
        ok(0, "a pipe");
        return;
    }
    close(fds[0]);
    status = rayo_output_open_fd(&out, fds[1], "pipe", &err);
    if (status == RAYO_OK)
        status = write_stream_and_commit(out, &in_place, &err);
    close(fds[1]);
    is_int(status, RAYO_ERR_PIPE, "closed pipe: RAYO_ERR_PIPE");
}

/* A terminal, and only a terminal, is one: a pseudo-terminal's device,
 * opened by its path as `-o /dev/pts/N` would; a file and /dev/null are
 * not. */
static void test_is_terminal(void)
{
    char path[] = "/tmp/rayo-t-output.XXXXXX";
    int fd = mkstemp(path), master = posix_openpt(O_RDWR | O_NOCTTY);
    const char *device = master < 0 || grantpt(master) != 0 ||
                                 unlockpt(master) != 0
                             ? NULL
                             : ptsname(master);
    rayo_output *out;
    rayo_error err;
    int opened;
    if (fd >= 0)
        close(fd);
    opened = fd >= 0 && rayo_output_open(&out, path, &err) == RAYO_OK;
    ok(opened && !rayo_output_is_terminal(out),
       "a regular file is not a terminal");
    if (opened)
        rayo_output_abort(out);
    unlink(path);
    opened = rayo_output_open(&out, "/dev/null", &err) == RAYO_OK;
    ok(opened && !rayo_output_is_terminal(out), "/dev/null is not a terminal");
    if (opened)
        rayo_output_abort(out);
    if (device == NULL) {
        ok(1, "# SKIP no pseudo-terminal");
    } else {
        opened = rayo_output_open(&out, device, &err) == RAYO_OK;
        ok(opened && rayo_output_is_terminal(out),
           "a pseudo-terminal (%s) is a terminal", device);
        if (opened)
            rayo_output_abort(out);
    }
    if (master >= 0)
        close(master);
}

int main(void)
{
    signal(SIGPIPE, SIG_IGN);
    test_is_terminal();
    test_file();
    test_pipe();
    test_full_device();
    test_closed_pipe();
    return tap_done();
}
