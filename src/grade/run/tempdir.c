/*
 * tempdir.c - the grader's scratch space: a fresh private directory per
 * submission (mkdtemp, mode 0700), removed with everything in it when
 * the grading ends, and the small file helpers the steps use inside it.
 *
 * Removal does not follow symbolic links (a student's program that
 * links to /home is not a way to delete /home), works relative to open
 * directories (no PATH_MAX limit) and makes directories writable before
 * emptying them.  Files are opened without following links or blocking
 * on a FIFO, and read only when regular.  It is not a general file
 * utility.
 */
#define _XOPEN_SOURCE 700

#include <errno.h>
#include <fcntl.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../grade_impl.h"

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

char *grade_dir_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    if (slash == NULL)
        return strdup(".");
    if (slash == path)
        return strdup("/");
    return strndup(path, (size_t)(slash - path));
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

/*
 * Removal.  Every call is relative to an open directory (openat,
 * unlinkat, fdopendir), so no path is ever longer than one name and no
 * symbolic link is followed: a program that nests folders past PATH_MAX
 * or links to /home removes only what it made.  A folder deeper than
 * MAX_DEPTH below the top is moved up to the top first (renameat), so
 * the descriptors held stay few however deep it goes.
 */
#define MAX_DEPTH 16

static unsigned long moved_count;

/* Empties the directory open as fd (owned; closed here). */
static void empty_dir(int top, int fd, int depth)
{
    DIR *d;
    int progress = 1;
    fchmod(fd, S_IRWXU);
    d = fdopendir(fd);
    if (d == NULL) {
        close(fd);
        return;
    }
    while (progress) {
        struct dirent *entry;
        progress = 0;
        rewinddir(d);
        while ((entry = readdir(d)) != NULL) {
            const char *name = entry->d_name;
            int child;
            if (strcmp(name, ".") == 0 || strcmp(name, "..") == 0)
                continue;
            if (unlinkat(dirfd(d), name, 0) == 0 ||
                unlinkat(dirfd(d), name, AT_REMOVEDIR) == 0) {
                progress = 1;
                continue;
            }
            if (depth >= MAX_DEPTH) {
                char flat[64];
                snprintf(flat, sizeof flat, ".rayo-deep-%lu", moved_count++);
                if (renameat(dirfd(d), name, top, flat) == 0)
                    progress = 1;
                continue;
            }
            child = openat(dirfd(d), name,
                           O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_NONBLOCK);
            if (child < 0) {
                /* A folder without search or read permission. */
                if (fchmodat(dirfd(d), name, S_IRWXU, 0) == 0)
                    child = openat(dirfd(d), name,
                                   O_RDONLY | O_DIRECTORY | O_NOFOLLOW |
                                       O_NONBLOCK);
                if (child < 0)
                    continue;
            }
            empty_dir(top, child, depth + 1);
            if (unlinkat(dirfd(d), name, AT_REMOVEDIR) == 0)
                progress = 1;
        }
    }
    closedir(d);
}

void grade_tempdir_remove(char *path)
{
    int top, again;
    if (path == NULL)
        return;
    chmod(path, S_IRWXU);
    do {
        unsigned long before = moved_count;
        top = open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW);
        if (top < 0)
            break;
        {
            int fd = dup(top);
            if (fd >= 0)
                empty_dir(top, fd, 0);
        }
        close(top);
        /* Folders moved up to the top are emptied on the next pass. */
        again = moved_count != before;
    } while (again);
    rmdir(path);
    free(path);
}

rayo_status grade_read_fd(int fd, uint64_t limit, char **data, size_t *size,
                          int *cut, rayo_error *err)
{
    char *buffer = NULL;
    size_t length = 0, capacity = 0;
    *cut = 0;
    for (;;) {
        ssize_t got;
        if (capacity - length < 4096) {
            char *grown;
            if (capacity > limit || capacity > ((size_t)-1) / 2 - 8192) {
                char probe;
                *cut = read(fd, &probe, 1) == 1;
                break;
            }
            capacity = capacity * 2 + 8192;
            grown = realloc(buffer, capacity + 1);
            if (grown == NULL) {
                free(buffer);
                return rayo_error_set(err, RAYO_ERR_NOMEM,
                                      "grade: out of memory");
            }
            buffer = grown;
        }
        got = read(fd, buffer + length, capacity - length);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0) {
            rayo_status status = rayo_error_set(err, RAYO_ERR_IO,
                                                "grade: read: %s",
                                                strerror(errno));
            free(buffer);
            return status;
        }
        if (got == 0)
            break;
        length += (size_t)got;
    }
    if (length > limit) {
        length = (size_t)limit;
        *cut = 1;
    }
    if (buffer == NULL) {
        buffer = malloc(1);
        if (buffer == NULL)
            return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    }
    buffer[length] = '\0';
    *data = buffer;
    *size = length;
    return RAYO_OK;
}

rayo_status grade_read_file(const char *path, uint64_t limit, char **data,
                            size_t *size, rayo_error *err)
{
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK);
    struct stat st;
    int cut;
    rayo_status status;
    if (fd < 0)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", path,
                              strerror(errno));
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        return rayo_error_set(err, RAYO_ERR_IO, "%s: not a regular file",
                              path);
    }
    status = grade_read_fd(fd, limit, data, size, &cut, err);
    close(fd);
    return status;
}

rayo_status grade_write_file(const char *path, const char *text,
                             rayo_error *err)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_NONBLOCK,
                  0600);
    size_t length = strlen(text), done = 0;
    struct stat st;
    if (fd < 0)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", path,
                              strerror(errno));
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        return rayo_error_set(err, RAYO_ERR_IO, "%s: not a regular file",
                              path);
    }
    while (done < length) {
        ssize_t put = write(fd, text + done, length - done);
        if (put < 0 && errno == EINTR)
            continue;
        if (put <= 0) {
            rayo_status status = rayo_error_set(err, RAYO_ERR_IO, "%s: %s",
                                                path, strerror(errno));
            close(fd);
            return status;
        }
        done += (size_t)put;
    }
    if (close(fd) != 0)
        return rayo_error_set(err, RAYO_ERR_IO, "%s: %s", path,
                              strerror(errno));
    return RAYO_OK;
}
