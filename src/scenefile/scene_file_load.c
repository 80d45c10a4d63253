/*
 * scene_file_load.c - reading a scene file from disk into memory and
 * handing it to the parser (scene_file.c).
 *
 * The whole file ("-": standard input, named so in messages) is read,
 * up to RAYO_SCENE_MAX_BYTES: a regular file larger than that is refused
 * before a byte is read; a pipe is refused once it has delivered that
 * much.  It is read a window at a time into one buffer of SCENE_WINDOW
 * bytes, each window parsed before the next is read
 * (scene_file_impl.h), and the hierarchy is built once the buffer is
 * freed.  Failures name the path and the system's reason.
 */
#define _POSIX_C_SOURCE 200809L

#include "rayo/scene_file.h"
#include "scene_file_impl.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static rayo_status too_large(const char *path, rayo_error *err)
{
    return rayo_error_set(err, RAYO_ERR_LIMIT,
                          "%s: the file is larger than %lu bytes; expected "
                          "a smaller scene",
                          path, RAYO_SCENE_MAX_BYTES);
}

/* Where the window in buffer[0, filled) ends: just after its last
 * newline; all of it when it has none (at the end of the file, or a
 * line longer than the window, which the lexer refuses). */
static size_t window_length(const char *buffer, size_t filled, int at_end)
{
    size_t n = filled;
    if (at_end)
        return filled;
    while (n > 0 && buffer[n - 1] != '\n')
        n--;
    return n > 0 ? n : filled;
}

/*
 * Reads the file a window at a time into one buffer (scene_file_impl.h),
 * each window's whole lines to the reader, the rest of its last line
 * moved to the buffer's start for the next.
 */
static rayo_status read_windows(FILE *in, const char *name, scene_reader *r,
                                rayo_error *err)
{
    char *buffer = malloc(SCENE_WINDOW);
    size_t filled = 0, total = 0;
    int at_end = 0;
    rayo_status status = RAYO_OK;
    if (buffer == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "%s: out of memory reading the scene", name);
    while (status == RAYO_OK) {
        size_t take;
        while (!at_end && filled < SCENE_WINDOW) {
            size_t got = fread(buffer + filled, 1, SCENE_WINDOW - filled, in);
            filled += got;
            total += got;
            if (got == 0)
                at_end = 1;
        }
        if (ferror(in)) {
            int error = errno;
            status = rayo_error_set(err, RAYO_ERR_IO, "%s: %s", name,
                                    strerror(error));
            break;
        }
        if (total > RAYO_SCENE_MAX_BYTES) {
            status = too_large(name, err);
            break;
        }
        if (filled == 0)
            break;
        take = window_length(buffer, filled, at_end);
        status = scene_reader_take(r, buffer, take);
        memmove(buffer, buffer + take, filled - take);
        filled -= take;
    }
    free(buffer);
    return status;
}

rayo_status rayo_scene_file_load(rayo_scene_file *file, const char *path,
                                 rayo_error *err)
{
    return rayo_scene_file_load_threads(file, path, 0, err);
}

rayo_status rayo_scene_file_load_threads(rayo_scene_file *file,
                                         const char *path, unsigned threads,
                                         rayo_error *err)
{
    struct stat info;
    scene_reader *reader;
    rayo_status status;
    int from_stdin = strcmp(path, "-") == 0;
    const char *name = from_stdin ? "standard input" : path;
    FILE *in = from_stdin ? stdin : fopen(path, "rb");
    file->scene = NULL;
    if (in == NULL)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", path,
                              strerror(errno));
    if (fstat(fileno(in), &info) == 0 && S_ISREG(info.st_mode) &&
        (unsigned long long)info.st_size > RAYO_SCENE_MAX_BYTES)
        status = too_large(name, err);
    else
        status = scene_reader_new(&reader, file, name, threads, err);
    if (status == RAYO_OK)
        status = scene_reader_end(reader,
                                  read_windows(in, name, reader, err));
    if (!from_stdin)
        fclose(in);
    if (status == RAYO_OK)
        status = scene_file_prepare(file, threads, err);
    return status;
}
