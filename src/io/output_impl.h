/*
 * output_impl.h - what output.c (the buffer, descriptors, memory) and
 * output_file.c (creating and replacing files) share behind output.h:
 * the output's state and its life.  Not a public header.
 */
#ifndef RAYO_OUTPUT_IMPL_H
#define RAYO_OUTPUT_IMPL_H

#include <stddef.h>

#include "rayo/output.h"

#define OUTPUT_PIPE_BUFFER (64u * 1024u)    /* Linux's default pipe size */
#define OUTPUT_FILE_BUFFER (1024u * 1024u)  /* regular files */

/* References held between two writes, at most (a writev gathers twice
 * as many pieces and one, far below any system's IOV_MAX). */
#define OUTPUT_REFERENCES 64

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
    int in_memory;     /* rayo_output_open_memory: flushes append to
                          memory, handed to *memory_data on commit */
    unsigned char *memory;
    size_t memory_used, memory_capacity;
    unsigned char **memory_data;
    size_t *memory_size;
};

/* A new output with no descriptor, named display in messages; NULL when
 * out of memory. */
rayo_output *rayo_io_output_new(const char *display);

/* Closes what out owns and frees it (no file is removed). */
void rayo_io_output_free(rayo_output *out);

/* code (an errno) as out's error: RAYO_ERR_PIPE for EPIPE, else
 * RAYO_ERR_IO, "NAME: the system's reason". */
rayo_status rayo_io_output_error(const rayo_output *out, int code,
                                 rayo_error *err);

/*
 * What output_file.c does for output.c, a build without files
 * (RAYO_NO_FILE_OUTPUT) doing none of it:
 *
 * the buffer's size for out's descriptor: OUTPUT_FILE_BUFFER for a
 * regular file, else (and in a build without files) OUTPUT_PIPE_BUFFER;
 */
size_t rayo_io_output_buffer_size(const rayo_output *out);

/* once out->temp holds everything: syncs and closes it, and renames it
 * over the target; */
rayo_status rayo_io_output_file_finish(rayo_output *out, rayo_error *err);

/* removes out->temp (an output aborted or failed). */
void rayo_io_output_file_remove(rayo_output *out);

#endif
