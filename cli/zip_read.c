/*
 * zip_read.c - a student's zip file's C sources copied out (see
 * zip_read.h).
 *
 * The archive is read whole (at most CLI_ZIP_MAX_SIZE bytes) and its
 * central directory walked twice: first every entry is checked (names,
 * kinds, encryption, methods, declared sizes, duplicates), so a hostile
 * archive is refused before anything is written; then the sources are
 * inflated one by one into a bounded buffer, so an entry whose header
 * lies about its size still stops at CLI_ZIP_MAX_FILE bytes.  Each
 * inflated source must match its CRC-32.  Zip64 archives and archives
 * split over several disks are refused: a student's sources never need
 * them.
 */
#define _POSIX_C_SOURCE 200809L

#include "zip_read.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include "cli.h"

#define EOCD_SIZE 22
#define CENTRAL_SIZE 46
#define LOCAL_SIZE 30
#define NAME_SHOWN 80 /* bytes of an entry's name quoted in a message */

typedef struct zip_entry {
    const unsigned char *name; /* not NUL-terminated */
    size_t name_length;
    unsigned flags, method, made_by;
    uint32_t crc, packed, size, attributes, offset;
} zip_entry;

static unsigned get16(const unsigned char *p)
{
    return (unsigned)p[0] | (unsigned)p[1] << 8;
}

static uint32_t get32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
           (uint32_t)p[3] << 24;
}

/* The entry's name for a message, on one line: control bytes and bytes
   that are not UTF-8 escaped as the command escapes names (\n, \xHH),
   at most about NAME_SHOWN bytes, then "...". */
static const char *shown(const zip_entry *e, char text[NAME_SHOWN + 16])
{
    char raw[NAME_SHOWN + 8];
    size_t n = e->name_length < NAME_SHOWN ? e->name_length : NAME_SHOWN;
    size_t used = 0, at = 0;
    memcpy(raw, e->name, n);
    memset(raw + n, 0, sizeof raw - n);
    while (at < n && raw[at] != '\0') {
        char unit[8];
        size_t columns, length;
        at += cli_escape_unit(raw + at, 1, unit, &columns);
        length = strlen(unit);
        if (used + length > NAME_SHOWN)
            break;
        memcpy(text + used, unit, length);
        used += length;
    }
    strcpy(text + used, at < e->name_length ? "..." : "");
    return text;
}

/* The part of the name after its last '/' (or '\'). */
static size_t own_name_start(const zip_entry *e)
{
    size_t i, start = 0;
    for (i = 0; i < e->name_length; i++)
        if (e->name[i] == '/' || e->name[i] == '\\')
            start = i + 1;
    return start;
}

/* Whether the entry is a C source or header we copy out. */
static int is_source(const zip_entry *e)
{
    size_t start = own_name_start(e), n = e->name_length - start, i;
    const unsigned char *own = e->name + start;
    if (n < 3 || own[0] == '.' || own[n - 2] != '.' ||
        (own[n - 1] != 'c' && own[n - 1] != 'h'))
        return 0;
    for (i = 0; i + 8 <= e->name_length; i++)
        if (memcmp(e->name + i, "__MACOSX", 8) == 0 &&
            (i == 0 || e->name[i - 1] == '/'))
            return 0;
    return 1;
}

/* Why the entry's name or kind is refused, or NULL. */
static const char *refused(const zip_entry *e)
{
    size_t i, start = 0;
    unsigned type = (unsigned)(e->attributes >> 16) & 0170000u;
    if (e->name_length == 0)
        return N_("has no name");
    if (memchr(e->name, '\0', e->name_length) != NULL)
        return N_("has a NUL byte in its name");
    if (e->name[0] == '/' || e->name[0] == '\\' ||
        (e->name_length >= 2 && e->name[1] == ':'))
        return N_("is an absolute path");
    for (i = 0; i <= e->name_length; i++) {
        if (i == e->name_length || e->name[i] == '/' || e->name[i] == '\\') {
            if (i - start == 2 && e->name[start] == '.' &&
                e->name[start + 1] == '.')
                return N_("climbs out of the folder with '..'");
            start = i + 1;
        }
    }
    if ((e->made_by >> 8) == 3 && type == 0120000u)
        return N_("is a symbolic link");
    if ((e->made_by >> 8) == 3 && type != 0 && type != 0100000u &&
        type != 0040000u)
        return N_("is not a plain file or folder");
    if (e->flags & 1u)
        return N_("is encrypted");
    return NULL;
}

/* The central directory: where it starts and how many entries. */
static rayo_status find_directory(const char *path, const unsigned char *zip,
                                  size_t size, size_t *start,
                                  size_t *entries, rayo_error *err)
{
    size_t at, lowest;
    if (size < EOCD_SIZE)
        return rayo_error_set(err, RAYO_ERR_FORMAT, "%s: not a zip file "
                              "(too short); expected a zip archive", path);
    lowest = size - EOCD_SIZE > 65535 ? size - EOCD_SIZE - 65535 : 0;
    for (at = size - EOCD_SIZE + 1; at-- > lowest;) {
        if (get32(zip + at) != 0x06054b50u)
            continue;
        if (get16(zip + at + 4) != 0 || get16(zip + at + 6) != 0 ||
            get16(zip + at + 8) != get16(zip + at + 10))
            return rayo_error_set(err, RAYO_ERR_FORMAT, "%s: a zip split "
                                  "over several disks; expected one file",
                                  path);
        *entries = get16(zip + at + 10);
        *start = get32(zip + at + 16);
        if (*entries == 0xFFFFu || *start == 0xFFFFFFFFu)
            return rayo_error_set(err, RAYO_ERR_FORMAT, "%s: a Zip64 "
                                  "archive; rayo reads plain zip files",
                                  path);
        if (*start > at || get32(zip + at + 12) > at - *start)
            return rayo_error_set(err, RAYO_ERR_FORMAT, "%s: the zip's "
                                  "directory points outside the file",
                                  path);
        if (*entries > CLI_ZIP_MAX_ENTRIES)
            return rayo_error_set(err, RAYO_ERR_LIMIT, "%s: %zu entries; "
                                  "rayo reads at most %u", path, *entries,
                                  CLI_ZIP_MAX_ENTRIES);
        return RAYO_OK;
    }
    return rayo_error_set(err, RAYO_ERR_FORMAT, "%s: not a zip file (no "
                          "end of central directory); expected a zip "
                          "archive", path);
}

/* The entries, read and checked; *list allocated. */
static rayo_status read_entries(const char *path, const unsigned char *zip,
                                size_t size, zip_entry **list,
                                size_t *count, rayo_error *err)
{
    size_t start = 0, entries = 0, at, i;
    zip_entry *e;
    rayo_status status = find_directory(path, zip, size, &start, &entries,
                                        err);
    if (status != RAYO_OK)
        return status;
    e = calloc(entries > 0 ? entries : 1, sizeof *e);
    if (e == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                              path);
    for (i = 0, at = start; i < entries; i++) {
        char text[NAME_SHOWN + 16];
        const char *why;
        if (at + CENTRAL_SIZE > size || get32(zip + at) != 0x02014b50u) {
            free(e);
            return rayo_error_set(err, RAYO_ERR_FORMAT, "%s: the zip's "
                                  "directory is damaged at entry %zu",
                                  path, i + 1);
        }
        e[i].made_by = get16(zip + at + 4);
        e[i].flags = get16(zip + at + 8);
        e[i].method = get16(zip + at + 10);
        e[i].crc = get32(zip + at + 16);
        e[i].packed = get32(zip + at + 20);
        e[i].size = get32(zip + at + 24);
        e[i].name_length = get16(zip + at + 28);
        e[i].attributes = get32(zip + at + 38);
        e[i].offset = get32(zip + at + 42);
        e[i].name = zip + at + CENTRAL_SIZE;
        if (at + CENTRAL_SIZE + e[i].name_length > size) {
            free(e);
            return rayo_error_set(err, RAYO_ERR_FORMAT, "%s: the zip's "
                                  "directory is damaged at entry %zu",
                                  path, i + 1);
        }
        why = refused(&e[i]);
        if (why == NULL && is_source(&e[i]) && e[i].method != 0 &&
            e[i].method != 8)
            why = N_("is compressed with a method other than stored or "
                     "deflated");
        if (why == NULL && is_source(&e[i]) && e[i].size > CLI_ZIP_MAX_FILE)
            why = N_("inflates past the 1 MiB a source may have");
        if (why != NULL) {
            shown(&e[i], text);
            free(e);
            return rayo_error_set(err, RAYO_ERR_FORMAT, "%s: the entry "
                                  "'%s' %s; refusing the archive",
                                  path, text, _(why));
        }
        at += CENTRAL_SIZE + e[i].name_length + get16(zip + at + 30) +
              get16(zip + at + 32);
    }
    *list = e;
    *count = entries;
    return RAYO_OK;
}

/* Refuses two sources with the same own name. */
static rayo_status check_duplicates(const char *path, const zip_entry *e,
                                    size_t count, rayo_error *err)
{
    size_t i, j;
    for (i = 0; i < count; i++) {
        size_t a = own_name_start(&e[i]), na = e[i].name_length - a;
        if (!is_source(&e[i]))
            continue;
        for (j = i + 1; j < count; j++) {
            size_t b = own_name_start(&e[j]), nb = e[j].name_length - b;
            if (is_source(&e[j]) && na == nb &&
                memcmp(e[i].name + a, e[j].name + b, na) == 0) {
                char first[NAME_SHOWN + 16], second[NAME_SHOWN + 16];
                return rayo_error_set(err, RAYO_ERR_FORMAT, "%s: the "
                                      "entries '%s' and '%s' have the same "
                                      "name; expected one of each source",
                                      path, shown(&e[i], first),
                                      shown(&e[j], second));
            }
        }
    }
    return RAYO_OK;
}

/* The entry's bytes, inflated into out (at most CLI_ZIP_MAX_FILE);
   *length how many. */
static rayo_status inflate_entry(const char *path, const unsigned char *zip,
                                 size_t size, const zip_entry *e,
                                 unsigned char *out, size_t *length,
                                 rayo_error *err)
{
    char text[NAME_SHOWN + 16];
    size_t data;
    if ((size_t)e->offset + LOCAL_SIZE > size ||
        get32(zip + e->offset) != 0x04034b50u)
        return rayo_error_set(err, RAYO_ERR_FORMAT, "%s: the entry '%s' "
                              "is damaged (no local header)", path,
                              shown(e, text));
    data = (size_t)e->offset + LOCAL_SIZE + get16(zip + e->offset + 26) +
           get16(zip + e->offset + 28);
    if (data > size || e->packed > size - data)
        return rayo_error_set(err, RAYO_ERR_FORMAT, "%s: the entry '%s' "
                              "runs past the end of the file", path,
                              shown(e, text));
    if (e->method == 0) {
        if (e->packed > CLI_ZIP_MAX_FILE)
            return rayo_error_set(err, RAYO_ERR_LIMIT, "%s: the entry '%s' "
                                  "inflates past the 1 MiB a source may "
                                  "have; refusing the archive", path,
                                  shown(e, text));
        memcpy(out, zip + data, e->packed);
        *length = e->packed;
    } else {
        z_stream z;
        int result;
        memset(&z, 0, sizeof z);
        if (inflateInit2(&z, -MAX_WBITS) != Z_OK)
            return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                                  path);
        z.next_in = (unsigned char *)(uintptr_t)(zip + data);
        z.avail_in = e->packed;
        z.next_out = out;
        z.avail_out = CLI_ZIP_MAX_FILE + 1;
        result = inflate(&z, Z_FINISH);
        *length = CLI_ZIP_MAX_FILE + 1 - z.avail_out;
        inflateEnd(&z);
        if (*length > CLI_ZIP_MAX_FILE)
            return rayo_error_set(err, RAYO_ERR_LIMIT, "%s: the entry '%s' "
                                  "inflates past the 1 MiB a source may "
                                  "have; refusing the archive", path,
                                  shown(e, text));
        if (result != Z_STREAM_END)
            return rayo_error_set(err, RAYO_ERR_FORMAT, "%s: the entry '%s' "
                                  "is damaged (it does not inflate)", path,
                                  shown(e, text));
    }
    if (*length != e->size ||
        crc32(0L, out, (uInt)*length) != e->crc)
        return rayo_error_set(err, RAYO_ERR_FORMAT, "%s: the entry '%s' is "
                              "damaged (its size or CRC does not match)",
                              path, shown(e, text));
    return RAYO_OK;
}

/* Writes bytes into dest/name, a new file. */
static rayo_status write_source(const char *dest, const char *name,
                                const unsigned char *bytes, size_t length,
                                rayo_error *err)
{
    size_t room = strlen(dest) + strlen(name) + 2, done = 0;
    char *target = malloc(room);
    int fd;
    if (target == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                              dest);
    snprintf(target, room, "%s/%s", dest, name);
    fd = open(target, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
              0644);
    while (fd >= 0 && done < length) {
        ssize_t n = write(fd, bytes + done, length - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            int saved = errno;
            close(fd);
            fd = -1;
            errno = saved;
            break;
        }
        done += (size_t)n;
    }
    if (fd < 0 || close(fd) != 0) {
        rayo_status status = rayo_error_set(err, RAYO_ERR_IO, "%s: %s",
                                            target, strerror(errno));
        free(target);
        return status;
    }
    free(target);
    return RAYO_OK;
}

/* The whole zip file in memory. */
static rayo_status read_zip(const char *path, unsigned char **zip,
                            size_t *size, rayo_error *err)
{
    struct stat st;
    size_t done = 0;
    int fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0 || fstat(fd, &st) != 0) {
        rayo_status status = rayo_error_set(err, RAYO_ERR_IO, "%s: %s",
                                            path, strerror(errno));
        if (fd >= 0)
            close(fd);
        return status;
    }
    if (!S_ISREG(st.st_mode) || st.st_size > (off_t)CLI_ZIP_MAX_SIZE) {
        close(fd);
        return rayo_error_set(err, RAYO_ERR_LIMIT, "%s: not a regular file "
                              "of at most 64 MiB; expected a student's zip",
                              path);
    }
    *zip = malloc((size_t)st.st_size + 1);
    if (*zip == NULL) {
        close(fd);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                              path);
    }
    while (done < (size_t)st.st_size) {
        ssize_t n = read(fd, *zip + done, (size_t)st.st_size - done);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            break;
        done += (size_t)n;
    }
    close(fd);
    *size = done;
    return RAYO_OK;
}

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

rayo_status cli_zip_extract_sources(const char *path, const char *dest,
                                    char ***names, size_t *count,
                                    size_t *others, rayo_error *err)
{
    unsigned char *zip = NULL, *out = NULL;
    zip_entry *e = NULL;
    size_t size = 0, entries = 0, i, written = 0, total = 0;
    char **list = NULL;
    rayo_status status;
    *names = NULL;
    *count = 0;
    *others = 0;
    status = read_zip(path, &zip, &size, err);
    if (status == RAYO_OK)
        status = read_entries(path, zip, size, &e, &entries, err);
    if (status == RAYO_OK)
        status = check_duplicates(path, e, entries, err);
    if (status == RAYO_OK) {
        out = malloc(CLI_ZIP_MAX_FILE + 1);
        list = calloc(entries > 0 ? entries : 1, sizeof *list);
        if (out == NULL || list == NULL)
            status = rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                                    path);
    }
    for (i = 0; status == RAYO_OK && i < entries; i++) {
        size_t start = own_name_start(&e[i]), length = 0;
        if (!is_source(&e[i])) {
            if (e[i].name[e[i].name_length - 1] != '/')
                (*others)++;
            continue;
        }
        status = inflate_entry(path, zip, size, &e[i], out, &length, err);
        if (status == RAYO_OK && (total += length) > CLI_ZIP_MAX_TOTAL)
            status = rayo_error_set(err, RAYO_ERR_LIMIT, "%s: its sources "
                                    "inflate past 8 MiB in all; refusing "
                                    "the archive", path);
        if (status == RAYO_OK) {
            list[written] = malloc(e[i].name_length - start + 1);
            if (list[written] == NULL) {
                status = rayo_error_set(err, RAYO_ERR_NOMEM,
                                        "%s: out of memory", path);
                break;
            }
            memcpy(list[written], e[i].name + start,
                   e[i].name_length - start);
            list[written][e[i].name_length - start] = '\0';
            status = write_source(dest, list[written++], out, length, err);
        }
    }
    free(out);
    free(e);
    free(zip);
    if (status != RAYO_OK) {
        for (i = 0; i < written; i++)
            free(list[i]);
        free(list);
        return status;
    }
    qsort(list, written, sizeof *list, by_name);
    *names = list;
    *count = written;
    return RAYO_OK;
}
