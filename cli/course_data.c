/*
 * course_data.c - where the course's own reference images are on this
 * machine, for `rayo grade --reference course`.
 *
 * They are data files, not code (data/course/ in the source tree,
 * PREFIX/share/rayo/course/ once installed), looked for in this order:
 * $RAYO_DATA_DIR/course, then beside the running command
 * (DIR/../data/course for build/rayo in a work tree, DIR/../share/rayo/
 * course for PREFIX/bin/rayo).  Finding files is the command's job; the
 * library only ever gets a path.
 *
 * Image operands (compare, view, convert) name them course:ej1,
 * course:ej2, course:ej3.  A file whose name really is "course:ej1" in
 * the current directory wins (./course:ej1 always means the file), so no
 * name that worked before changes meaning.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

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

int cli_course_reference(const char *exercise, char *path, size_t room)
{
    static const char *const beside[] = {"../data/course",
                                         "../share/rayo/course"};
    char file[64], exe[4096], dir[4096 + 32];
    const char *env = getenv("RAYO_DATA_DIR");
    ssize_t n;
    size_t i;
    char *slash;
    snprintf(file, sizeof file, "referencia-catedra-%s.png", exercise);
    if (env != NULL && env[0] != '\0') {
        snprintf(dir, sizeof dir, "%s/course", env);
        if (join(path, room, dir, file) && readable(path))
            return 1;
    }
    n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0)
        return 0;
    exe[n] = '\0';
    slash = strrchr(exe, '/');
    if (slash == NULL)
        return 0;
    *slash = '\0';
    for (i = 0; i < sizeof beside / sizeof beside[0]; i++) {
        snprintf(dir, sizeof dir, "%s/%s", exe, beside[i]);
        if (join(path, room, dir, file) && readable(path))
            return 1;
    }
    return 0;
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
    if (strcmp(name, "ej1") != 0 && strcmp(name, "ej2") != 0 &&
        strcmp(name, "ej3") != 0) {
        static const char *const images[] = {"course:ej1", "course:ej2",
                                             "course:ej3"};
        const char *nearest = cli_nearest(operand, images, 3);
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
