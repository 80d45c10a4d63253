/*
 * grade_staging.c - rayo's folder of copied sources (see
 * grade_staging.h).
 */
#define _POSIX_C_SOURCE 200809L

#include "grade_staging.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <unistd.h>

char *cli_path_join(const char *dir, const char *name)
{
    size_t room = strlen(dir) + strlen(name) + 2;
    char *path = malloc(room);
    if (path != NULL)
        snprintf(path, room, "%s/%s", dir, name);
    return path;
}

int cli_copy_source(const char *from, const char *folder, const char *own)
{
    char buffer[8192], *to = cli_path_join(folder, own);
    size_t total = 0;
    int in, out, ok = 1;
    if (to == NULL)
        return 0;
    in = open(from, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    out = in < 0 ? -1
                 : open(to, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW |
                                O_CLOEXEC, 0644);
    free(to);
    if (in < 0 || out < 0) {
        if (in >= 0)
            close(in);
        return 0;
    }
    for (;;) {
        ssize_t n = read(in, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            ok = n == 0;
            break;
        }
        total += (size_t)n;
        if (total > CLI_COPY_MAX) {
            errno = EFBIG;
            ok = 0;
            break;
        }
        if (write(out, buffer, (size_t)n) != n) {
            ok = 0;
            break;
        }
    }
    close(in);
    if (close(out) != 0)
        ok = 0;
    return ok;
}

void cli_remove_staging(const char *staging)
{
    DIR *top = opendir(staging);
    struct dirent *de;
    if (top == NULL)
        return;
    while ((de = readdir(top)) != NULL) {
        int fd;
        DIR *sub;
        struct dirent *file;
        if (strcmp(de->d_name, ".") == 0 || strcmp(de->d_name, "..") == 0)
            continue;
        fd = openat(dirfd(top), de->d_name,
                    O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (fd < 0) {
            unlinkat(dirfd(top), de->d_name, 0);
            continue;
        }
        sub = fdopendir(fd);
        if (sub == NULL) {
            close(fd);
            continue;
        }
        while ((file = readdir(sub)) != NULL)
            if (strcmp(file->d_name, ".") != 0 &&
                strcmp(file->d_name, "..") != 0)
                unlinkat(fd, file->d_name, 0);
        closedir(sub);
        unlinkat(dirfd(top), de->d_name, AT_REMOVEDIR);
    }
    closedir(top);
    rmdir(staging);
}
