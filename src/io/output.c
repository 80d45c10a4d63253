/*
 * output.c - buffered output (see output.h for the contract): to a
 * descriptor, a file (its creation and replacing: output_file.c) or memory.
 *
 * It fills one buffer, sized for what it writes to, and writes it out,
 * gathering the bytes a formatter hands over by reference; it formats
 * nothing itself (the writers do).  How the buffer is sized, the bytes
 * by reference, and memory outputs are said after the includes.
 */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE

#include "rayo/output.h"

#include "output_impl.h"
#include "output_reserve.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/uio.h>
#include <unistd.h>

/*
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
 *
 * An output into memory (rayo_output_open_memory) has no descriptor: the
 * same buffer's flushes append to a growing block, handed over on commit.
 */

#define OUTPUT_DIRECT_WRITE (64u * 1024u)

/* A write smaller than OUTPUT_DIRECT_WRITE must fit an empty buffer. */
_Static_assert(OUTPUT_DIRECT_WRITE <= OUTPUT_PIPE_BUFFER &&
                   OUTPUT_DIRECT_WRITE <= OUTPUT_FILE_BUFFER,
               "small writes must fit every buffer");

rayo_status rayo_io_output_error(const rayo_output *out, int code,
                                  rayo_error *err)
{
    if (code == EPIPE)
        return rayo_error_set(err, RAYO_ERR_PIPE, "%s: %s", out->display,
                              strerror(code));
    return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", out->display,
                          strerror(code));
}

void rayo_io_output_free(rayo_output *out)
{
    if (out->owns_fd && out->fd >= 0)
        close(out->fd);
    if (out->dir_fd >= 0)
        close(out->dir_fd);
    free(out->buffer);
    free(out->memory);
    free(out->name);
    free(out->temp);
    free(out->display);
    free(out);
}

rayo_output *rayo_io_output_new(const char *display)
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
    out->in_memory = 0;
    out->memory = NULL;
    out->memory_used = out->memory_capacity = 0;
    out->memory_data = NULL;
    out->memory_size = NULL;
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
    rayo_output *out = rayo_io_output_new(name);
    *result = NULL;
    if (out == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory", name);
    out->fd = fd;
    *result = out;
    return RAYO_OK;
}

rayo_status rayo_output_open_memory(rayo_output **result, const char *name,
                                    unsigned char **data, size_t *size,
                                    rayo_error *err)
{
    rayo_output *out = rayo_io_output_new(name);
    *result = NULL;
    if (out == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory", name);
    out->in_memory = 1;
    out->memory_data = data;
    out->memory_size = size;
    *result = out;
    return RAYO_OK;
}


/* Appends count pieces to an output into memory's block, which grows by
 * doubling; fails, and the output with it, when it cannot. */
static rayo_status append_all(rayo_output *out, const struct iovec *pieces,
                              int count, rayo_error *err)
{
    size_t need = 0, want = out->memory_capacity;
    unsigned char *grown;
    int i;
    for (i = 0; i < count; i++) {
        if (pieces[i].iov_len > SIZE_MAX - out->memory_used - need)
            goto no_memory;
        need += pieces[i].iov_len;
    }
    if (need > out->memory_capacity - out->memory_used) {
        if (want == 0)
            want = OUTPUT_PIPE_BUFFER;
        while (want - out->memory_used < need) {
            if (want > SIZE_MAX / 2) {
                want = out->memory_used + need;
                break;
            }
            want *= 2;
        }
        grown = realloc(out->memory, want);
        if (grown == NULL)
            goto no_memory;
        out->memory = grown;
        out->memory_capacity = want;
    }
    for (i = 0; i < count; i++) {
        if (pieces[i].iov_len > 0)
            memcpy(out->memory + out->memory_used, pieces[i].iov_base,
                   pieces[i].iov_len);
        out->memory_used += pieces[i].iov_len;
    }
    return RAYO_OK;
no_memory:
    out->write_errno = ENOMEM;
    return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                          out->display);
}

/* Writes count pieces, whatever part of them each writev takes. */
static rayo_status writev_all(rayo_output *out, struct iovec *pieces,
                              int count, rayo_error *err)
{
    if (out->in_memory)
        return append_all(out, pieces, count, err);
    while (count > 0) {
        ssize_t n = writev(out->fd, pieces, count);
        if (n < 0) {
            if (errno == EINTR)
                continue;
            out->write_errno = errno;
            return rayo_io_output_error(out, errno, err);
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
    size_t capacity = out->in_memory ? OUTPUT_PIPE_BUFFER
                                     : rayo_io_output_buffer_size(out);
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
        status = rayo_io_output_error(out, out->write_errno, err);
    else if (out->abandoned)
        status = rayo_error_set(err, RAYO_ERR_INVALID,
                                "%s: incomplete: an image written to it "
                                "was abandoned",
                                out->display);
    else
        status = flush(out, err);
    if (status == RAYO_OK && out->temp != NULL)
        status = rayo_io_output_file_finish(out, err);
    if (status != RAYO_OK) {
        rayo_output_abort(out);
        return status;
    }
    if (out->in_memory) {
        *out->memory_data = out->memory;
        *out->memory_size = out->memory_used;
        out->memory = NULL;
    }
    rayo_io_output_free(out);
    return RAYO_OK;
}

void rayo_output_abort(rayo_output *out)
{
    if (out == NULL)
        return;
    if (out->temp != NULL)
        rayo_io_output_file_remove(out);
    rayo_io_output_free(out);
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
    return !out->in_memory && out->temp == NULL && isatty(out->fd);
}
