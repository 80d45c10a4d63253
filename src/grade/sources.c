/*
 * sources.c - finding what to grade: the C files of one submission (a
 * file, or the *.c directly inside a folder) and the submission folders
 * of a class (the folders directly inside a directory), sorted by name
 * so reports come out in the same order every time.
 *
 * It only lists names; it neither reads nor compiles anything.
 */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "grade_impl.h"

void rayo_grade_paths_free(char **paths, size_t count)
{
    size_t i;
    if (paths == NULL)
        return;
    for (i = 0; i < count; i++)
        free(paths[i]);
    free(paths);
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static int is_c_file(const char *name)
{
    size_t n = strlen(name);
    return n > 2 && name[0] != '.' && strcmp(name + n - 2, ".c") == 0;
}

/* Entries of dir for which keep(path) holds, sorted. */
static rayo_status list_dir(const char *dir, int want_dirs, char ***paths,
                            size_t *count, rayo_error *err)
{
    DIR *d = opendir(dir);
    struct dirent *entry;
    char **list = NULL;
    size_t n = 0, capacity = 0;
    if (d == NULL)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", dir,
                              strerror(errno));
    while ((entry = readdir(d)) != NULL) {
        struct stat st;
        char *path;
        if (entry->d_name[0] == '.' || (!want_dirs && !is_c_file(entry->d_name)))
            continue;
        path = grade_path_join(dir, entry->d_name);
        if (path == NULL)
            goto nomem;
        if (stat(path, &st) != 0 ||
            (want_dirs ? !S_ISDIR(st.st_mode) : !S_ISREG(st.st_mode))) {
            free(path);
            continue;
        }
        if (n == capacity) {
            char **grown;
            if (capacity > ((size_t)-1) / (2 * sizeof *grown) - 8) {
                free(path);
                goto nomem;
            }
            capacity = capacity * 2 + 8;
            grown = realloc(list, capacity * sizeof *grown);
            if (grown == NULL) {
                free(path);
                goto nomem;
            }
            list = grown;
        }
        list[n++] = path;
    }
    closedir(d);
    if (n > 0)
        qsort(list, n, sizeof *list, by_name);
    *paths = list;
    *count = n;
    return RAYO_OK;
nomem:
    closedir(d);
    rayo_grade_paths_free(list, n);
    return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory", dir);
}

rayo_status rayo_grade_sources(const char *path, char ***sources,
                               size_t *count, rayo_error *err)
{
    struct stat st;
    rayo_status status;
    *sources = NULL;
    *count = 0;
    if (stat(path, &st) != 0)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", path,
                              strerror(errno));
    if (!S_ISDIR(st.st_mode)) {
        char **one = malloc(sizeof *one);
        if (one == NULL || (one[0] = strdup(path)) == NULL) {
            free(one);
            return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
        }
        *sources = one;
        *count = 1;
        return RAYO_OK;
    }
    status = list_dir(path, 0, sources, count, err);
    if (status == RAYO_OK && *count == 0)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "%s: no .c file in this folder; expected "
                              "the submission's C sources",
                              path);
    return status;
}

rayo_status rayo_grade_submissions(const char *dir, char ***folders,
                                   size_t *count, rayo_error *err)
{
    rayo_status status;
    *folders = NULL;
    *count = 0;
    status = list_dir(dir, 1, folders, count, err);
    if (status == RAYO_OK && *count == 0)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "%s: no submission folders inside; --each "
                              "expects one folder per student",
                              dir);
    return status;
}
