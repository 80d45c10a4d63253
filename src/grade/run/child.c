/*
 * child.c - the child of one run, between fork and exec: into the run's
 * cgroup, a session of its own, death with the grader, the captures and
 * the log's socket placed at their numbers and every other descriptor
 * closed, the working folder, the limits, and exec.
 *
 * Everything it needs was worked out before fork() (process.c), so it
 * calls only async-signal-safe functions (setsid, prctl, open, dup2,
 * fcntl, chdir, setrlimit, getrlimit, setgroups, setgid, setuid,
 * execve, _exit) and is safe to fork from a threaded program.  The limits are set on what it execs (bwrap,
 * in the sandbox) and so hold inside.  Not where a run is planned or
 * waited for: process.c and wait.c.
 */
#define _DEFAULT_SOURCE

#include <fcntl.h>
#include <grp.h>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include "spawn.h"

static void set_limit(int resource, rlim_t soft, rlim_t hard)
{
    struct rlimit limit;
    limit.rlim_cur = soft;
    limit.rlim_max = hard;
    setrlimit(resource, &limit);
}

/* fd onto number, even when it already is that number (dup2 would
   then keep FD_CLOEXEC). */
static int place(int fd, int number)
{
    if (fd == number)
        return fcntl(fd, F_SETFD, 0);
    return dup2(fd, number) < 0 ? -1 : 0;
}

/*
 * valgrind keeps the descriptors from the soft RLIMIT_NOFILE it starts
 * with upwards for itself: the program under it gets EBADF there (and
 * valgrind logs "invalid file descriptor N"), while valgrind's own
 * --log-fd=N keeps working.  The log's descriptor is placed below the
 * inherited limit (grade_log_fd) and the limit then lowered to it, last,
 * after any other limit on descriptors, keeping the hard limit the child
 * has by then (getrlimit: not on POSIX's list of async-signal-safe
 * functions, but a bare system call that takes no lock).
 */
static void keep_log_out_of_reach(int log_number)
{
    struct rlimit limit;
    if (getrlimit(RLIMIT_NOFILE, &limit) == 0 &&
        limit.rlim_cur > (rlim_t)log_number)
        set_limit(RLIMIT_NOFILE, (rlim_t)log_number, limit.rlim_max);
}

int grade_log_fd(void)
{
    struct rlimit limit;
    rlim_t highest = 1023;
    if (getrlimit(RLIMIT_NOFILE, &limit) == 0 &&
        limit.rlim_cur != RLIM_INFINITY && limit.rlim_cur <= highest)
        highest = limit.rlim_cur > 0 ? limit.rlim_cur - 1 : 0;
    /* Above the descriptors the child is given by number. */
    return highest > FD_FILE + 1 ? (int)highest : -1;
}

void grade_child(const child_plan *plan)
{
    const child_fds *fds = plan->fds;
    const grade_limits *limits = plan->limits;
    int fd, moved[6], in = -1, i;
    long k;
    /* Into the run's cgroup before anything else: all it starts is
       counted there. */
    if (grade_cgroup_enter(plan->cg) != 0)
        _exit(126);
    /* A session of its own: its own process group (killed as one), and
       no controlling terminal to push input into (TIOCSTI). */
    setsid();
#ifdef __linux__
    /* If the grader dies (killed, not cancelled), so does the program. */
    prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
    /* Out of the way of the numbers they are going to, first. */
    {
        const int sources[6] = {fds->out, fds->err, fds->log, fds->json,
                                fds->name, fds->file};
        for (i = 0; i < 6; i++) {
            moved[i] = -1;
            if (sources[i] >= 0) {
                moved[i] = fcntl(sources[i], F_DUPFD, 20);
                if (moved[i] < 0)
                    _exit(126);
            }
        }
    }
    if (fds->in >= 0 && (in = fcntl(fds->in, F_DUPFD, 20)) < 0)
        _exit(126);
    fd = in >= 0 ? in : open("/dev/null", O_RDONLY);
    if (fd < 0 || dup2(fd, 0) < 0)
        _exit(126);
    if (place(moved[0], 1) != 0 || place(moved[1], 2) != 0)
        _exit(126);
    if (moved[2] >= 0 && place(moved[2], fds->log_number) != 0)
        _exit(126);
    if (moved[3] >= 0 && place(moved[3], FD_JSON) != 0)
        _exit(126);
    if (moved[4] >= 0 && place(moved[4], FD_NAME) != 0)
        _exit(126);
    if (moved[5] >= 0 && place(moved[5], FD_FILE) != 0)
        _exit(126);
    for (k = 3; k < plan->max_fd; k++) {
        if ((moved[2] >= 0 && k == fds->log_number) ||
            (moved[3] >= 0 && k == FD_JSON) ||
            (moved[4] >= 0 && k == FD_NAME) ||
            (moved[5] >= 0 && k == FD_FILE))
            continue;
        close((int)k);
    }
    if (chdir(plan->dir) != 0)
        _exit(126);
    set_limit(RLIMIT_CORE, 0, 0);
    if (limits->cpu > 0) {
        rlim_t cpu = (rlim_t)limits->cpu;
        if ((double)cpu < limits->cpu)
            cpu++;
        set_limit(RLIMIT_CPU, cpu, cpu + 1);
    }
    if (limits->memory > 0)
        set_limit(RLIMIT_AS, (rlim_t)limits->memory,
                  (rlim_t)limits->memory);
    if (limits->file_size > 0)
        set_limit(RLIMIT_FSIZE, (rlim_t)limits->file_size,
                  (rlim_t)limits->file_size);
    if (limits->processes > 0)
        set_limit(RLIMIT_NPROC, (rlim_t)limits->processes,
                  (rlim_t)limits->processes);
    if (limits->open_files > 0)
        set_limit(RLIMIT_NOFILE, (rlim_t)limits->open_files,
                  (rlim_t)limits->open_files);
    if (moved[2] >= 0)
        keep_log_out_of_reach(fds->log_number);
    /* A uid of its own (uid.c), after the limits root may set; the
       change clears the death signal, which is set again. */
    if (plan->uid != 0) {
        if (setgroups(0, NULL) != 0 || setgid((gid_t)plan->uid) != 0 ||
            setuid((uid_t)plan->uid) != 0)
            _exit(126);
#ifdef __linux__
        prctl(PR_SET_PDEATHSIG, SIGKILL);
#endif
    }
    signal(SIGPIPE, SIG_DFL);
    signal(SIGXFSZ, SIG_DFL);
    execve(plan->program, plan->argv, plan->env);
    _exit(127);
}
