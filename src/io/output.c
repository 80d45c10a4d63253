/*
 * output.c - buffered, atomic output files (see output.h for the contract).
 *
 * The temporary file is ".NAME.XXXXXX" in the target's directory, created
 * as mkstemp would (O_EXCL, six random characters), given the mode a new
 * file would get (0666 less the umask, or the existing file's mode),
 * filled, fsync'ed, closed and renamed.  Everything after the opening
 * goes through a descriptor of that directory (openat, renameat,
 * unlinkat): a directory renamed mid-way still gets its file, or loses
 * its temporary file, where it now is, and a signal handler can remove
 * the temporary file with one unlinkat (rayo_output_temp_at).
 *
 * What it replaces is respected as a shell's redirection would respect
 * it (output_target.c finds it and checks): an existing file we may not
 * write is refused before anything is created; a replaced file keeps its
 * mode and, when we are root, its owner and group; a symbolic link is
 * followed, so the link survives and its target is replaced, but only
 * where the kernel's protected_symlinks rule would follow it.
 *
 * The buffer's size suits what is written to, and is chosen (by fstat)
 * at the first write.  A pipe gets one pipe's worth: the reader empties
 * it while the next is being filled, so rendering overlaps with the
 * reader for free.  A regular file gets a large one: nothing runs in
 * parallel with a write to the page cache, and each write costs a fixed
 * amount besides its bytes, so fewer, larger writes are faster (the seed
 * job, 312 KB, goes out in one).  Blocks at least OUTPUT_DIRECT_WRITE
 * long skip the buffer and are written from the caller's memory.
 *
 * The library's formatters may also hand over bytes by reference
 * (rayo_output_refer, output_reserve.h): bytes that stay put until the
 * next write, such as plain PBM's template of white rows.  They are not
 * copied into the buffer; the next write gathers them, in order, with
 * the buffer's bytes around them (writev), so the kernel copies them
 * once, straight from where they are.
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE

#include "rayo/output.h"

#include "output_reserve.h"
#include "output_target.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <time.h>
#include <unistd.h>

#define OUTPUT_PIPE_BUFFER (64u * 1024u)    /* Linux's default pipe size */
#define OUTPUT_FILE_BUFFER (1024u * 1024u)  /* regular files */
#define OUTPUT_DIRECT_WRITE (64u * 1024u)
/* References held between two writes, at most (a writev gathers twice
 * as many pieces and one, far below any system's IOV_MAX). */
#define OUTPUT_REFERENCES 64

/* Names tried for the temporary file before giving up (mkstemp's
 * EEXIST); each is one of 62^6. */
#define OUTPUT_TEMP_TRIES 100

/* A write smaller than OUTPUT_DIRECT_WRITE must fit an empty buffer. */
_Static_assert(OUTPUT_DIRECT_WRITE <= OUTPUT_PIPE_BUFFER &&
                   OUTPUT_DIRECT_WRITE <= OUTPUT_FILE_BUFFER,
               "small writes must fit every buffer");

/* Bytes by reference: size bytes at data, after the buffer's first at. */
typedef struct output_reference {
    size_t at;
    const unsigned char *data;
    size_t size;
} output_reference;

struct rayo_output {
    int fd;
    int owns_fd;
    int dir_fd;      /* the target's directory, or -1 (writing directly) */
    char *name;      /* the target's name in it (links followed) */
    char *temp;      /* temporary file's name in it, NULL when writing
                        directly */
    char *display;   /* name for messages */
    unsigned char *buffer; /* allocated at the first write */
    size_t capacity;
    size_t used;
    output_reference references[OUTPUT_REFERENCES];
    size_t reference_count;
    size_t referenced; /* bytes the references hold */
    int write_errno;   /* why a write failed, once one has: bytes were
                          lost, so the output can no longer be committed */
    int abandoned;     /* an image on it was abandoned
                          (rayo_output_abandon): the same */
};

static rayo_status system_error(const rayo_output *out, int code,
                                rayo_error *err)
{
    if (code == EPIPE)
        return rayo_error_set(err, RAYO_ERR_PIPE, "%s: %s", out->display,
                              strerror(code));
    return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", out->display,
                          strerror(code));
}

static void output_free(rayo_output *out)
{
    if (out->owns_fd && out->fd >= 0)
        close(out->fd);
    if (out->dir_fd >= 0)
        close(out->dir_fd);
    free(out->buffer);
    free(out->name);
    free(out->temp);
    free(out->display);
    free(out);
}

static rayo_output *output_new(const char *display)
{
    rayo_output *out = malloc(sizeof *out);
    if (out == NULL)
        return NULL;
    out->fd = -1;
    out->owns_fd = 0;
    out->dir_fd = -1;
    out->name = NULL;
    out->temp = NULL;
    out->buffer = NULL;
    out->capacity = 0;
    out->used = 0;
    out->reference_count = 0;
    out->referenced = 0;
    out->write_errno = 0;
    out->abandoned = 0;
    out->display = strdup(display);
    if (out->display == NULL) {
        free(out);
        return NULL;
    }
    return out;
}

rayo_status rayo_output_open_fd(rayo_output **result, int fd,
                                const char *name, rayo_error *err)
{
    rayo_output *out = output_new(name);
    *result = NULL;
    if (out == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory", name);
    out->fd = fd;
    *result = out;
    return RAYO_OK;
}

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
        return system_error(out, code, err);
    }
    out->owns_fd = 1;
    if (set_attributes(out->fd, want) != 0) {
        rayo_status status = system_error(out, errno, err);
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
    out = output_new(path);
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
            status = system_error(out, code, err);
            output_free(out);
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
            status = system_error(out, code, err);
        rayo_output_target_free(&target);
        output_free(out);
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
        output_free(out);
        return status;
    }
    *result = out;
    return RAYO_OK;
}

/* Writes count pieces, whatever part of them each writev takes. */
static rayo_status writev_all(rayo_output *out, struct iovec *pieces,
                              int count, rayo_error *err)
{
    while (count > 0) {
        ssize_t n = writev(out->fd, pieces, count);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            out->write_errno = errno;
            return system_error(out, errno, err);
        }
        while (count > 0 && (size_t)n >= pieces->iov_len) {
            n -= (ssize_t)pieces->iov_len;
            pieces++;
            count--;
        }
        if (count > 0) {
            pieces->iov_base = (char *)pieces->iov_base + n;
            pieces->iov_len -= (size_t)n;
        }
    }
    return RAYO_OK;
}

static rayo_status write_all(rayo_output *out, const void *data,
                             size_t size, rayo_error *err)
{
    struct iovec piece;
    piece.iov_base = (void *)(uintptr_t)data;
    piece.iov_len = size;
    return writev_all(out, &piece, size > 0, err);
}

/* The buffer and the references, in order, in one writev. */
static rayo_status flush_gathered(rayo_output *out, rayo_error *err)
{
    struct iovec pieces[2 * OUTPUT_REFERENCES + 1];
    size_t at = 0, i;
    int count = 0;
    for (i = 0; i < out->reference_count; i++) {
        const output_reference *r = &out->references[i];
        if (r->at > at) {
            pieces[count].iov_base = out->buffer + at;
            pieces[count++].iov_len = r->at - at;
            at = r->at;
        }
        pieces[count].iov_base = (void *)(uintptr_t)r->data;
        pieces[count++].iov_len = r->size;
    }
    if (out->used > at) {
        pieces[count].iov_base = out->buffer + at;
        pieces[count++].iov_len = out->used - at;
    }
    return writev_all(out, pieces, count, err);
}

/* Writes out the buffer and the references; both are empty after, even
 * when the write fails. */
static rayo_status flush(rayo_output *out, rayo_error *err)
{
    rayo_status status = out->reference_count > 0
                             ? flush_gathered(out, err)
                             : write_all(out, out->buffer, out->used, err);
    out->used = 0;
    out->reference_count = 0;
    out->referenced = 0;
    return status;
}

/* Allocates the buffer, its size fitted to out->fd. */
static rayo_status make_buffer(rayo_output *out, rayo_error *err)
{
    struct stat st;
    size_t capacity = OUTPUT_PIPE_BUFFER;
    if (fstat(out->fd, &st) == 0 && S_ISREG(st.st_mode))
        capacity = OUTPUT_FILE_BUFFER;
    out->buffer = malloc(capacity);
    if (out->buffer == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                              out->display);
    out->capacity = capacity;
    return RAYO_OK;
}

rayo_status rayo_output_reserve(rayo_output *out, size_t size,
                                unsigned char **room, size_t *available,
                                rayo_error *err)
{
    rayo_status status;
    *room = NULL;
    *available = 0;
    if (out->buffer == NULL && (status = make_buffer(out, err)) != RAYO_OK)
        return status;
    if (size > out->capacity)
        return RAYO_OK;
    if (size > out->capacity - out->used - out->referenced &&
        (status = flush(out, err)) != RAYO_OK)
        return status;
    *room = out->buffer + out->used;
    *available = out->capacity - out->used - out->referenced;
    return RAYO_OK;
}

rayo_status rayo_output_write(rayo_output *out, const void *data,
                              size_t size, rayo_error *err)
{
    unsigned char *room;
    size_t available;
    rayo_status status;
    if (size >= OUTPUT_DIRECT_WRITE) {
        status = flush(out, err);
        return status == RAYO_OK ? write_all(out, data, size, err) : status;
    }
    /* Smaller than every buffer (the assertion above): room is found. */
    status = rayo_output_reserve(out, size, &room, &available, err);
    if (status != RAYO_OK)
        return status;
    memcpy(room, data, size);
    out->used += size;
    return RAYO_OK;
}

rayo_status rayo_output_refer(rayo_output *out, const void *data,
                              size_t size, rayo_error *err)
{
    rayo_status status;
    output_reference *r;
    if (size == 0)
        return RAYO_OK;
    if (out->buffer == NULL && (status = make_buffer(out, err)) != RAYO_OK)
        return status;
    /* No more pending than a buffer's worth: a pipe's reader still gets
     * it in pieces, and a full list of references goes out first. */
    if (out->reference_count == OUTPUT_REFERENCES ||
        size > out->capacity - out->used - out->referenced) {
        status = flush(out, err);
        if (status != RAYO_OK)
            return status;
        if (size > out->capacity)
            return write_all(out, data, size, err);
    }
    r = &out->references[out->reference_count++];
    r->at = out->used;
    r->data = data;
    r->size = size;
    out->referenced += size;
    return RAYO_OK;
}

rayo_status rayo_output_release(rayo_output *out, rayo_error *err)
{
    return out->reference_count > 0 ? flush(out, err) : RAYO_OK;
}

void rayo_output_abandon(rayo_output *out)
{
    out->used = 0;
    out->reference_count = 0;
    out->referenced = 0;
    out->abandoned = 1;
}

void rayo_output_advance(rayo_output *out, size_t n)
{
    size_t room = out->capacity - out->used - out->referenced;
    out->used += n < room ? n : room;
}

rayo_status rayo_output_commit(rayo_output *out, rayo_error *err)
{
    rayo_status status;
    if (out->write_errno != 0)
        status = system_error(out, out->write_errno, err);
    else if (out->abandoned)
        status = rayo_error_set(err, RAYO_ERR_INVALID,
                                "%s: incomplete: an image written to it "
                                "was abandoned",
                                out->display);
    else
        status = flush(out, err);
    if (status == RAYO_OK && out->temp != NULL) {
        int failed = fsync(out->fd) != 0, code = errno;
        if (close(out->fd) != 0 && !failed) {
            failed = 1;
            code = errno;
        }
        out->fd = -1;
        if (failed) {
            status = system_error(out, code, err);
        } else {
            if (renameat(out->dir_fd, out->temp, out->dir_fd, out->name) != 0)
                status = system_error(out, errno, err);
            else {
                free(out->temp);
                out->temp = NULL;
            }
        }
    }
    if (status != RAYO_OK) {
        rayo_output_abort(out);
        return status;
    }
    output_free(out);
    return RAYO_OK;
}

void rayo_output_abort(rayo_output *out)
{
    if (out == NULL)
        return;
    if (out->temp != NULL)
        unlinkat(out->dir_fd, out->temp, 0);
    output_free(out);
}

const char *rayo_output_name(const rayo_output *out)
{
    return out->display;
}

const char *rayo_output_temp_at(const rayo_output *out, int *dir_fd)
{
    *dir_fd = out->temp != NULL ? out->dir_fd : -1;
    return out->temp;
}

int rayo_output_is_terminal(const rayo_output *out)
{
    return out->temp == NULL && isatty(out->fd);
}
