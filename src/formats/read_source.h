/*
 * read_source.h - the bytes an image reader reads: a file, standard input
 * or a block of memory, behind one buffered cursor that knows its byte
 * offset and, when it can, how many bytes are left.
 *
 * Readers use it to stream (a file is never read whole into memory), to
 * say where a problem is (the offset), and to check that a raw raster can
 * be there before allocating it (the remaining size of a regular file or
 * of memory).  Not a public header; not a general I/O layer (output.h is
 * the other direction).
 */
#ifndef RAYO_READ_SOURCE_H
#define RAYO_READ_SOURCE_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/status.h"

#define RAYO_SOURCE_BUFFER_SIZE (64u * 1024u)

typedef struct rayo_source {
    const char *name;            /* for messages */
    int fd;                      /* -1 for memory */
    int owns_fd;
    int read_errno;              /* the system's reason a read failed, or 0 */
    int size_known;              /* regular file or memory */
    uint64_t size;               /* total bytes, when size_known */
    unsigned char *buffer;       /* owned; NULL for memory */
    const unsigned char *start;  /* the window read so far */
    const unsigned char *next;   /* next unread byte in the window */
    const unsigned char *end;    /* end of the window */
    uint64_t base;               /* offset of start in the stream */
    uint64_t limit;              /* most bytes read (RAYO_MAX_INPUT_BYTES) */
    int over_limit;              /* more than limit bytes were offered;
                                    read_errno is then EFBIG */
} rayo_source;

/* Reads from memory; nothing is copied, data must outlive the source. */
void rayo_source_open_memory(rayo_source *src, const void *data, size_t size,
                             const char *name);

/* Opens path for reading; "-" is standard input (named so in messages). */
rayo_status rayo_source_open_file(rayo_source *src, const char *path,
                                  rayo_error *err);

void rayo_source_close(rayo_source *src);

/*
 * Refills an exhausted window.  Returns 1 when bytes are available, 0 at
 * the end of the data or after a failed read (read_errno says which).
 */
int rayo_source_refill(rayo_source *src);

/* The next byte, or -1 at the end (or after a failed read). */
static inline int rayo_source_getc(rayo_source *src)
{
    if (src->next == src->end && !rayo_source_refill(src))
        return -1;
    return *src->next++;
}

/* The next byte without consuming it, or -1. */
static inline int rayo_source_peek(rayo_source *src)
{
    if (src->next == src->end && !rayo_source_refill(src))
        return -1;
    return *src->next;
}

/* Offset of the next unread byte. */
static inline uint64_t rayo_source_offset(const rayo_source *src)
{
    return src->base + (uint64_t)(src->next - src->start);
}

/* Bytes left after the cursor, when the size is known; 0 when not. */
int rayo_source_remaining(const rayo_source *src, uint64_t *remaining);

/*
 * Copies up to size bytes into dst; *got says how many (fewer only at the
 * end of the data or after a failed read).
 */
void rayo_source_read(rayo_source *src, void *dst, size_t size, size_t *got);

/* Consumes the rest of the data, counting it. */
rayo_status rayo_source_count_rest(rayo_source *src, uint64_t *count,
                                   rayo_error *err);

/*
 * The error for running out of data at the cursor: RAYO_ERR_IO with the
 * system's reason after a failed read, else RAYO_ERR_FORMAT "FILE: byte
 * N: found the end of the file; expected WHAT".
 */
rayo_status rayo_source_end_error(const rayo_source *src, const char *what,
                                  rayo_error *err);

/*
 * Describes byte c (from rayo_source_getc) for a message: 'x' for a
 * printable character, "byte 0x89" otherwise, "the end of the file" for
 * -1.  Returns buffer.
 */
const char *rayo_source_describe(int c, char *buffer, size_t size);

#endif
