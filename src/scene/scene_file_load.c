/*
 * scene_file_load.c - reading a scene file from disk into memory and
 * handing it to the parser (scene_file.c).
 *
 * The whole file ("-": standard input, named so in messages) is read,
 * up to RAYO_SCENE_MAX_BYTES: a regular file larger than that is refused
 * before a byte is read; a pipe is refused once it has delivered that
 * much.  Failures name the path and the
 * system's reason.
 */
#define _POSIX_C_SOURCE 200809L

#include "rayo/scene_file.h"

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

/* Grows buffer to hold at most RAYO_SCENE_MAX_BYTES + 1 bytes. */
static char *grow(char *buffer, size_t *capacity)
{
    size_t wanted = *capacity * 2;
    char *grown;
    if (wanted > RAYO_SCENE_MAX_BYTES + 1)
        wanted = RAYO_SCENE_MAX_BYTES + 1;
    grown = realloc(buffer, wanted);
    if (grown != NULL)
        *capacity = wanted;
    return grown;
}

static rayo_status read_all(FILE *in, const char *path, char **text,
                            size_t *length, rayo_error *err)
{
    size_t capacity = 64 * 1024, used = 0;
    char *buffer = malloc(capacity);
    if (buffer == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "%s: out of memory reading the scene", path);
    for (;;) {
        size_t got;
        if (used > RAYO_SCENE_MAX_BYTES) {
            free(buffer);
            return too_large(path, err);
        }
        if (used == capacity) {
            char *grown = grow(buffer, &capacity);
            if (grown == NULL) {
                free(buffer);
                return rayo_error_set(err, RAYO_ERR_NOMEM,
                                      "%s: out of memory reading the scene",
                                      path);
            }
            buffer = grown;
        }
        got = fread(buffer + used, 1, capacity - used, in);
        used += got;
        if (got == 0)
            break;
    }
    if (ferror(in)) {
        int error = errno;
        free(buffer);
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", path,
                              strerror(error));
    }
    *text = buffer;
    *length = used;
    return RAYO_OK;
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
    char *text = NULL;
    size_t length = 0;
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
        status = read_all(in, name, &text, &length, err);
    if (!from_stdin)
        fclose(in);
    if (status != RAYO_OK)
        return status;
    status = rayo_scene_file_parse_threads(file, name, text, length, threads,
                                           err);
    free(text);
    return status;
}
