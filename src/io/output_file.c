/*
 * output_file.c - rayo_output_open: a file that appears whole or not at
 * all (output.h).  It is written as ".NAME.XXXXXX" beside the target
 * (O_EXCL, as mkstemp would; the target's mode, or a new file's), and
 * output.c's commit fsyncs it and renames it over the target, all through
 * a descriptor of the directory (openat, renameat, unlinkat), so that a
 * directory renamed mid-way still gets its file.  What it replaces is
 * respected as a shell's `>` would (output_target.c): a file we may not
 * write is refused, a replaced file keeps its mode (and, for root, its
 * owner), a link is followed where protected_symlinks allows.  It also
 * sizes a descriptor's buffer (fstat).  Built with RAYO_NO_FILE_OUTPUT
 * (a host without files: the page's WebAssembly), only a refusal of
 * every path but "-" is compiled, and no file system call is made.
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE

#include "rayo/output.h"

#include "output_impl.h"
#ifndef RAYO_NO_FILE_OUTPUT
#include "output_target.h"
#endif

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* Names tried for the temporary file before giving up (mkstemp's
 * EEXIST); each is one of 62^6. */
#define OUTPUT_TEMP_TRIES 100

#ifndef RAYO_NO_FILE_OUTPUT
/* The mode a newly created file would get: 0666 less the umask. */
static mode_t new_file_mode(void)
{
    mode_t mask = umask(022);
    umask(mask);
    return (mode_t)(0666 & ~mask);
}

/* Six characters of [0-9A-Za-z] for a temporary name, from a mix of
 * the clock, the process and a counter (splitmix64): O_EXCL, not the
 * randomness, keeps the file ours. */
static void random_suffix(char *six)
{
    static const char alphabet[] =
        "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";
    static uint64_t counter;
    struct timespec ts;
    uint64_t x;
    int i;
    clock_gettime(CLOCK_REALTIME, &ts);
    x = (uint64_t)ts.tv_nsec ^ ((uint64_t)ts.tv_sec << 30) ^
        ((uint64_t)getpid() << 20) ^ (++counter * 0x9e3779b97f4a7c15u);
    x += 0x9e3779b97f4a7c15u;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9u;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebu;
    x ^= x >> 31;
    for (i = 0; i < 6; i++, x /= 62)
        six[i] = alphabet[x % 62];
}

/* What the temporary file must have: the replaced file's mode (and, for
 * root, owner), or a new file's. */
typedef struct output_attributes {
    mode_t mode;
    int keep_owner; /* 1: give it uid and gid */
    uid_t uid;
    gid_t gid;
} output_attributes;

/* Gives the new temporary file its owner (first: chown clears the
 * set-user-ID bit) and mode. */
static int set_attributes(int fd, const output_attributes *want)
{
    struct stat st;
    if (want->keep_owner && fstat(fd, &st) == 0 &&
        (st.st_uid != want->uid || st.st_gid != want->gid) &&
        fchown(fd, want->uid, want->gid) != 0)
        return -1;
    return fchmod(fd, want->mode);
}

/* Creates ".NAME.XXXXXX" in out->dir_fd, as mkstemp would; sets
 * out->temp and out->fd. */
static rayo_status open_temporary(rayo_output *out,
                                  const output_attributes *want,
                                  rayo_error *err)
{
    size_t length = strlen(out->name);
    int tries, code = EEXIST;
    out->temp = malloc(length + sizeof "..XXXXXX");
    if (out->temp == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                              out->display);
    out->temp[0] = '.';
    memcpy(out->temp + 1, out->name, length);
    out->temp[length + 1] = '.';
    out->temp[length + 8] = '\0';
    for (tries = 0; tries < OUTPUT_TEMP_TRIES && code == EEXIST; tries++) {
        random_suffix(out->temp + length + 2);
        out->fd = openat(out->dir_fd, out->temp,
                         O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
        code = out->fd < 0 ? errno : 0;
    }
    if (out->fd < 0) {
        free(out->temp);
        out->temp = NULL;
        return rayo_io_output_error(out, code, err);
    }
    out->owns_fd = 1;
    if (set_attributes(out->fd, want) != 0) {
        rayo_status status = rayo_io_output_error(out, errno, err);
        unlinkat(out->dir_fd, out->temp, 0);
        free(out->temp);
        out->temp = NULL;
        return status;
    }
    return RAYO_OK;
}

rayo_status rayo_output_open(rayo_output **result, const char *path,
                             rayo_error *err)
{
    rayo_output *out;
    rayo_output_target target;
    output_attributes want;
    rayo_status status;
    int code;
    *result = NULL;
    if (strcmp(path, "-") == 0)
        return rayo_output_open_fd(result, STDOUT_FILENO, "standard output",
                                   err);
    out = rayo_io_output_new(path);
    if (out == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory", path);
    code = rayo_output_target_find(&target, path);
    if (code == 0 && target.exists && S_ISDIR(target.st.st_mode))
        code = EISDIR;
    if (code == 0 && target.exists && !S_ISREG(target.st.st_mode)) {
        /* A device, pipe or socket: write straight into it. */
        out->fd = openat(target.dir_fd, target.name,
                         O_WRONLY | O_TRUNC | O_CLOEXEC);
        code = out->fd < 0 ? errno : 0;
        rayo_output_target_free(&target);
        if (code != 0) {
            status = rayo_io_output_error(out, code, err);
            rayo_io_output_free(out);
            return status;
        }
        out->owns_fd = 1;
        *result = out;
        return RAYO_OK;
    }
    if (code == 0 && target.exists)
        code = rayo_output_target_replaceable(&target);
    if (code != 0) {
        if (target.refused_link)
            status = rayo_error_set(
                err, RAYO_ERR_IO,
                "%s: %s (a symbolic link in a sticky world-writable "
                "directory, owned by another user: not followed)",
                path, strerror(code));
        else
            status = rayo_io_output_error(out, code, err);
        rayo_output_target_free(&target);
        rayo_io_output_free(out);
        return status;
    }
    want.mode = target.exists ? (mode_t)(target.st.st_mode & 07777)
                              : new_file_mode();
    want.keep_owner = target.exists && geteuid() == 0;
    want.uid = target.exists ? target.st.st_uid : 0;
    want.gid = target.exists ? target.st.st_gid : 0;
    out->dir_fd = target.dir_fd; /* taken over */
    out->name = target.name;
    status = open_temporary(out, &want, err);
    if (status != RAYO_OK) {
        rayo_io_output_free(out);
        return status;
    }
    *result = out;
    return RAYO_OK;
}

size_t rayo_io_output_buffer_size(const rayo_output *out)
{
    struct stat st;
    if (fstat(out->fd, &st) == 0 && S_ISREG(st.st_mode))
        return OUTPUT_FILE_BUFFER;
    return OUTPUT_PIPE_BUFFER;
}

rayo_status rayo_io_output_file_finish(rayo_output *out, rayo_error *err)
{
    int failed = fsync(out->fd) != 0, code = errno;
    if (close(out->fd) != 0 && !failed) {
        failed = 1;
        code = errno;
    }
    out->fd = -1;
    if (failed)
        return rayo_io_output_error(out, code, err);
    if (renameat(out->dir_fd, out->temp, out->dir_fd, out->name) != 0)
        return rayo_io_output_error(out, errno, err);
    free(out->temp);
    out->temp = NULL;
    return RAYO_OK;
}

void rayo_io_output_file_remove(rayo_output *out)
{
    unlinkat(out->dir_fd, out->temp, 0);
}
#else
rayo_status rayo_output_open(rayo_output **result, const char *path,
                             rayo_error *err)
{
    *result = NULL;
    if (strcmp(path, "-") == 0)
        return rayo_output_open_fd(result, STDOUT_FILENO, "standard output",
                                   err);
    return rayo_error_set(err, RAYO_ERR_IO,
                          "%s: this build of rayo writes no files (it was "
                          "built with RAYO_NO_FILE_OUTPUT)",
                          path);
}

size_t rayo_io_output_buffer_size(const rayo_output *out)
{
    (void)out;
    return OUTPUT_PIPE_BUFFER;
}

/* No file is ever opened: out->temp stays NULL, and these go uncalled. */
rayo_status rayo_io_output_file_finish(rayo_output *out, rayo_error *err)
{
    (void)out, (void)err;
    return RAYO_OK;
}

void rayo_io_output_file_remove(rayo_output *out) { (void)out; }
#endif
