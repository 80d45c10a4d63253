/*
 * t_output.c - rayo_output gets every byte to its destination in order,
 * whatever mix of small writes, large writes, in-place formatting
 * (rayo_output_reserve/advance) and bytes by reference
 * (rayo_output_refer) it is given, into a regular file (its large
 * buffer) and into a pipe (its pipe-sized one); and it reports what goes
 * wrong: no room on the device, a closed pipe, a reservation larger than
 * the buffer, a commit after bytes were lost or an image abandoned.  It
 * also tells a terminal from the rest (rayo_output_is_terminal), on a
 * pseudo-terminal of its own.  And it respects what it replaces: a
 * directory renamed mid-way still gets the file, or loses the temporary
 * file; a replaced file keeps its mode (and, for root, its owner); a
 * file the user may not write is refused (as user nobody, in a child,
 * when the test runs as root); links are followed only as the kernel's
 * protected_symlinks rule would.
 *
 * The expected stream is generated here from a seeded sequence and the
 * destination read back with plain read(2).
 */
#define _XOPEN_SOURCE 700 /* posix_openpt, grantpt, unlockpt, ptsname */
#define _DEFAULT_SOURCE   /* setgroups */

#include <dirent.h>
#include <errno.h>
#include <grp.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "../../src/formats/writer_impl.h"
#include "../../src/formats/writer_runs.h"
#include "../../src/io/output_reserve.h"
#include "rayo.h"
#include "tap.h"

/* Byte i of the stream. */
static unsigned char stream_byte(size_t i)
{
    return (unsigned char)((i * 2654435761u) >> 13);
}

/* Sizes of the first pieces, around every buffer and threshold the
 * output has (64 KiB, 1 MiB) and a plain PBM row of the seed (651 bytes). */
static const size_t piece_sizes[] = {
    0,      1,           651,         7,           65535,   65536,
    65537,  3,           200000,      1048575,     1048576, 1048577,
    651,    64 * 1024,   2,           1024 * 1024 - 651,     5,
    8192,   1,           4096};
#define LARGE_PIECES (sizeof piece_sizes / sizeof piece_sizes[0])
/* Then small pieces, two references out of three: more references than
 * the output holds between two writes, some of them back to back. */
#define SMALL_PIECES 300
#define PIECES (LARGE_PIECES + SMALL_PIECES)

static size_t piece_size(size_t i)
{
    return i < LARGE_PIECES ? piece_sizes[i]
                            : 1 + (i * 7) % 13 + (i % 5 == 0 ? 700 : 0);
}

/* How piece i reaches the output. */
typedef enum piece_kind { IN_PLACE, COPIED, REFERRED } piece_kind;

static piece_kind piece_kind_of(size_t i)
{
    if (i < LARGE_PIECES)
        return (piece_kind)(i % 3);
    return i % 3 == 0 ? IN_PLACE : REFERRED;
}

static size_t stream_length(void)
{
    size_t i, n = 0;
    for (i = 0; i < PIECES; i++)
        n += piece_size(i);
    return n;
}

/* The whole stream, where references point: it never changes. */
static const unsigned char *whole_stream(void)
{
    static unsigned char *bytes;
    if (bytes == NULL) {
        size_t i, n = stream_length();
        bytes = malloc(n);
        if (bytes == NULL)
            abort();
        for (i = 0; i < n; i++)
            bytes[i] = stream_byte(i);
    }
    return bytes;
}

/*
 * Writes the stream into out: pieces through rayo_output_write, formatted
 * in place when the buffer has room for them, and by reference
 * (rayo_output_refer).  Returns the status of the first failure;
 * *in_place counts pieces placed.
 */
static rayo_status write_stream(rayo_output *out, int *in_place,
                                rayo_error *err)
{
    static unsigned char piece[1024 * 1024 + 1];
    size_t i, at = 0, j;
    *in_place = 0;
    for (i = 0; i < PIECES; i++) {
        size_t n = piece_size(i);
        piece_kind kind = piece_kind_of(i);
        rayo_status status;
        unsigned char *room = NULL;
        size_t available = 0;
        if (kind == REFERRED) {
            status = rayo_output_refer(out, whole_stream() + at, n, err);
            if (status != RAYO_OK)
                return status;
            at += n;
            continue;
        }
        if (kind == IN_PLACE) {
            status = rayo_output_reserve(out, n, &room, &available, err);
            if (status != RAYO_OK)
                return status;
            if (room != NULL && available < n)
                return RAYO_ERR_INVALID; /* less room than asked for */
        }
        if (room != NULL) {
            for (j = 0; j < n; j++)
                room[j] = stream_byte(at + j);
            rayo_output_advance(out, n);
            (*in_place)++;
        } else {
            for (j = 0; j < n; j++)
                piece[j] = stream_byte(at + j);
            status = rayo_output_write(out, piece, n, err);
            if (status != RAYO_OK)
                return status;
        }
        at += n;
    }
    return RAYO_OK;
}

/* The stream into out, then commit (or abort on a failure, which is
 * returned); out is gone either way. */
static rayo_status write_stream_and_commit(rayo_output *out, int *in_place,
                                           rayo_error *err)
{
    rayo_status status = write_stream(out, in_place, err);
    if (status != RAYO_OK) {
        rayo_output_abort(out);
        return status;
    }
    return rayo_output_commit(out, err);
}

/* The number of bytes of fd that differ from the stream, or -1 when the
 * length differs. */
static long stream_mismatches(int fd, size_t length)
{
    unsigned char chunk[65536];
    size_t at = 0;
    long bad = 0;
    for (;;) {
        ssize_t n = read(fd, chunk, sizeof chunk), j;
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        for (j = 0; j < n; j++)
            if (at + (size_t)j >= length ||
                chunk[j] != stream_byte(at + (size_t)j))
                bad++;
        at += (size_t)n;
    }
    return at == length ? bad : -1;
}

typedef struct pipe_reader {
    int fd;
    size_t length;
    long mismatches;
} pipe_reader;

static void *read_pipe(void *argument)
{
    pipe_reader *reader = argument;
    reader->mismatches = stream_mismatches(reader->fd, reader->length);
    return NULL;
}

/* For test_interrupted_pipe: counts interruptions. */
static volatile sig_atomic_t alarms;

static void count_alarm(int signal_number)
{
    (void)signal_number;
    alarms++;
}

/* A reader that takes a while: the writer blocks in the middle of its
 * writes, where a signal cuts them short. */
static void *read_pipe_slowly(void *argument)
{
    pipe_reader *reader = argument;
    unsigned char chunk[16384];
    size_t at = 0;
    long bad = 0;
    sigset_t blocked;
    sigemptyset(&blocked);
    sigaddset(&blocked, SIGALRM);
    pthread_sigmask(SIG_BLOCK, &blocked, NULL);
    for (;;) {
        struct timespec pause = {0, 100000};
        ssize_t n = read(reader->fd, chunk, sizeof chunk), j;
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        for (j = 0; j < n; j++)
            if (at + (size_t)j >= reader->length ||
                chunk[j] != stream_byte(at + (size_t)j))
                bad++;
        at += (size_t)n;
        nanosleep(&pause, NULL);
    }
    reader->mismatches = at == reader->length ? bad : -1;
    return NULL;
}

static void test_file(void)
{
    char path[] = "/tmp/rayo-t-output.XXXXXX";
    int fd = mkstemp(path), in_place = 0;
    rayo_output *out;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    if (fd < 0) {
        ok(0, "a temporary file");
        return;
    }
    close(fd);
    status = rayo_output_open(&out, path, &err);
    if (status == RAYO_OK)
        status = write_stream_and_commit(out, &in_place, &err);
    is_int(status, RAYO_OK, "file: every piece written and committed");
    ok(in_place >= 6, "file: pieces formatted in place (%d)", in_place);
    fd = open(path, O_RDONLY);
    is_int(stream_mismatches(fd, stream_length()), 0,
           "file: %lu bytes, all in order", (unsigned long)stream_length());
    close(fd);
    unlink(path);
}

static void test_pipe(void)
{
    int fds[2], in_place = 0;
    pipe_reader reader;
    pthread_t thread;
    rayo_output *out;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    unsigned char *room;
    size_t available;
    if (pipe(fds) != 0) {
        ok(0, "a pipe");
        return;
    }
    reader.fd = fds[0];
    reader.length = stream_length();
    if (pthread_create(&thread, NULL, read_pipe, &reader) != 0) {
        ok(0, "a reading thread");
        return;
    }
    status = rayo_output_open_fd(&out, fds[1], "pipe", &err);
    if (status == RAYO_OK) {
        /* A pipe's buffer holds 64 KiB: no more can be reserved. */
        status = rayo_output_reserve(out, 64 * 1024 + 1, &room, &available,
                                     &err);
        ok(status == RAYO_OK && room == NULL && available == 0,
           "pipe: a reservation larger than the buffer gives no room");
        status = rayo_output_reserve(out, 100, &room, &available, &err);
        ok(status == RAYO_OK && room != NULL && available == 64 * 1024,
           "pipe: an empty buffer offers all its 64 KiB");
        status = write_stream_and_commit(out, &in_place, &err);
    }
    close(fds[1]);
    pthread_join(thread, NULL);
    close(fds[0]);
    is_int(status, RAYO_OK, "pipe: every piece written and committed");
    ok(in_place >= 4, "pipe: pieces formatted in place (%d)", in_place);
    is_int(reader.mismatches, 0, "pipe: %lu bytes, all in order",
           (unsigned long)reader.length);
}

/*
 * Writes cut short: a signal (without SA_RESTART) arriving while a write
 * or writev is blocked on a full pipe ends it early with what it wrote,
 * and the output goes on from the first byte not written, in the middle
 * of a reference or of the buffer.
 */
static void test_interrupted_pipe(void)
{
    int fds[2], in_place = 0;
    pipe_reader reader;
    pthread_t thread;
    rayo_output *out;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status = RAYO_ERR_IO;
    struct sigaction action, previous;
    struct itimerval every = {{0, 300}, {0, 300}}, off = {{0, 0}, {0, 0}};
    memset(&action, 0, sizeof action);
    action.sa_handler = count_alarm; /* no SA_RESTART */
    sigemptyset(&action.sa_mask);
    if (pipe(fds) != 0 || sigaction(SIGALRM, &action, &previous) != 0) {
        ok(0, "a pipe and a signal handler");
        return;
    }
    reader.fd = fds[0];
    reader.length = stream_length();
    alarms = 0;
    if (pthread_create(&thread, NULL, read_pipe_slowly, &reader) != 0) {
        ok(0, "a reading thread");
        return;
    }
    setitimer(ITIMER_REAL, &every, NULL);
    if (rayo_output_open_fd(&out, fds[1], "pipe", &err) == RAYO_OK)
        status = write_stream_and_commit(out, &in_place, &err);
    setitimer(ITIMER_REAL, &off, NULL);
    sigaction(SIGALRM, &previous, NULL);
    close(fds[1]);
    pthread_join(thread, NULL);
    close(fds[0]);
    is_int(status, RAYO_OK, "interrupted pipe: every piece written");
    ok(alarms > 10, "interrupted pipe: writes were interrupted (%d signals)",
       (int)alarms);
    is_int(reader.mismatches, 0, "interrupted pipe: %lu bytes, all in order",
           (unsigned long)reader.length);
}

static void test_full_device(void)
{
    int fd = open("/dev/full", O_WRONLY), in_place;
    rayo_output *out;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    if (fd < 0) {
        ok(1, "# SKIP no /dev/full");
        return;
    }
    status = rayo_output_open_fd(&out, fd, "/dev/full", &err);
    if (status == RAYO_OK)
        status = write_stream_and_commit(out, &in_place, &err);
    close(fd);
    is_int(status, RAYO_ERR_IO, "/dev/full: an I/O error");
    ok(strstr(err.message, "/dev/full") != NULL &&
           strstr(err.message, strerror(ENOSPC)) != NULL,
       "/dev/full: the message names the file and the reason");
    printf("# %s\n", err.message);
}

/* Once a write has failed, bytes are lost: the commit fails too, even
 * with nothing pending any more. */
static void test_lost_bytes(void)
{
    int fd = open("/dev/full", O_WRONLY);
    rayo_output *out;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    if (fd < 0) {
        ok(1, "# SKIP no /dev/full");
        ok(1, "# SKIP no /dev/full");
        return;
    }
    status = rayo_output_open_fd(&out, fd, "/dev/full", &err);
    if (status == RAYO_OK)
        status = rayo_output_refer(out, "P1\n", 3, &err);
    if (status == RAYO_OK)
        status = rayo_output_release(out, &err);
    is_int(status, RAYO_ERR_IO, "/dev/full: releasing references fails");
    if (status != RAYO_ERR_IO) {
        ok(0, "no output to commit");
    } else {
        status = rayo_output_commit(out, &err);
        ok(status == RAYO_ERR_IO &&
               strstr(err.message, strerror(ENOSPC)) != NULL,
           "and the commit after it fails with the write's reason");
    }
    close(fd);
}

/* A writer discarded mid-image (after an error) leaves its output
 * uncommittable, whatever it left pending (plain PBM's white rows by
 * reference among it): the file never appears. */
static void test_abandoned_image(void)
{
    static const rayo_write_options kinds[] = {{RAYO_FORMAT_PBM, 1, 0},
                                               {RAYO_FORMAT_PBM, 1, 0},
                                               {RAYO_FORMAT_PBM, 0, 0},
                                               {RAYO_FORMAT_PNG, 0, 0}};
    static const char *const names[] = {"plain PBM", "plain PBM by reference",
                                        "raw PBM", "PNG"};
    static unsigned char rows[300 * 8];
    static rayo_row_runs white[300]; /* no runs: all white */
    rayo_image_info info = rayo_image_info_bit(64, 400);
    size_t k;
    for (k = 0; k < 4; k++) {
        char path[] = "/tmp/rayo-t-output-abandoned.XXXXXX";
        int fd = mkstemp(path);
        rayo_output *out;
        rayo_writer *writer;
        rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
        rayo_status status = RAYO_ERR_IO;
        if (fd >= 0) {
            close(fd);
            unlink(path);
        }
        if (fd >= 0 && rayo_output_open(&out, path, &err) == RAYO_OK) {
            if (rayo_writer_open(&writer, out, &info, &kinds[k], &err) ==
                RAYO_OK) {
                status = k == 1 ? rayo_writer_write_runs(writer, rows, 8,
                                                         white, 300, &err)
                                : rayo_writer_write_rows(writer, rows, 8, 300,
                                                         &err);
                if (k == 1 && writer->rows_referred < 200)
                    status = RAYO_ERR_IO; /* the references were not taken */
                rayo_writer_discard(writer);
            }
            if (status == RAYO_OK)
                status = rayo_output_commit(out, &err);
            else
                rayo_output_abort(out);
        }
        ok(status == RAYO_ERR_INVALID &&
               strstr(err.message, "abandoned") != NULL,
           "%s: after a discarded writer the commit fails", names[k]);
        ok(access(path, F_OK) != 0 && errno == ENOENT,
           "%s: and no file appears", names[k]);
    }
}

static void test_closed_pipe(void)
{
    int fds[2], in_place;
    rayo_output *out;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    if (pipe(fds) != 0) {
        ok(0, "a pipe");
        return;
    }
    close(fds[0]);
    status = rayo_output_open_fd(&out, fds[1], "pipe", &err);
    if (status == RAYO_OK)
        status = write_stream_and_commit(out, &in_place, &err);
    close(fds[1]);
    is_int(status, RAYO_ERR_PIPE, "closed pipe: RAYO_ERR_PIPE");
}

/* A terminal, and only a terminal, is one: a pseudo-terminal's device,
 * opened by its path as `-o /dev/pts/N` would; a file and /dev/null are
 * not. */
static void test_is_terminal(void)
{
    char path[] = "/tmp/rayo-t-output.XXXXXX";
    int fd = mkstemp(path), master = posix_openpt(O_RDWR | O_NOCTTY);
    const char *device = master < 0 || grantpt(master) != 0 ||
                                 unlockpt(master) != 0
                             ? NULL
                             : ptsname(master);
    rayo_output *out;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    int opened;
    if (fd >= 0)
        close(fd);
    opened = fd >= 0 && rayo_output_open(&out, path, &err) == RAYO_OK;
    ok(opened && !rayo_output_is_terminal(out),
       "a regular file is not a terminal");
    if (opened)
        rayo_output_abort(out);
    unlink(path);
    opened = rayo_output_open(&out, "/dev/null", &err) == RAYO_OK;
    ok(opened && !rayo_output_is_terminal(out), "/dev/null is not a terminal");
    if (opened)
        rayo_output_abort(out);
    if (device == NULL) {
        ok(1, "# SKIP no pseudo-terminal");
    } else {
        opened = rayo_output_open(&out, device, &err) == RAYO_OK;
        ok(opened && rayo_output_is_terminal(out),
           "a pseudo-terminal (%s) is a terminal", device);
        if (opened)
            rayo_output_abort(out);
    }
    if (master >= 0)
        close(master);
}

/* --- replacing a file: its directory, its mode, owner and links ---- */

/* A fresh directory under /tmp with the given mode, path into dir. */
static int make_dir(char *dir, size_t size, mode_t mode)
{
    snprintf(dir, size, "/tmp/rayo-t-output-dir.XXXXXX");
    return mkdtemp(dir) != NULL && chmod(dir, mode) == 0;
}

static void put_file(const char *path, const char *text, mode_t mode)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd >= 0) {
        if (write(fd, text, strlen(text)) < 0)
            abort();
        fchmod(fd, mode);
        close(fd);
    }
}

/* The file's first bytes as a string ("" when it cannot be read). */
static const char *file_text(const char *path)
{
    static char text[64];
    int fd = open(path, O_RDONLY);
    ssize_t n = fd >= 0 ? read(fd, text, sizeof text - 1) : -1;
    text[n > 0 ? n : 0] = '\0';
    if (fd >= 0)
        close(fd);
    return text;
}

/* Entries of dir other than . and .. */
static int entries(const char *dir)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    if (d == NULL)
        return -1;
    while ((e = readdir(d)) != NULL)
        n += strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0;
    closedir(d);
    return n;
}

/* Opens path, writes text and commits: the status, err's message. */
static rayo_status replace_with(const char *path, const char *text,
                                rayo_error *err)
{
    rayo_output *out;
    rayo_status status = rayo_output_open(&out, path, err);
    if (status != RAYO_OK)
        return status;
    status = rayo_output_write(out, text, strlen(text), err);
    if (status != RAYO_OK) {
        rayo_output_abort(out);
        return status;
    }
    return rayo_output_commit(out, err);
}

static void remove_tree(const char *dir)
{
    char command[256];
    snprintf(command, sizeof command, "rm -rf '%s'", dir);
    if (system(command) != 0)
        printf("# could not remove %s\n", dir);
}

/* The directory is renamed between the opening and the end: the commit
 * lands, and an abort removes the temporary file, where it now is;
 * rayo_output_temp_at names the temporary file in that directory. */
static void test_renamed_directory(void)
{
    char dir[64], moved[80], again[96], path[128], check[160];
    rayo_output *out;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    const char *name;
    int dir_fd, found;
    struct stat st;
    umask(022);
    if (!make_dir(dir, sizeof dir, 0755)) {
        ok(0, "a directory");
        return;
    }
    snprintf(moved, sizeof moved, "%s-moved", dir);
    snprintf(again, sizeof again, "%s-again", dir);
    snprintf(path, sizeof path, "%s/f.pbm", dir);
    found = rayo_output_open(&out, path, &err) == RAYO_OK;
    ok(found, "renamed directory: opened");
    if (!found)
        return;
    name = rayo_output_temp_at(out, &dir_fd);
    ok(name != NULL && strncmp(name, ".f.pbm.", 7) == 0 &&
           strlen(name) == 13,
       "the temporary file is .NAME.XXXXXX (%s)", name ? name : "none");
    ok(name != NULL && fstatat(dir_fd, name, &st, 0) == 0 &&
           S_ISREG(st.st_mode) && (st.st_mode & 0777) == 0644,
       "in the descriptor's directory, with a new file's mode");
    rayo_output_write(out, "one\n", 4, &err);
    ok(rename(dir, moved) == 0, "the directory renamed mid-way");
    is_int(rayo_output_commit(out, &err), RAYO_OK, "the commit succeeds");
    snprintf(check, sizeof check, "%s/f.pbm", moved);
    is_string(file_text(check), "one\n", "the file is in the renamed "
                                         "directory");
    is_int(entries(moved), 1, "and nothing else is");

    snprintf(path, sizeof path, "%s/f.pbm", moved);
    found = rayo_output_open(&out, path, &err) == RAYO_OK;
    ok(found, "renamed directory: opened again");
    if (!found)
        return;
    rayo_output_write(out, "two\n", 4, &err);
    ok(rename(moved, again) == 0, "renamed again");
    name = rayo_output_temp_at(out, &dir_fd);
    snprintf(check, sizeof check, "%s/%s", again, name ? name : "?");
    ok(access(check, F_OK) == 0, "the temporary file moved with it");
    rayo_output_abort(out);
    is_int(entries(again), 1, "abort: the temporary file removed there");
    snprintf(check, sizeof check, "%s/f.pbm", again);
    is_string(file_text(check), "one\n", "abort: the earlier file intact");
    remove_tree(again);
    ok(rayo_output_open(&out, "-", &err) == RAYO_OK &&
           rayo_output_temp_at(out, &dir_fd) == NULL && dir_fd == -1,
       "standard output has no temporary file");
    rayo_output_abort(out);
}

/* A replaced file keeps its mode, whatever the umask says. */
static void test_keeps_mode(void)
{
    char dir[64], path[96];
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    struct stat st;
    if (!make_dir(dir, sizeof dir, 0755)) {
        ok(0, "a directory");
        return;
    }
    snprintf(path, sizeof path, "%s/m.pbm", dir);
    put_file(path, "old\n", 0604);
    is_int(replace_with(path, "new\n", &err), RAYO_OK, "mode: replaced");
    if (stat(path, &st) != 0)
        st.st_mode = 0;
    is_int(st.st_mode & 07777, 0604, "a 0604 file stays 0604");
    is_string(file_text(path), "new\n", "with the new bytes");
    remove_tree(dir);
}

#define NOBODY 65534

/* Runs replace_with(path) as user NOBODY, in a child: 0 when it
 * succeeded, 1 refused as permission denied (EACCES), 2 otherwise. */
static int replace_as_nobody(const char *path)
{
    pid_t pid = fork();
    int status;
    if (pid == 0) {
        rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
        rayo_status s;
        if (setgroups(0, NULL) != 0 || setgid(NOBODY) != 0 ||
            setuid(NOBODY) != 0)
            _exit(3);
        s = replace_with(path, "nobody\n", &err);
        if (s == RAYO_OK)
            _exit(0);
        _exit(s == RAYO_ERR_IO &&
                      strstr(err.message, strerror(EACCES)) != NULL
                  ? 1
                  : 2);
    }
    if (pid < 0 || waitpid(pid, &status, 0) != pid || !WIFEXITED(status))
        return -1;
    return WEXITSTATUS(status);
}

/* As an ordinary user, in a world-writable directory: a root-owned 0444
 * file (which `>` cannot open) is refused and stays; one the user may
 * write is replaced.  As root, a replaced file keeps its owner. */
static void test_permissions(void)
{
    char dir[64], path[96];
    struct stat st;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    if (geteuid() != 0) {
        ok(1, "# SKIP not root: no other user to be");
        return;
    }
    if (!make_dir(dir, sizeof dir, 0777)) {
        ok(0, "a directory");
        return;
    }
    snprintf(path, sizeof path, "%s/ro.pbm", dir);
    put_file(path, "root's\n", 0444);
    is_int(replace_as_nobody(path), 1,
           "a user's -o over root's 0444 file: permission denied");
    is_string(file_text(path), "root's\n", "the file is intact");
    ok(stat(path, &st) == 0 && st.st_uid == 0 && (st.st_mode & 0777) == 0444,
       "still root's, still 0444");
    is_int(entries(dir), 1, "no temporary file was made");

    snprintf(path, sizeof path, "%s/own.pbm", dir);
    put_file(path, "mine\n", 0664);
    if (chown(path, NOBODY, NOBODY) != 0)
        ok(0, "chown");
    is_int(replace_as_nobody(path), 0, "a file the user may write: replaced");
    is_string(file_text(path), "nobody\n", "with the user's bytes");

    snprintf(path, sizeof path, "%s/theirs.pbm", dir);
    put_file(path, "theirs\n", 0640);
    if (chown(path, NOBODY, NOBODY) != 0)
        ok(0, "chown");
    is_int(replace_with(path, "root's\n", &err), RAYO_OK,
           "root replaces another user's file");
    if (stat(path, &st) != 0)
        memset(&st, 0, sizeof st);
    is_int(st.st_uid, NOBODY, "which keeps its owner");
    is_int(st.st_gid, NOBODY, "its group");
    is_int(st.st_mode & 07777, 0640, "and its mode");
    remove_tree(dir);
}

/* A link named by root in dir (mode dir_mode, owner dir_owner), owned
 * by link_owner, to a root-owned 0600 file: 1 when rayo followed it
 * (the file replaced, the link still a link), 0 when it refused (the
 * file intact), -1 otherwise. */
static int follows(mode_t dir_mode, uid_t dir_owner, uid_t link_owner)
{
    char dir[64], target_dir[64], target[96], link[96];
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    struct stat st;
    int result = -1;
    if (!make_dir(dir, sizeof dir, dir_mode) ||
        !make_dir(target_dir, sizeof target_dir, 0755))
        return -1;
    snprintf(target, sizeof target, "%s/secret", target_dir);
    snprintf(link, sizeof link, "%s/out.pbm", dir);
    put_file(target, "secret\n", 0600);
    if (chown(dir, dir_owner, dir_owner) == 0 && symlink(target, link) == 0 &&
        lchown(link, link_owner, link_owner) == 0) {
        status = replace_with(link, "replaced\n", &err);
        if (status == RAYO_OK && lstat(link, &st) == 0 && S_ISLNK(st.st_mode) &&
            strcmp(file_text(target), "replaced\n") == 0 &&
            stat(target, &st) == 0 && (st.st_mode & 0777) == 0600)
            result = 1;
        else if (status == RAYO_ERR_IO &&
                 strstr(err.message, strerror(EACCES)) != NULL &&
                 strcmp(file_text(target), "secret\n") == 0 &&
                 entries(dir) == 1)
            result = 0;
    }
    remove_tree(dir);
    remove_tree(target_dir);
    return result;
}

/* The kernel's protected_symlinks rule, whatever the kernel's setting:
 * in a sticky world-writable directory a link is followed only when
 * its owner is the follower or the directory's owner. */
static void test_links(void)
{
    char dir[64], link[96], target[96];
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    if (geteuid() != 0) {
        ok(1, "# SKIP not root: links of other users cannot be made");
        return;
    }
    is_int(follows(01777, 0, NOBODY), 0,
           "sticky /tmp-like directory, another user's link: refused");
    is_int(follows(01777, 0, 0), 1, "the same, root's own link: followed");
    is_int(follows(01777, NOBODY, NOBODY), 1,
           "the link of the directory's owner: followed");
    is_int(follows(00777, 0, NOBODY), 1,
           "not sticky: another user's link followed");
    is_int(follows(01755, 0, NOBODY), 1,
           "sticky, not world-writable: followed");
    if (!make_dir(dir, sizeof dir, 0755)) {
        ok(0, "a directory");
        return;
    }
    snprintf(link, sizeof link, "%s/dangling.pbm", dir);
    snprintf(target, sizeof target, "%s/new.pbm", dir);
    if (symlink("new.pbm", link) != 0)
        ok(0, "symlink");
    is_int(replace_with(link, "new\n", &err), RAYO_OK,
           "a relative link to nothing yet");
    is_string(file_text(target), "new\n", "creates its target, as > does");
    remove_tree(dir);
}

/* A link to a pipe, as /dev/stdout is through /proc/self/fd/1 (whose
 * target, "pipe:[N]", names nothing to walk to): written straight into
 * the pipe, no temporary file. */
static void test_link_to_pipe(void)
{
    char dir[64], link[96], target[64], got[8] = {0};
    int fds[2], dir_fd = 0;
    rayo_output *out;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    int opened;
    if (!make_dir(dir, sizeof dir, 0755) || pipe(fds) != 0) {
        ok(0, "a directory and a pipe");
        return;
    }
    snprintf(link, sizeof link, "%s/stdout", dir);
    snprintf(target, sizeof target, "/proc/self/fd/%d", fds[1]);
    if (symlink(target, link) != 0)
        ok(0, "symlink");
    opened = rayo_output_open(&out, link, &err) == RAYO_OK;
    ok(opened && rayo_output_temp_at(out, &dir_fd) == NULL,
       "a link to a pipe's /proc/self/fd entry: written directly");
    if (opened) {
        rayo_output_write(out, "P1\n", 3, &err);
        is_int(rayo_output_commit(out, &err), RAYO_OK, "and committed");
        ok(read(fds[0], got, 3) == 3 && strcmp(got, "P1\n") == 0,
           "the bytes came through the pipe");
    }
    close(fds[0]);
    close(fds[1]);
    remove_tree(dir);
}

int main(void)
{
    signal(SIGPIPE, SIG_IGN);
    test_is_terminal();
    test_file();
    test_pipe();
    test_interrupted_pipe();
    test_full_device();
    test_lost_bytes();
    test_abandoned_image();
    test_closed_pipe();
    test_renamed_directory();
    test_keeps_mode();
    test_permissions();
    test_links();
    test_link_to_pipe();
    return tap_done();
}
