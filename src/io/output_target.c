/*
 * output_target.c - following an output path to what it names, and the
 * checks before replacing it (output_target.h).
 *
 * The path is walked here, not by realpath(3), so that each symbolic
 * link is judged where it lies: the kernel's protected_symlinks rule
 * (fs.protected_symlinks = 1) is applied whatever the kernel's own
 * setting, because rayo does not open the link's target, where the
 * kernel would apply it, but renames a new file over it.  The walk
 * ends with a descriptor of the final directory, which output.c keeps.
 */
#define _GNU_SOURCE /* O_PATH */

#include "output_target.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* Symbolic links followed, at most (Linux's own limit). */
#define TARGET_MAX_LINKS 40
/* A directory opened only to name files in it: search permission is
 * enough for O_PATH, where the system has it. */
#ifdef O_PATH
#define TARGET_DIR_FLAGS (O_PATH | O_DIRECTORY | O_CLOEXEC)
#else
#define TARGET_DIR_FLAGS (O_RDONLY | O_DIRECTORY | O_CLOEXEC)
#endif

/*
 * Splits path into its directory, opened as *dir_fd (relative to
 * `from`; the previous *dir_fd closed), and its last name, copied into
 * *name ("." when path ends in a slash, so that a directory is found to
 * be one).  0 or an errno value.
 */
static int open_parent(int from, const char *path, int *dir_fd, char **name)
{
    const char *slash = strrchr(path, '/');
    const char *base = slash != NULL ? slash + 1 : path;
    int fd;
    if (slash == NULL) {
        fd = openat(from, ".", TARGET_DIR_FLAGS);
    } else if (slash == path) {
        fd = open("/", TARGET_DIR_FLAGS);
    } else {
        char *dir = strndup(path, (size_t)(slash - path));
        if (dir == NULL)
            return ENOMEM;
        fd = openat(from, dir, TARGET_DIR_FLAGS);
        free(dir);
    }
    if (fd < 0)
        return errno;
    free(*name);
    *name = strdup(*base != '\0' ? base : ".");
    if (*name == NULL) {
        close(fd);
        return ENOMEM;
    }
    if (*dir_fd >= 0)
        close(*dir_fd);
    *dir_fd = fd;
    return 0;
}

/*
 * The protected_symlinks rule: a link in a sticky, world-writable
 * directory is followed only by its owner, or when the directory's
 * owner owns it too.  Otherwise anyone could plant, in /tmp, a link
 * that leads whoever writes there to a file of theirs.  1 when the link
 * may be followed.
 */
static int may_follow(int dir_fd, const struct stat *link)
{
    struct stat dir;
    if (fstat(dir_fd, &dir) != 0)
        return 0;
    if ((dir.st_mode & (S_ISVTX | S_IWOTH)) != (S_ISVTX | S_IWOTH))
        return 1;
    return link->st_uid == geteuid() || link->st_uid == dir.st_uid;
}

int rayo_output_target_find(rayo_output_target *t, const char *path)
{
    int code, links = 0;
    t->dir_fd = -1;
    t->name = NULL;
    t->exists = 0;
    t->refused_link = 0;
    code = open_parent(AT_FDCWD, path, &t->dir_fd, &t->name);
    while (code == 0) {
        char link[PATH_MAX];
        ssize_t length;
        if (fstatat(t->dir_fd, t->name, &t->st, AT_SYMLINK_NOFOLLOW) != 0)
            return errno == ENOENT ? 0 : errno;
        if (!S_ISLNK(t->st.st_mode)) {
            t->exists = 1;
            return 0;
        }
        if (++links > TARGET_MAX_LINKS)
            return ELOOP;
        if (!may_follow(t->dir_fd, &t->st)) {
            t->refused_link = 1;
            return EACCES;
        }
        if (fstatat(t->dir_fd, t->name, &t->st, 0) == 0 &&
            !S_ISREG(t->st.st_mode) && !S_ISDIR(t->st.st_mode)) {
            t->exists = 1; /* a device, pipe or socket behind the link */
            return 0;
        }
        length = readlinkat(t->dir_fd, t->name, link, sizeof link);
        if (length < 0)
            return errno;
        if ((size_t)length >= sizeof link)
            return ENAMETOOLONG;
        if (length == 0)
            return ENOENT;
        link[length] = '\0';
        code = open_parent(t->dir_fd, link, &t->dir_fd, &t->name);
    }
    return code;
}

int rayo_output_target_replaceable(const rayo_output_target *t)
{
    struct stat dir;
    if (faccessat(t->dir_fd, t->name, W_OK, AT_EACCESS) != 0)
        return errno;
    if (geteuid() != 0 && fstat(t->dir_fd, &dir) == 0 &&
        (dir.st_mode & S_ISVTX) && t->st.st_uid != geteuid() &&
        dir.st_uid != geteuid())
        return EPERM;
    return 0;
}

void rayo_output_target_free(rayo_output_target *t)
{
    if (t->dir_fd >= 0)
        close(t->dir_fd);
    t->dir_fd = -1;
    free(t->name);
    t->name = NULL;
}
