/*
 * course_data.c - where the course's own reference images are on this
 * machine, for `rayo grade --reference course` and the image operands
 * course:NAME (compare, view, convert), one for each exercise of the
 * course's registry (rayo/course/course.h), whose entry names the file.
 *
 * Looked for in $RAYO_DATA_DIR/course, then beside the running command
 * (../data/course, ../share/rayo/course), and last the copy built into
 * the library, handed on as a file only this process sees.  A file
 * really named "course:ej1" in the current directory wins, so no name
 * that worked before changes meaning.  cli_course_picture tells whether
 * an image read from elsewhere is one of them (compare's kinds note).
 */
#define _GNU_SOURCE /* memfd_create */

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"
#include "rayo/course.h"

static int readable(const char *path)
{
    return access(path, R_OK) == 0;
}

/* dir + "/" + file into out; 0 when it does not fit. */
static int join(char *out, size_t room, const char *dir, const char *file)
{
    int n = snprintf(out, room, "%s/%s", dir, file);
    return n > 0 && (size_t)n < room;
}

/*
 * The library's built-in copy of the exercise's reference as a path: an
 * anonymous in-memory file (closed on exec, so no program rayo runs sees
 * it), written once per exercise and kept open until rayo exits; readers
 * open it again through /proc/self/fd.  0 when there is none or the
 * system refuses.
 */
static int built_in(const char *exercise, const char *file, char *path,
                    size_t room)
{
    static int fds[RAYO_COURSE_EXERCISES]; /* the descriptor + 1 */
    rayo_course_exercise e = rayo_course_find(exercise);
    const unsigned char *data;
    size_t size, done = 0;
    int n;
    if (e >= RAYO_COURSE_EXERCISES)
        return 0;
    data = rayo_course_reference_png(e, &size);
    if (data == NULL)
        return 0;
    if (fds[e] == 0) {
        int fd = memfd_create(file, MFD_CLOEXEC);
        if (fd < 0)
            return 0;
        while (done < size) {
            ssize_t w = write(fd, data + done, size - done);
            if (w < 0 && errno == EINTR)
                continue;
            if (w <= 0) {
                close(fd);
                return 0;
            }
            done += (size_t)w;
        }
        fds[e] = fd + 1;
    }
    n = snprintf(path, room, "/proc/self/fd/%d", fds[e] - 1);
    return n > 0 && (size_t)n < room && readable(path);
}

int cli_course_reference(const char *exercise, char *path, size_t room)
{
    static const char *const beside[] = {"../data/course",
                                         "../share/rayo/course"};
    const rayo_course_info *info =
        rayo_course_info_of(rayo_course_find(exercise));
    char exe[4096], dir[4096 + 32];
    const char *env = getenv("RAYO_DATA_DIR"), *file;
    ssize_t n;
    size_t i;
    char *slash;
    if (info == NULL)
        return 0;
    file = info->reference;
    if (env != NULL && env[0] != '\0') {
        snprintf(dir, sizeof dir, "%s/course", env);
        if (join(path, room, dir, file) && readable(path))
            return 1;
    }
    n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    slash = NULL;
    if (n > 0) {
        exe[n] = '\0';
        slash = strrchr(exe, '/');
    }
    if (slash != NULL) {
        *slash = '\0';
        for (i = 0; i < sizeof beside / sizeof beside[0]; i++) {
            snprintf(dir, sizeof dir, "%s/%s", exe, beside[i]);
            if (join(path, room, dir, file) && readable(path))
                return 1;
        }
    }
    return built_in(exercise, file, path, room);
}

int cli_image_operand(const char *operand, char *path, size_t room,
                      const char **resolved)
{
    static const char prefix[] = "course:";
    const char *name = operand + sizeof prefix - 1;
    struct stat st;
    *resolved = operand;
    if (strncmp(operand, prefix, sizeof prefix - 1) != 0 ||
        lstat(operand, &st) == 0)
        return CLI_EXIT_OK;
    if (rayo_course_find(name) == RAYO_COURSE_EXERCISES) {
        char images[RAYO_COURSE_EXERCISES][40];
        const char *list[RAYO_COURSE_EXERCISES];
        const char *nearest;
        unsigned i;
        for (i = 0; i < RAYO_COURSE_EXERCISES; i++) {
            snprintf(images[i], sizeof images[i], "%s%s", prefix,
                     rayo_course_name((rayo_course_exercise)i));
            list[i] = images[i];
        }
        nearest = cli_nearest(operand, list, RAYO_COURSE_EXERCISES);
        if (nearest != NULL)
            return cli_usage_error(_("%s: no such course image; did you "
                                     "mean %s? The course's images are "
                                     "course:ej1, course:ej2 and "
                                     "course:ej3"),
                                   operand, nearest);
        return cli_usage_error(_("%s: no such course image; expected "
                                 "course:ej1, course:ej2 or course:ej3"),
                               operand);
    }
    if (!cli_course_reference(name, path, room))
        return cli_usage_error(_("%s: the course's image "
                                 "(referencia-catedra-%s.png) is not "
                                 "installed; looked in $RAYO_DATA_DIR/course "
                                 "and beside the command (../data/course, "
                                 "../share/rayo/course)"),
                               operand, name);
    *resolved = path;
    return CLI_EXIT_OK;
}

rayo_course_exercise cli_course_picture(const rayo_image *image)
{
    rayo_course_exercise e =
        rayo_picture_kind_exercise(rayo_picture_kind_of(image));
    const rayo_course_info *info = rayo_course_info_of(e);
    char path[4096];
    rayo_image course;
    rayo_error err = RAYO_ERROR_INIT(cli_lang());
    int same;
    /* Only a picture of the exercise's size is read against its image. */
    if (info == NULL || image->info.width != info->width ||
        image->info.height != info->height ||
        !cli_course_reference(info->name, path, sizeof path))
        return RAYO_COURSE_EXERCISES;
    memset(&course, 0, sizeof course);
    rayo_error_clear(&err);
    if (rayo_image_read_file(path, &course, NULL, &err) != RAYO_OK)
        return RAYO_COURSE_EXERCISES;
    same = rayo_image_same_picture(image, &course);
    rayo_image_free(&course);
    return same ? e : RAYO_COURSE_EXERCISES;
}
