/*
 * replay.c - runs a fuzz target without libFuzzer: every file named on
 * the command line, and every file in every folder named, is read into a
 * buffer of exactly its size and handed to LLVMFuzzerTestOneInput once.
 *
 * Built with the ordinary build (gcc or clang, any sanitizer or none) as
 * $(BUILD)/fuzz/replay-<target>, so `make check` replays the seed corpus
 * and every input that ever crashed or leaked (fuzz/regression/) on each
 * run, and `make check-sanitize` does it under ASan and UBSan.  A target
 * that breaks a promise aborts, which fails the run; a file that cannot
 * be read is exit status 1.  Prints "replayed N files" on success, on
 * the stream given by --count-to (a file), since the targets' own
 * messages (the command-line parsers print) go to stdout and stderr.
 */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "fuzz.h"

/* Largest input replayed; fuzzing inputs are a few KiB. */
#define REPLAY_MAX_BYTES (16ul << 20)

static int replay_file(const char *path, FILE *log)
{
    struct stat st;
    unsigned char *data;
    size_t got;
    FILE *in = fopen(path, "rb");
    if (in == NULL || fstat(fileno(in), &st) != 0) {
        fprintf(log, "replay: %s: %s\n", path, strerror(errno));
        if (in != NULL)
            fclose(in);
        return 0;
    }
    if ((unsigned long long)st.st_size > REPLAY_MAX_BYTES) {
        fprintf(log, "replay: %s: larger than %lu bytes\n", path,
                REPLAY_MAX_BYTES);
        fclose(in);
        return 0;
    }
    /* At least one byte, so a zero-length input is a valid pointer. */
    data = malloc(st.st_size > 0 ? (size_t)st.st_size : 1);
    if (data == NULL) {
        fclose(in);
        return 0;
    }
    got = fread(data, 1, (size_t)st.st_size, in);
    fclose(in);
    if (got != (size_t)st.st_size) {
        fprintf(log, "replay: %s: short read\n", path);
        free(data);
        return 0;
    }
    LLVMFuzzerTestOneInput(data, got);
    free(data);
    return 1;
}

static int compare_names(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Replays the regular files in dir, in name order; 0 on failure. */
static int replay_folder(const char *dir, FILE *log, unsigned long *count)
{
    DIR *d = opendir(dir);
    struct dirent *entry;
    char **names = NULL;
    size_t n = 0, capacity = 0, i;
    int ok = 1;
    if (d == NULL) {
        fprintf(log, "replay: %s: %s\n", dir, strerror(errno));
        return 0;
    }
    while (ok && (entry = readdir(d)) != NULL) {
        size_t length = strlen(dir) + strlen(entry->d_name) + 2;
        if (entry->d_name[0] == '.')
            continue;
        if (n == capacity) {
            char **grown;
            capacity = capacity ? capacity * 2 : 64;
            grown = realloc(names, capacity * sizeof *names);
            if (grown == NULL) {
                ok = 0;
                break;
            }
            names = grown;
        }
        names[n] = malloc(length);
        if (names[n] == NULL) {
            ok = 0;
            break;
        }
        snprintf(names[n++], length, "%s/%s", dir, entry->d_name);
    }
    closedir(d);
    if (n > 0)
        qsort(names, n, sizeof *names, compare_names);
    for (i = 0; i < n; i++) {
        struct stat st;
        if (ok && stat(names[i], &st) == 0 && S_ISREG(st.st_mode)) {
            ok = replay_file(names[i], log);
            *count += (unsigned long)ok;
        }
        free(names[i]);
    }
    free(names);
    return ok;
}

int main(int argc, char **argv)
{
    FILE *log = stderr;
    unsigned long count = 0;
    int i = 1, ok = 1;
    if (argc > 2 && strcmp(argv[1], "--count-to") == 0) {
        log = fopen(argv[2], "w");
        if (log == NULL) {
            perror(argv[2]);
            return 1;
        }
        i = 3;
    }
    for (; ok && i < argc; i++) {
        struct stat st;
        if (stat(argv[i], &st) == 0 && S_ISDIR(st.st_mode))
            ok = replay_folder(argv[i], log, &count);
        else {
            ok = replay_file(argv[i], log);
            count += (unsigned long)ok;
        }
    }
    if (ok)
        fprintf(log, "replayed %lu files\n", count);
    if (log != stderr)
        fclose(log);
    return ok ? 0 : 1;
}
