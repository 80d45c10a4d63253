/*
 * fuzz_zip.c - fuzz target: the zip reader of `rayo grade --each`
 * (cli/zip_read.c, reached through its header, cli/zip_read.h, with the
 * fuzz rules' -Icli), which reads students' zip files.
 *
 * The input is written to a temporary file and its sources copied out
 * into a fresh temporary folder.  A refusal must be one line; on success
 * every name must be a plain own name (no '/', not "." or ".."), a
 * C source or header, and a regular file in the folder of at most the
 * bound.  The folder and the file are removed after each input.  Not a
 * conformance test: tests/cli/grade_layouts.t checks what is read.
 */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "zip_read.h"
#include "fuzz.h"

static void check_name(const char *dest, const char *name)
{
    char path[8200];
    struct stat st;
    size_t n = strlen(name);
    if (n < 3 || strchr(name, '/') != NULL || name[0] == '.' ||
        name[n - 2] != '.' || (name[n - 1] != 'c' && name[n - 1] != 'h'))
        abort();
    snprintf(path, sizeof path, "%s/%s", dest, name);
    if (lstat(path, &st) != 0 || !S_ISREG(st.st_mode) ||
        st.st_size > (off_t)CLI_ZIP_MAX_FILE)
        abort();
    unlink(path);
}

/* A refused archive may leave sources behind (the folder is flat). */
static void remove_folder(const char *dest)
{
    DIR *d = opendir(dest);
    struct dirent *e;
    if (d == NULL)
        abort();
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0 &&
            unlinkat(dirfd(d), e->d_name, 0) != 0)
            abort();
    closedir(d);
    if (rmdir(dest) != 0)
        abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    const char *tmp = getenv("TMPDIR");
    char zip[4096], dest[4096], **names = NULL;
    size_t count = 0, others = 0, i;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    FILE *file;
    int fd;
    if (tmp == NULL || tmp[0] == '\0')
        tmp = "/tmp";
    snprintf(zip, sizeof zip, "%s/rayo-fuzz-zip.XXXXXX", tmp);
    snprintf(dest, sizeof dest, "%s/rayo-fuzz-dest.XXXXXX", tmp);
    fd = mkstemp(zip);
    if (fd < 0 || mkdtemp(dest) == NULL)
        abort();
    file = fdopen(fd, "wb");
    if (file == NULL || fwrite(data, 1, size, file) != size ||
        fclose(file) != 0)
        abort();
    rayo_error_clear(&err);
    status = cli_zip_extract_sources(zip, dest, &names, &count, &others,
                                     &err);
    if (status != RAYO_OK) {
        fuzz_check_refusal(status, &err);
    } else {
        for (i = 0; i < count; i++)
            check_name(dest, names[i]);
        rayo_grade_paths_free(names, count);
    }
    remove_folder(dest);
    unlink(zip);
    return 0;
}
