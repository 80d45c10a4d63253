/*
 * read_source.c - the buffered input cursor behind the image readers
 * (see read_source.h).
 *
 * A file is read in 64 KiB windows with read(2); memory is one window
 * that never refills.  The size of a regular file comes from fstat, so a
 * reader can refuse a header that promises more than the file holds.
 */
#define _POSIX_C_SOURCE 200809L

#include "read_source.h"

#include "rayo/lang.h"
#include "rayo/limits.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

void rayo_source_open_memory(rayo_source *src, const void *data, size_t size,
                             const char *name)
{
    static const unsigned char nothing[1];
    if (data == NULL || size == 0) {
        data = nothing; /* no arithmetic on a null pointer */
        size = 0;
    }
    memset(src, 0, sizeof *src);
    src->name = name;
    src->fd = -1;
    src->size_known = 1;
    src->size = size;
    src->start = data;
    src->next = src->start;
    src->end = src->start + size;
    src->limit = RAYO_MAX_INPUT_BYTES;
}

static rayo_status over_limit(const rayo_source *src, rayo_error *err)
{
    return rayo_error_set(err, RAYO_ERR_LIMIT,
                          "%s: byte %llu: found more data; expected an input "
                          "of at most %llu bytes",
                          src->name, (unsigned long long)src->limit,
                          (unsigned long long)src->limit);
}

static rayo_status open_descriptor(rayo_source *src, const char *path,
                                   rayo_error *err)
{
    if (strcmp(path, "-") == 0) {
        src->fd = STDIN_FILENO;
        src->name = "standard input";
        return RAYO_OK;
    }
    src->fd = open(path, O_RDONLY | O_CLOEXEC);
    if (src->fd < 0)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", path,
                              strerror(errno));
    src->owns_fd = 1;
    return RAYO_OK;
}

rayo_status rayo_source_open_file(rayo_source *src, const char *path,
                                  rayo_error *err)
{
    struct stat st;
    rayo_status status;
    memset(src, 0, sizeof *src);
    src->name = path;
    src->limit = RAYO_MAX_INPUT_BYTES;
    status = open_descriptor(src, path, err);
    if (status != RAYO_OK)
        return status;
    if (fstat(src->fd, &st) == 0 && S_ISDIR(st.st_mode)) {
        rayo_source_close(src);
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", path,
                              strerror(EISDIR));
    }
    if (fstat(src->fd, &st) == 0 && S_ISREG(st.st_mode)) {
        off_t here = lseek(src->fd, 0, SEEK_CUR);
        if (here >= 0 && here <= st.st_size) {
            src->size_known = 1;
            src->size = (uint64_t)(st.st_size - here);
        }
        if (src->size_known && src->size > src->limit) {
            rayo_source_close(src);
            return rayo_error_set(err, RAYO_ERR_LIMIT,
                                  "%s: the file is %llu bytes; expected at "
                                  "most %llu",
                                  src->name, (unsigned long long)src->size,
                                  (unsigned long long)src->limit);
        }
    }
    src->buffer = malloc(RAYO_SOURCE_BUFFER_SIZE);
    if (src->buffer == NULL) {
        rayo_source_close(src);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory", path);
    }
    src->start = src->buffer;
    src->next = src->buffer;
    src->end = src->buffer;
    return RAYO_OK;
}

void rayo_source_close(rayo_source *src)
{
    if (src->owns_fd && src->fd >= 0)
        close(src->fd);
    free(src->buffer);
    src->buffer = NULL;
    src->fd = -1;
    src->owns_fd = 0;
}

int rayo_source_refill(rayo_source *src)
{
    ssize_t n;
    size_t wanted = RAYO_SOURCE_BUFFER_SIZE;
    if (src->next != src->end)
        return 1;
    if (src->buffer == NULL || src->read_errno != 0)
        return 0;
    src->base += (uint64_t)(src->end - src->start);
    src->start = src->buffer;
    src->next = src->buffer;
    src->end = src->buffer;
    /* Up to the limit; at the limit, one byte more tells an input of
       exactly limit bytes (accepted) from a longer one (refused). */
    if (src->limit - src->base < wanted)
        wanted = src->base < src->limit ? (size_t)(src->limit - src->base)
                                        : 1;
    do
        n = read(src->fd, src->buffer, wanted);
    while (n < 0 && errno == EINTR);
    if (n < 0) {
        src->read_errno = errno;
        return 0;
    }
    if (n > 0 && src->base >= src->limit) {
        src->over_limit = 1;
        src->read_errno = EFBIG;
        return 0;
    }
    src->end = src->buffer + n;
    return n > 0;
}

int rayo_source_remaining(const rayo_source *src, uint64_t *remaining)
{
    uint64_t offset = rayo_source_offset(src);
    if (!src->size_known)
        return 0;
    *remaining = offset < src->size ? src->size - offset : 0;
    return 1;
}

void rayo_source_read(rayo_source *src, void *dst, size_t size, size_t *got)
{
    unsigned char *out = dst;
    size_t done = 0;
    while (done < size) {
        size_t available, take;
        if (src->next == src->end && !rayo_source_refill(src))
            break;
        available = (size_t)(src->end - src->next);
        take = size - done < available ? size - done : available;
        memcpy(out + done, src->next, take);
        src->next += take;
        done += take;
    }
    *got = done;
}

rayo_status rayo_source_count_rest(rayo_source *src, uint64_t *count,
                                   rayo_error *err)
{
    uint64_t remaining;
    *count = 0;
    /* A regular file's size says how much follows; it need not be read. */
    if (src->fd >= 0 && rayo_source_remaining(src, &remaining)) {
        *count = remaining;
        src->next = src->end;
        return RAYO_OK;
    }
    for (;;) {
        if (src->next == src->end && !rayo_source_refill(src))
            break;
        *count += (uint64_t)(src->end - src->next);
        src->next = src->end;
    }
    if (src->over_limit)
        return over_limit(src, err);
    if (src->read_errno != 0)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", src->name,
                              strerror(src->read_errno));
    return RAYO_OK;
}

rayo_status rayo_source_end_error(const rayo_source *src, const char *what,
                                  rayo_error *err)
{
    if (src->over_limit)
        return over_limit(src, err);
    if (src->read_errno != 0)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", src->name,
                              strerror(src->read_errno));
    return rayo_error_set(err, RAYO_ERR_FORMAT,
                          "%s: byte %llu: found the end of the file; "
                          "expected %s",
                          src->name,
                          (unsigned long long)rayo_source_offset(src),
                          rayo_gettext(rayo_error_lang(err), what));
}

const char *rayo_source_describe(int c, char *buffer, size_t size)
{
    if (c < 0)
        snprintf(buffer, size, "the end of the file");
    else if (c > ' ' && c < 127 && c != '\'')
        snprintf(buffer, size, "'%c'", c);
    else if (c == ' ')
        snprintf(buffer, size, "a space");
    else if (c == '\n')
        snprintf(buffer, size, "a newline");
    else
        snprintf(buffer, size, "byte 0x%02x", (unsigned)c);
    return buffer;
}
