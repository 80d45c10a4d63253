/*
 * uid.c - a uid of its own for a grade's sandboxed runs, where the
 * grader is root and no cgroup can be made: the kernel does not count
 * root's processes against RLIMIT_NPROC (not even inside a user
 * namespace), so without it nothing would bound the tree.  Under an
 * unprivileged uid the limit binds, and the address space per process
 * times the processes bounds the tree's memory (limits.c).
 *
 * The uid has no account; the build folder is handed to it before each
 * run, and the sources' folders, which it may not be able to read, are
 * copied into the build folder for it (sandbox.c binds the copies where
 * the originals are).  Not used with a cgroup, nor without the sandbox.
 */
#define _DEFAULT_SOURCE

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../grade_impl.h"

/* The uids: GRADE_UID_FIRST + (the grader's pid, 22 bits) * 64 + a
   grade's number in this grader (6 bits), so that concurrent grades,
   of one grader (-j) or of several, do not share a uid. */
#define GRADE_UID_FIRST 0x70000000UL

/* How deep a copied folder is copied (deeper folders are copied
   empty, as places to bind on) and how many entries at most. */
#define COPY_DEPTH 8
#define COPY_ENTRIES 4096

static pthread_mutex_t serial_lock = PTHREAD_MUTEX_INITIALIZER;
static unsigned long serial;

static unsigned long pick_uid(void)
{
    unsigned long n;
    pthread_mutex_lock(&serial_lock);
    n = serial++;
    pthread_mutex_unlock(&serial_lock);
    return GRADE_UID_FIRST + (((unsigned long)getpid() & 0x3fffffUL) << 6) +
           (n & 63UL);
}

/* What a copy may still take. */
typedef struct budget {
    uint64_t bytes;
    unsigned entries;
    dev_t skip_dev; /* the build folder: copied as an empty folder */
    ino_t skip_ino;
} budget;

static void copy_file(int from_dir, int to_dir, const char *name,
                      const struct stat *st, budget *b)
{
    char buffer[65536];
    int in, out;
    ssize_t got;
    if ((uint64_t)st->st_size > b->bytes)
        return;
    in = openat(from_dir, name, O_RDONLY | O_NOFOLLOW | O_NONBLOCK |
                                    O_CLOEXEC);
    if (in < 0)
        return;
    out = openat(to_dir, name, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW |
                                   O_CLOEXEC,
                 0644);
    while (out >= 0 && (got = read(in, buffer, sizeof buffer)) > 0) {
        if ((uint64_t)got > b->bytes || write(out, buffer, (size_t)got) != got)
            break;
        b->bytes -= (uint64_t)got;
    }
    if (out >= 0)
        close(out);
    close(in);
}

/* Copies the folder open at from into the one open at to: regular
   files, symbolic links as links (they resolve inside the sandbox as
   they would have), folders to COPY_DEPTH; nothing else. */
static void copy_folder(int from, int to, int depth, budget *b)
{
    DIR *d = fdopendir(from);
    struct dirent *entry;
    if (d == NULL) {
        close(from);
        return;
    }
    while ((entry = readdir(d)) != NULL && b->entries > 0) {
        const char *name = entry->d_name;
        struct stat st;
        if (strcmp(name, ".") == 0 || strcmp(name, "..") == 0 ||
            fstatat(dirfd(d), name, &st, AT_SYMLINK_NOFOLLOW) != 0)
            continue;
        b->entries--;
        if (S_ISREG(st.st_mode))
            copy_file(dirfd(d), to, name, &st, b);
        else if (S_ISLNK(st.st_mode)) {
            char target[4096];
            ssize_t n = readlinkat(dirfd(d), name, target, sizeof target - 1);
            if (n > 0) {
                target[n] = '\0';
                symlinkat(target, to, name);
            }
        } else if (S_ISDIR(st.st_mode) && mkdirat(to, name, 0755) == 0 &&
                   depth < COPY_DEPTH &&
                   !(st.st_dev == b->skip_dev && st.st_ino == b->skip_ino)) {
            int sub_from = openat(dirfd(d), name, O_RDONLY | O_DIRECTORY |
                                                      O_NOFOLLOW | O_CLOEXEC);
            int sub_to = openat(to, name, O_RDONLY | O_DIRECTORY |
                                              O_NOFOLLOW | O_CLOEXEC);
            if (sub_from >= 0 && sub_to >= 0)
                copy_folder(sub_from, sub_to, depth + 1, b);
            else if (sub_from >= 0)
                close(sub_from);
            if (sub_to >= 0)
                close(sub_to);
        }
    }
    closedir(d);
}

char *grade_source_copy(const grade_context *ctx, size_t i)
{
    char name[48];
    size_t first;
    char *folder = grade_dir_of(ctx->absolute[i]), *other;
    if (folder == NULL)
        return NULL;
    /* One copy per folder: the first source in it names it. */
    for (first = 0; first < i; first++) {
        other = grade_dir_of(ctx->absolute[first]);
        if (other != NULL && strcmp(other, folder) == 0) {
            free(other);
            break;
        }
        free(other);
    }
    free(folder);
    snprintf(name, sizeof name, ".sources/%lu", (unsigned long)first);
    return grade_path_join(ctx->dir, name);
}

/* The sources' folders, each copied once into dir/.sources/N. */
static rayo_status copy_sources(const grade_context *ctx, rayo_error *err)
{
    char *top = grade_path_join(ctx->dir, ".sources");
    struct stat st;
    budget b;
    size_t i;
    if (top == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    if (mkdir(top, 0755) != 0) {
        rayo_status status = rayo_error_set(err, RAYO_ERR_IO, "%s: %s", top,
                                            strerror(errno));
        free(top);
        return status;
    }
    free(top);
    b.bytes = ctx->options->disk;
    b.entries = COPY_ENTRIES;
    b.skip_dev = 0;
    b.skip_ino = 0;
    if (stat(ctx->dir, &st) == 0) {
        b.skip_dev = st.st_dev;
        b.skip_ino = st.st_ino;
    }
    for (i = 0; i < ctx->source_count; i++) {
        char *copy = grade_source_copy(ctx, i);
        char *folder = grade_dir_of(ctx->absolute[i]);
        int from, to;
        if (copy == NULL || folder == NULL) {
            free(copy);
            free(folder);
            return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
        }
        if (mkdir(copy, 0755) == 0) {
            from = open(folder, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
            to = open(copy, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
            if (from >= 0 && to >= 0)
                copy_folder(from, to, 0, &b);
            else if (from >= 0)
                close(from);
            if (to >= 0)
                close(to);
        }
        free(copy);
        free(folder);
    }
    return RAYO_OK;
}

/* Hands everything in the folder open at dir to uid (links themselves,
   not what they point to). */
static void hand_over(int dir, uid_t uid, int depth)
{
    DIR *d = fdopendir(dir);
    struct dirent *entry;
    if (d == NULL) {
        close(dir);
        return;
    }
    while ((entry = readdir(d)) != NULL) {
        struct stat st;
        if (strcmp(entry->d_name, ".") == 0 ||
            strcmp(entry->d_name, "..") == 0 ||
            fstatat(dirfd(d), entry->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0)
            continue;
        if (st.st_uid != uid)
            fchownat(dirfd(d), entry->d_name, uid, (gid_t)uid,
                     AT_SYMLINK_NOFOLLOW);
        if (S_ISDIR(st.st_mode) && depth < COPY_DEPTH + 2) {
            int sub = openat(dirfd(d), entry->d_name, O_RDONLY | O_DIRECTORY |
                                                          O_NOFOLLOW |
                                                          O_CLOEXEC);
            if (sub >= 0)
                hand_over(sub, uid, depth + 1);
        }
    }
    closedir(d);
}

rayo_status grade_run_uid(grade_context *ctx, unsigned long *uid,
                          rayo_error *err)
{
    int dir;
    *uid = 0;
    if (!ctx->sandboxed || geteuid() != 0 || grade_cgroup_kind(NULL, 0) > 0)
        return RAYO_OK;
    if (ctx->run_uid == 0) {
        rayo_status status = copy_sources(ctx, err);
        if (status != RAYO_OK)
            return status;
        ctx->run_uid = pick_uid();
    }
    dir = open(ctx->dir, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (dir < 0 || fchown(dir, (uid_t)ctx->run_uid,
                          (gid_t)ctx->run_uid) != 0) {
        rayo_status status = rayo_error_set(err, RAYO_ERR_IO, "%s: %s",
                                            ctx->dir, strerror(errno));
        if (dir >= 0)
            close(dir);
        return status;
    }
    hand_over(dir, (uid_t)ctx->run_uid, 0);
    *uid = ctx->run_uid;
    return RAYO_OK;
}
