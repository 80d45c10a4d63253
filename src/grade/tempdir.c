/*
 * tempdir.c - the grader's scratch space: a fresh private directory per
 * submission (mkdtemp, mode 0700), removed with everything in it when
 * the grading ends, and the small file helpers the steps use inside it.
 *
 * Removal does not follow symbolic links (a student's program that
 * links to /home is not a way to delete /home) and makes directories
 * writable before emptying them.  It is not a general file utility.
 */
#define _XOPEN_SOURCE 700

#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "grade_impl.h"

char *grade_path_join(const char *dir, const char *name)
{
    size_t a = strlen(dir), b = strlen(name);
    char *path;
    if (a > ((size_t)-1) - b - 2)
        return NULL;
    path = malloc(a + b + 2);
    if (path == NULL)
        return NULL;
    memcpy(path, dir, a);
    path[a] = '/';
    memcpy(path + a + 1, name, b + 1);
    return path;
}

char *grade_concat(const char *a, const char *b)
{
    size_t m = strlen(a), n = strlen(b);
    char *joined;
    if (m > ((size_t)-1) - n - 1)
        return NULL;
    joined = malloc(m + n + 1);
    if (joined == NULL)
        return NULL;
    memcpy(joined, a, m);
    memcpy(joined + m, b, n + 1);
    return joined;
}

rayo_status grade_tempdir_create(char **path, rayo_error *err)
{
    const char *base = getenv("TMPDIR");
    char *templ;
    if (base == NULL || base[0] != '/')
        base = "/tmp";
    templ = grade_path_join(base, "rayo-grade.XXXXXX");
    if (templ == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    if (mkdtemp(templ) == NULL) {
        rayo_status status = rayo_error_set(
            err, RAYO_ERR_IO, "grade: cannot create a temporary directory "
                              "in %s: %s", base, strerror(errno));
        free(templ);
        return status;
    }
    *path = templ;
    return RAYO_OK;
}

static int remove_entry(const char *path, const struct stat *st, int type,
                        struct FTW *where)
{
    (void)st;
    (void)where;
    if (type == FTW_DP || type == FTW_D)
        rmdir(path);
    else
        unlink(path);
    return 0;
}

/* A student may leave directories without write or search permission. */
static int open_up(const char *path, const struct stat *st, int type,
                   struct FTW *where)
{
    (void)where;
    if (type == FTW_D || type == FTW_DNR)
        chmod(path, (st->st_mode & 07777) | S_IRWXU);
    return 0;
}

void grade_tempdir_remove(char *path)
{
    if (path == NULL)
        return;
    chmod(path, S_IRWXU);
    nftw(path, open_up, 16, FTW_PHYS);
    nftw(path, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
    free(path);
}

rayo_status grade_read_file(const char *path, uint64_t limit, char **data,
                            size_t *size, rayo_error *err)
{
    FILE *file = fopen(path, "rb");
    char *buffer = NULL;
    size_t length = 0, capacity = 0;
    if (file == NULL)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", path,
                              strerror(errno));
    for (;;) {
        size_t got;
        if (capacity - length < 4096) {
            char *grown;
            if (capacity > limit || capacity > ((size_t)-1) / 2 - 8192)
                break;
            capacity = capacity * 2 + 8192;
            grown = realloc(buffer, capacity + 1);
            if (grown == NULL) {
                free(buffer);
                fclose(file);
                return rayo_error_set(err, RAYO_ERR_NOMEM,
                                      "%s: out of memory", path);
            }
            buffer = grown;
        }
        got = fread(buffer + length, 1, capacity - length, file);
        length += got;
        if (got == 0)
            break;
    }
    if (ferror(file)) {
        rayo_status status = rayo_error_set(err, RAYO_ERR_IO, "%s: %s",
                                            path, strerror(errno));
        free(buffer);
        fclose(file);
        return status;
    }
    fclose(file);
    if (buffer == NULL) {
        buffer = malloc(1);
        if (buffer == NULL)
            return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                                  path);
    }
    buffer[length] = '\0';
    *data = buffer;
    *size = length;
    return RAYO_OK;
}

rayo_status grade_write_file(const char *path, const char *text,
                             rayo_error *err)
{
    FILE *file = fopen(path, "w");
    size_t length = strlen(text);
    if (file == NULL)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", path,
                              strerror(errno));
    if (fwrite(text, 1, length, file) != length) {
        fclose(file);
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", path,
                              strerror(errno));
    }
    if (fclose(file) != 0)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", path,
                              strerror(errno));
    return RAYO_OK;
}
