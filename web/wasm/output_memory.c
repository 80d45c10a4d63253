/*
 * output_memory.c - rayo's output (include/rayo/output.h and
 * src/io/output_reserve.h) into memory, for the page's WebAssembly
 * build, in place of src/io/output.c.
 *
 * The page has no files: what the library writes (a difference picture,
 * a Netpbm image) is collected in a growing buffer and, on commit, handed
 * to the web_bytes the caller gave (web.h), for the script to copy out.
 * The contract is output.c's: an abandoned image makes the commit fail,
 * and an output that is aborted leaves nothing.  rayo_output_open and
 * rayo_output_open_fd (files) refuse.
 */
#include <stdlib.h>
#include <string.h>

#include "rayo/output.h"

#include "../../src/io/output_reserve.h"
#include "web.h"

struct rayo_output {
    web_bytes *result;
    unsigned char *data;
    size_t used, capacity;
    int abandoned;
    char name[64];
};

rayo_status web_output_open(rayo_output **out, const char *name,
                            web_bytes *result, rayo_error *err)
{
    rayo_output *o = calloc(1, sizeof *o);
    *out = NULL;
    if (o == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    o->result = result;
    strncpy(o->name, name, sizeof o->name - 1);
    *out = o;
    return RAYO_OK;
}

rayo_status rayo_output_open(rayo_output **out, const char *path,
                             rayo_error *err)
{
    *out = NULL;
    return rayo_error_set(err, RAYO_ERR_IO, "%s: the page writes no files",
                          path);
}

rayo_status rayo_output_open_fd(rayo_output **out, int fd, const char *name,
                                rayo_error *err)
{
    (void)fd;
    return rayo_output_open(out, name, err);
}

static rayo_status grow(rayo_output *out, size_t more, rayo_error *err)
{
    size_t want = out->capacity ? out->capacity : 64 * 1024;
    unsigned char *data;
    if (more <= out->capacity - out->used)
        return RAYO_OK;
    while (want - out->used < more) {
        if (want > (size_t)-1 / 2)
            return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                                  out->name);
        want *= 2;
    }
    data = realloc(out->data, want);
    if (data == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                              out->name);
    out->data = data;
    out->capacity = want;
    return RAYO_OK;
}

rayo_status rayo_output_write(rayo_output *out, const void *data,
                              size_t size, rayo_error *err)
{
    rayo_status s = grow(out, size, err);
    if (s != RAYO_OK)
        return s;
    if (size)
        memcpy(out->data + out->used, data, size);
    out->used += size;
    return RAYO_OK;
}

rayo_status rayo_output_reserve(rayo_output *out, size_t size,
                                unsigned char **room, size_t *available,
                                rayo_error *err)
{
    rayo_status s = grow(out, size, err);
    *room = NULL;
    *available = 0;
    if (s != RAYO_OK)
        return s;
    *room = out->data + out->used;
    *available = out->capacity - out->used;
    return RAYO_OK;
}

void rayo_output_advance(rayo_output *out, size_t n)
{
    if (n > out->capacity - out->used)
        n = out->capacity - out->used;
    out->used += n;
}

rayo_status rayo_output_refer(rayo_output *out, const void *data,
                              size_t size, rayo_error *err)
{
    return rayo_output_write(out, data, size, err);
}

rayo_status rayo_output_release(rayo_output *out, rayo_error *err)
{
    (void)out, (void)err;
    return RAYO_OK;
}

void rayo_output_abandon(rayo_output *out) { out->abandoned = 1; }

void rayo_output_abort(rayo_output *out)
{
    if (out == NULL)
        return;
    free(out->data);
    free(out);
}

rayo_status rayo_output_commit(rayo_output *out, rayo_error *err)
{
    rayo_status s = RAYO_OK;
    if (out->abandoned) {
        s = rayo_error_set(err, RAYO_ERR_IO,
                           "%s: incomplete: an image written to it was "
                           "abandoned",
                           out->name);
        free(out->data);
    } else {
        free(out->result->data);
        out->result->data = out->data;
        out->result->size = out->used;
    }
    free(out);
    return s;
}

const char *rayo_output_name(const rayo_output *out) { return out->name; }

int rayo_output_is_terminal(const rayo_output *out)
{
    (void)out;
    return 0;
}

const char *rayo_output_temp_at(const rayo_output *out, int *dir_fd)
{
    (void)out;
    if (dir_fd != NULL)
        *dir_fd = -1;
    return NULL;
}
