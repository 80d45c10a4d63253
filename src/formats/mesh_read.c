/*
 * mesh_read.c - the public face of the mesh readers (mesh.h): opens the
 * source, tells binary STL, ASCII STL and OBJ apart from the first bytes
 * and the file's size, and hands over to mesh_stl.c or mesh_obj.c; owns
 * what they share, the growing list of triangles and the text cursor.
 *
 * Not where any format is parsed.
 */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../core/decimal.h"
#include "mesh_impl.h"
#include "rayo/limits.h"

const char *rayo_mesh_format_name(rayo_mesh_format format)
{
    switch (format) {
    case RAYO_MESH_STL_BINARY: return "binary STL";
    case RAYO_MESH_STL_ASCII: return "ASCII STL";
    case RAYO_MESH_OBJ: return "OBJ";
    }
    return "?";
}

void rayo_mesh_free(rayo_mesh *mesh)
{
    if (mesh == NULL)
        return;
    free(mesh->corners);
    free(mesh->normals);
    memset(mesh, 0, sizeof *mesh);
}

static rayo_status too_many(const char *name, rayo_error *err)
{
    return rayo_error_set(err, RAYO_ERR_LIMIT,
                          "%s: more than %lu triangles; expected at most "
                          "%lu (2^24, the objects of a scene)",
                          name, RAYO_MAX_OBJECTS, RAYO_MAX_OBJECTS);
}

rayo_status mesh_reserve(mesh_builder *b, size_t more, const char *name,
                         rayo_error *err)
{
    rayo_mesh *m = b->mesh;
    size_t want = m->count + more, capacity;
    float *corners, *normals;
    if (more > RAYO_MAX_OBJECTS || want > RAYO_MAX_OBJECTS)
        return too_many(name, err);
    if (want <= b->capacity)
        return RAYO_OK;
    capacity = b->capacity < 1024 ? 1024 : b->capacity * 2;
    if (capacity < want)
        capacity = want;
    if (capacity > RAYO_MAX_OBJECTS)
        capacity = RAYO_MAX_OBJECTS;
    corners = realloc(m->corners, capacity * 9 * sizeof *corners);
    if (corners == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    m->corners = corners;
    if (b->with_normals) {
        normals = realloc(m->normals, capacity * 3 * sizeof *normals);
        if (normals == NULL)
            return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
        m->normals = normals;
    }
    b->capacity = capacity;
    return RAYO_OK;
}

rayo_status mesh_push(mesh_builder *b, const float corners[9],
                      const float normal[3], const char *name,
                      rayo_error *err)
{
    rayo_mesh *m = b->mesh;
    if (m->count == b->capacity) {
        rayo_status status = mesh_reserve(b, 1, name, err);
        if (status != RAYO_OK)
            return status;
    }
    memcpy(m->corners + m->count * 9, corners, 9 * sizeof *corners);
    if (b->with_normals)
        memcpy(m->normals + m->count * 3, normal, 3 * sizeof *normal);
    m->count++;
    return RAYO_OK;
}

int mesh_text_getc(mesh_text *t)
{
    if (t->head_next < t->head_size)
        return t->head[t->head_next++];
    return rayo_source_getc(t->src);
}

size_t mesh_text_word(mesh_text *t, char *word, size_t size, uint64_t *line)
{
    size_t n = 0;
    int c = mesh_text_getc(t);
    while (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' ||
           c == '\v') {
        if (c == '\n')
            t->line++;
        c = mesh_text_getc(t);
    }
    *line = t->line;
    while (c >= 0 && !isspace(c)) {
        if (n + 1 < size)
            word[n++] = (char)c;
        else
            n = size - 1;
        c = mesh_text_getc(t);
    }
    if (c == '\n')
        t->line++;
    word[n] = '\0';
    return n;
}

int mesh_text_line(mesh_text *t, char *line, size_t size)
{
    size_t n = 0;
    int c = mesh_text_getc(t), too_long = 0;
    if (c < 0)
        return 0;
    t->line++;
    while (c >= 0 && c != '\n') {
        if (n + 1 < size)
            line[n++] = (char)c;
        else
            too_long = 1;
        c = mesh_text_getc(t);
    }
    if (n > 0 && line[n - 1] == '\r')
        n--;
    line[n] = '\0';
    return too_long ? -1 : 1;
}

int mesh_number(const char *word, float *value)
{
    double v;
    if (!decimal_read(word, strlen(word), &v) || fabs(v) > 3.4028234e38)
        return 0;
    *value = (float)v;
    return 1;
}

/* An OBJ keyword at the start of the text (after blanks). */
static int looks_like_obj(const unsigned char *head, size_t size)
{
    static const char *const words[] = {"v",  "vn", "vt", "vp", "f", "o",
                                        "g",  "s",  "l",  "p",  "#",
                                        "usemtl", "mtllib"};
    size_t i = 0, n, k;
    while (i < size && isspace(head[i]))
        i++;
    if (i < size && head[i] == '#')
        return 1;
    for (n = i; n < size && !isspace(head[n]); n++)
        ;
    if (n == size && size == 84)
        return 0; /* a first word that long is no keyword */
    for (k = 0; k < sizeof words / sizeof words[0]; k++)
        if (strlen(words[k]) == n - i &&
            memcmp(words[k], head + i, n - i) == 0)
            return 1;
    return 0;
}

static rayo_status read_mesh(rayo_source *src, rayo_mesh *mesh,
                             rayo_mesh_report *report, rayo_error *err)
{
    unsigned char head[84];
    size_t got;
    uint64_t remaining = 0;
    int size_known;
    mesh_builder b;
    mesh_text text;
    memset(&b, 0, sizeof b);
    b.mesh = mesh;
    rayo_source_read(src, head, sizeof head, &got);
    if (src->read_errno != 0)
        return rayo_source_end_error(src, "a mesh", err);
    size_known = rayo_source_remaining(src, &remaining);
    memset(&text, 0, sizeof text);
    text.src = src;
    text.head = head;
    text.head_size = got;
    text.line = 0;
    if (got == 84) {
        uint32_t count = (uint32_t)head[80] | ((uint32_t)head[81] << 8) |
                         ((uint32_t)head[82] << 16) |
                         ((uint32_t)head[83] << 24);
        int exact = size_known && remaining == (uint64_t)count * 50;
        /* Text never holds a NUL; a binary count below 2^24 always does
           (and a header is often padded with them). */
        int binary = memchr(head, '\0', sizeof head) != NULL;
        if (exact || binary ||
            (memcmp(head, "solid", 5) != 0 && !looks_like_obj(head, got))) {
            report->format = RAYO_MESH_STL_BINARY;
            b.with_normals = 1;
            return rayo_mesh_read_stl_binary(src, head, &b, report, err);
        }
    }
    if (got >= 5 && memcmp(head, "solid", 5) == 0) {
        report->format = RAYO_MESH_STL_ASCII;
        b.with_normals = 1;
        return rayo_mesh_read_stl_ascii(&text, &b, report, err);
    }
    if (looks_like_obj(head, got)) {
        report->format = RAYO_MESH_OBJ;
        return rayo_mesh_read_obj(&text, &b, report, err);
    }
    return rayo_error_set(err, RAYO_ERR_FORMAT,
                          "%s: byte 0: found %lu bytes that are no mesh; "
                          "expected a binary STL (an 84-byte header), an "
                          "ASCII STL (\"solid\") or an OBJ (v and f lines)",
                          src->name, (unsigned long)got);
}

static rayo_status read_from(rayo_source *src, rayo_mesh *mesh,
                             rayo_mesh_report *report, rayo_error *err)
{
    rayo_mesh_report local;
    rayo_status status;
    if (report == NULL)
        report = &local;
    memset(report, 0, sizeof *report);
    memset(mesh, 0, sizeof *mesh);
    status = read_mesh(src, mesh, report, err);
    if (status != RAYO_OK)
        rayo_mesh_free(mesh);
    return status;
}

rayo_status rayo_mesh_read_file(const char *path, rayo_mesh *mesh,
                                rayo_mesh_report *report, rayo_error *err)
{
    rayo_source src;
    rayo_status status;
    memset(mesh, 0, sizeof *mesh);
    status = rayo_source_open_file(&src, path, err);
    if (status != RAYO_OK)
        return status;
    status = read_from(&src, mesh, report, err);
    rayo_source_close(&src);
    return status;
}

rayo_status rayo_mesh_read_memory(const void *data, size_t size,
                                  const char *name, rayo_mesh *mesh,
                                  rayo_mesh_report *report, rayo_error *err)
{
    rayo_source src;
    rayo_source_open_memory(&src, data, size, name != NULL ? name : "memory");
    return read_from(&src, mesh, report, err);
}
