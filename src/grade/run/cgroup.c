/*
 * cgroup.c - limits on the whole tree of a run's processes: a control
 * group of its own per run, bounding the tree's memory (swap included)
 * and its processes whatever they do (fork, exec, another uid in a user
 * namespace).  process.c puts the child in it before exec and asks
 * afterwards whether the kernel killed for memory; then what is left in
 * it is killed and it is removed.
 *
 * cgroup v2 where the grader's group offers the memory and pids
 * controllers, else v1, else none (or RAYO_GRADE_NO_CGROUP=1, for
 * tests: limits.c then bounds the tree by a product of per-process
 * limits).  Not a general cgroup library: two limits, one level down.
 */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "../grade_impl.h"

/* What the probe found, kept for the process's life. */
static pthread_once_t probed = PTHREAD_ONCE_INIT;
static int kind;                 /* 2, 1 or 0 */
static char base[2][4096];       /* v2: [0]; v1: [0] memory, [1] pids */
static char reason[200];
static unsigned long serial;
static pthread_mutex_t serial_lock = PTHREAD_MUTEX_INITIALIZER;

/* The mount point of the cgroup hierarchy whose super options hold
   option (v1), or of the cgroup2 one (option NULL), and its root;
   1 when found. */
static int find_mount(const char *option, char *point, char *root,
                      size_t room)
{
    FILE *f = fopen("/proc/self/mountinfo", "r");
    char line[4096];
    int found = 0;
    if (f == NULL)
        return 0;
    while (!found && fgets(line, sizeof line, f) != NULL) {
        char *fields[12], *save = NULL, *word, *dash;
        size_t n = 0;
        dash = strstr(line, " - ");
        if (dash == NULL)
            continue;
        *dash = '\0';
        for (word = strtok_r(line, " ", &save); word != NULL && n < 12;
             word = strtok_r(NULL, " ", &save))
            fields[n++] = word;
        if (n < 5)
            continue;
        {
            char *type, *source, *super, *s2 = NULL;
            type = strtok_r(dash + 3, " ", &s2);
            source = strtok_r(NULL, " ", &s2);
            super = strtok_r(NULL, " \n", &s2);
            if (type == NULL || source == NULL || super == NULL)
                continue;
            if (option == NULL) {
                if (strcmp(type, "cgroup2") != 0)
                    continue;
            } else {
                char *opt, *s3 = NULL;
                int has = 0;
                if (strcmp(type, "cgroup") != 0)
                    continue;
                for (opt = strtok_r(super, ",", &s3); opt != NULL;
                     opt = strtok_r(NULL, ",", &s3))
                    if (strcmp(opt, option) == 0)
                        has = 1;
                if (!has)
                    continue;
            }
        }
        snprintf(root, room, "%s", fields[3]);
        snprintf(point, room, "%s", fields[4]);
        found = 1;
    }
    fclose(f);
    return found;
}

/* This process's group in the hierarchy named controller ("" for v2's
   "0::" line) from /proc/self/cgroup; 1 when found. */
static int own_group(const char *controller, char *path, size_t room)
{
    FILE *f = fopen("/proc/self/cgroup", "r");
    char line[4096];
    int found = 0;
    if (f == NULL)
        return 0;
    while (!found && fgets(line, sizeof line, f) != NULL) {
        char *first = strchr(line, ':'), *second, *list, *opt, *save = NULL;
        if (first == NULL)
            continue;
        second = strchr(first + 1, ':');
        if (second == NULL)
            continue;
        *second = '\0';
        list = first + 1;
        second[1 + strcspn(second + 1, "\n")] = '\0';
        if (controller[0] == '\0') {
            if (list[0] == '\0' && strncmp(line, "0:", 2) == 0) {
                snprintf(path, room, "%s", second + 1);
                found = 1;
            }
            continue;
        }
        for (opt = strtok_r(list, ",", &save); opt != NULL;
             opt = strtok_r(NULL, ",", &save))
            if (strcmp(opt, controller) == 0) {
                snprintf(path, room, "%s", second + 1);
                found = 1;
            }
    }
    fclose(f);
    return found;
}

/* The folder of this process's group: mount point + (path - root). */
static int group_dir(const char *option, const char *controller,
                     char *dir, size_t room)
{
    char point[4096], root[4096], path[4096];
    size_t r;
    if (!find_mount(option, point, root, sizeof point) ||
        !own_group(controller, path, sizeof path))
        return 0;
    r = strcmp(root, "/") == 0 ? 0 : strlen(root);
    if (r > 0 && strncmp(path, root, r) != 0)
        return 0;
    if (snprintf(dir, room, "%s%s", point, path + r) >= (int)room)
        return 0;
    r = strlen(dir);
    while (r > 1 && dir[r - 1] == '/')
        dir[--r] = '\0';
    return 1;
}

static int write_text(const char *dir, const char *file, const char *text)
{
    char path[4200];
    int fd, ok;
    snprintf(path, sizeof path, "%s/%s", dir, file);
    fd = open(path, O_WRONLY | O_CLOEXEC);
    if (fd < 0)
        return -1;
    ok = write(fd, text, strlen(text)) == (ssize_t)strlen(text);
    close(fd);
    return ok ? 0 : -1;
}

static int read_text(const char *dir, const char *file, char *text,
                     size_t room)
{
    char path[4200];
    int fd;
    ssize_t got;
    snprintf(path, sizeof path, "%s/%s", dir, file);
    fd = open(path, O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        return -1;
    got = read(fd, text, room - 1);
    close(fd);
    if (got < 0)
        return -1;
    text[got] = '\0';
    return 0;
}

/* 1 when the space-separated list holds word. */
static int has_word(const char *list, const char *word)
{
    size_t n = strlen(word);
    const char *p = list;
    while ((p = strstr(p, word)) != NULL) {
        if ((p == list || p[-1] == ' ') &&
            (p[n] == '\0' || p[n] == ' ' || p[n] == '\n'))
            return 1;
        p += n;
    }
    return 0;
}

/* v2: the controllers enabled for the groups below dir; when the
   grader's own group holds processes (it then cannot give its children
   controllers), the grader moves into a leaf of its own first. */
static int v2_ready(const char *dir)
{
    char text[512], leaf[4200];
    if (read_text(dir, "cgroup.controllers", text, sizeof text) != 0 ||
        !has_word(text, "memory") || !has_word(text, "pids"))
        return 0;
    if (read_text(dir, "cgroup.subtree_control", text, sizeof text) == 0 &&
        has_word(text, "memory") && has_word(text, "pids"))
        return 1;
    if (write_text(dir, "cgroup.subtree_control", "+memory +pids") == 0)
        return 1;
    snprintf(leaf, sizeof leaf, "%s/rayo-grader-%ld", dir, (long)getpid());
    if (mkdir(leaf, 0755) != 0 && errno != EEXIST)
        return 0;
    if (write_text(leaf, "cgroup.procs", "0") != 0) {
        rmdir(leaf);
        return 0;
    }
    return write_text(dir, "cgroup.subtree_control", "+memory +pids") == 0;
}

/* 1 when a group can be made in dir (and removed again). */
static int can_make(const char *dir, const char *limit_file,
                    const char *value)
{
    char probe[4200];
    int ok;
    snprintf(probe, sizeof probe, "%s/rayo-probe-%ld", dir, (long)getpid());
    if (mkdir(probe, 0755) != 0 && errno != EEXIST)
        return 0;
    ok = write_text(probe, limit_file, value) == 0;
    rmdir(probe);
    return ok;
}

/* Removes the empty groups a grader that was killed left in dir
   ("rayo-PID-N" of a PID that is gone); a group still in use, or of a
   live grader, stays. */
static void remove_stale(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *entry;
    if (d == NULL)
        return;
    while ((entry = readdir(d)) != NULL) {
        char path[4200], *end;
        long pid;
        if (strncmp(entry->d_name, "rayo-", 5) != 0)
            continue;
        pid = strtol(entry->d_name + 5, &end, 10);
        if (end == entry->d_name + 5 || *end != '-' || pid <= 0 ||
            kill((pid_t)pid, 0) == 0 || errno != ESRCH)
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, entry->d_name);
        rmdir(path);
    }
    closedir(d);
}

static void probe(void)
{
    const char *off = getenv("RAYO_GRADE_NO_CGROUP");
    if (off != NULL && strcmp(off, "1") == 0) {
        snprintf(reason, sizeof reason, "cgroups turned off "
                                        "(RAYO_GRADE_NO_CGROUP=1)");
        return;
    }
    if (group_dir(NULL, "", base[0], sizeof base[0]) && v2_ready(base[0]) &&
        can_make(base[0], "memory.max", "1073741824")) {
        kind = 2;
        remove_stale(base[0]);
        return;
    }
    if (group_dir("memory", "memory", base[0], sizeof base[0]) &&
        group_dir("pids", "pids", base[1], sizeof base[1])) {
        if (can_make(base[0], "memory.limit_in_bytes", "1073741824") &&
            can_make(base[1], "pids.max", "64")) {
            kind = 1;
            remove_stale(base[0]);
            remove_stale(base[1]);
            return;
        }
        snprintf(reason, sizeof reason, "cannot make a cgroup here (not "
                                        "root, no delegation)");
        return;
    }
    snprintf(reason, sizeof reason, "no cgroup with the memory and pids "
                                    "controllers here");
}

int grade_cgroup_kind(char *why, size_t room)
{
    pthread_once(&probed, probe);
    if (kind == 0 && why != NULL && room > 0)
        snprintf(why, room, "%s", reason);
    return kind;
}

/* Makes one group below dir with a name of its own; opens its
   cgroup.procs.  0 when done. */
static int make_one(grade_cgroup *cg, int i, const char *dir,
                    unsigned long number)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/rayo-%ld-%lu", dir, (long)getpid(),
             number);
    if (mkdir(path, 0755) != 0)
        return -1;
    cg->dirs[i] = strdup(path);
    if (cg->dirs[i] == NULL) {
        rmdir(path);
        return -1;
    }
    snprintf(path, sizeof path, "%s/cgroup.procs", cg->dirs[i]);
    cg->procs[i] = open(path, O_WRONLY | O_CLOEXEC);
    return cg->procs[i] < 0 ? -1 : 0;
}

rayo_status grade_cgroup_create(grade_cgroup *cg, uint64_t memory,
                                unsigned long processes, rayo_error *err)
{
    char number[32];
    unsigned long n;
    int ok;
    memset(cg, 0, sizeof *cg);
    cg->procs[0] = cg->procs[1] = -1;
    if (grade_cgroup_kind(NULL, 0) == 0)
        return RAYO_OK;
    pthread_mutex_lock(&serial_lock);
    n = ++serial;
    pthread_mutex_unlock(&serial_lock);
    cg->version = kind;
    if (kind == 2) {
        ok = make_one(cg, 0, base[0], n) == 0;
        if (ok && memory > 0) {
            snprintf(number, sizeof number, "%llu",
                     (unsigned long long)memory);
            ok = write_text(cg->dirs[0], "memory.max", number) == 0;
            /* No swap: where there is none the file may be missing. */
            write_text(cg->dirs[0], "memory.swap.max", "0");
        }
        if (ok && processes > 0) {
            snprintf(number, sizeof number, "%lu", processes);
            ok = write_text(cg->dirs[0], "pids.max", number) == 0;
        }
    } else {
        ok = make_one(cg, 0, base[0], n) == 0 &&
             make_one(cg, 1, base[1], n) == 0;
        if (ok && memory > 0) {
            snprintf(number, sizeof number, "%llu",
                     (unsigned long long)memory);
            ok = write_text(cg->dirs[0], "memory.limit_in_bytes", number) ==
                 0;
            /* Memory and swap together, where the kernel accounts swap
               (after the memory limit: it may not be below it). */
            write_text(cg->dirs[0], "memory.memsw.limit_in_bytes", number);
        }
        if (ok && processes > 0) {
            snprintf(number, sizeof number, "%lu", processes);
            ok = write_text(cg->dirs[1], "pids.max", number) == 0;
        }
    }
    if (!ok) {
        int saved = errno;
        grade_cgroup_remove(cg);
        return rayo_error_set(err, RAYO_ERR_IO, "grade: cannot set up the "
                                                "run's cgroup: %s",
                              strerror(saved));
    }
    return RAYO_OK;
}

int grade_cgroup_enter(const grade_cgroup *cg)
{
    int i;
    for (i = 0; i < 2; i++)
        if (cg->procs[i] >= 0 && write(cg->procs[i], "0", 1) != 1)
            return -1;
    return 0;
}

/* The number after "key " in a "key value" file; 0 when absent. */
static unsigned long long keyed(const char *dir, const char *file,
                                const char *key)
{
    char text[2048];
    const char *p;
    size_t n = strlen(key);
    if (dir == NULL || read_text(dir, file, text, sizeof text) != 0)
        return 0;
    for (p = text; *p != '\0'; p += strcspn(p, "\n"), p += *p == '\n') {
        if (strncmp(p, key, n) == 0 && p[n] == ' ')
            return strtoull(p + n + 1, NULL, 10);
    }
    return 0;
}

int grade_cgroup_oom(const grade_cgroup *cg)
{
    if (cg->version == 2)
        return keyed(cg->dirs[0], "memory.events", "oom_kill") > 0;
    if (cg->version == 1)
        return keyed(cg->dirs[0], "memory.oom_control", "oom_kill") > 0;
    return 0;
}

uint64_t grade_cgroup_peak(const grade_cgroup *cg)
{
    char text[64];
    const char *file = cg->version == 2 ? "memory.peak"
                                        : "memory.max_usage_in_bytes";
    if (cg->version == 0 || cg->dirs[0] == NULL ||
        read_text(cg->dirs[0], file, text, sizeof text) != 0)
        return 0;
    return (uint64_t)strtoull(text, NULL, 10);
}

/* Kills every process listed in dir's cgroup.procs; the number seen. */
static int kill_listed(const char *dir)
{
    char path[4200], line[64];
    FILE *f;
    int seen = 0;
    snprintf(path, sizeof path, "%s/cgroup.procs", dir);
    f = fopen(path, "r");
    if (f == NULL)
        return 0;
    while (fgets(line, sizeof line, f) != NULL) {
        long pid = strtol(line, NULL, 10);
        if (pid > 1) {
            kill((pid_t)pid, SIGKILL);
            seen++;
        }
    }
    fclose(f);
    return seen;
}

void grade_cgroup_remove(grade_cgroup *cg)
{
    int i, tries;
    if (cg->version == 2 && cg->dirs[0] != NULL)
        write_text(cg->dirs[0], "cgroup.kill", "1");
    for (i = 0; i < 2; i++) {
        if (cg->procs[i] >= 0)
            close(cg->procs[i]);
        cg->procs[i] = -1;
        if (cg->dirs[i] == NULL)
            continue;
        /* A group is removed once empty; the killed take a moment. */
        for (tries = 0; tries < 500; tries++) {
            struct timespec pause = {0, 2000000};
            kill_listed(cg->dirs[i]);
            if (rmdir(cg->dirs[i]) == 0 || errno == ENOENT)
                break;
            nanosleep(&pause, NULL);
        }
        free(cg->dirs[i]);
        cg->dirs[i] = NULL;
    }
    cg->version = 0;
}
