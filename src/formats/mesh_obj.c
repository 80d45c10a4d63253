/*
 * mesh_obj.c - Wavefront OBJ, the geometry of it that is triangles: "v X
 * Y Z [W]" vertices and "f A B C ..." faces, each corner an index from 1
 * (or negative, from the last vertex back) with optional "/texture" and
 * "/normal" parts, which are ignored.  A face of more than three corners
 * is cut into triangles around its first corner (a fan: right for the
 * convex polygons modellers write) and counted; every other statement
 * (vn, vt, g, o, s, usemtl, mtllib, l, p, ...) is counted and skipped, so
 * the scene can say how much of the file it did not use.
 *
 * A vertex that is not finite, an index of 0 or out of range, a face of
 * fewer than three corners and a line over 64 KiB are errors naming the
 * line.  Vertices take 12 bytes each until the mesh is made; a file's
 * vertices and faces are bounded by its size, triangles by
 * RAYO_MAX_OBJECTS.  Not the STL reader.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh_impl.h"
#include "rayo/limits.h"

#define OBJ_LINE_MAX 65536

typedef struct obj_reader {
    mesh_text *t;
    mesh_builder *b;
    rayo_mesh_report *report;
    const char *name;
    float *vertices; /* 3 floats each */
    size_t vertex_count, vertex_capacity;
    char *line;
} obj_reader;

/* The line being read, for messages ("NAME:LINE: found ..."), each
 * message a whole sentence so that it is translated whole. */
static unsigned long long line_of(const obj_reader *r)
{
    return (unsigned long long)r->t->line;
}

static rayo_status add_vertex(obj_reader *r, char *rest, rayo_error *err)
{
    float v[3];
    char *word, *save = NULL;
    int k;
    for (k = 0; k < 3; k++) {
        word = strtok_r(k == 0 ? rest : NULL, " \t", &save);
        if (word != NULL && !mesh_number(word, &v[k]))
            return rayo_error_set(err, RAYO_ERR_FORMAT,
                                  "%s:%llu: found '%.40s'; expected a "
                                  "vertex's x, y and z as finite numbers",
                                  r->name, line_of(r), word);
        if (word == NULL && k == 1)
            return rayo_error_set(err, RAYO_ERR_FORMAT,
                                  "%s:%llu: found 1 number; expected a "
                                  "vertex's x, y and z as finite numbers",
                                  r->name, line_of(r));
        if (word == NULL)
            return rayo_error_set(err, RAYO_ERR_FORMAT,
                                  "%s:%llu: found %d numbers; expected a "
                                  "vertex's x, y and z as finite numbers",
                                  r->name, line_of(r), k);
    }
    if (r->vertex_count == r->vertex_capacity) {
        size_t capacity = r->vertex_capacity < 1024 ? 1024
                                                    : r->vertex_capacity * 2;
        float *grown;
        if (capacity > (size_t)-1 / (3 * sizeof *grown))
            return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
        grown = realloc(r->vertices, capacity * 3 * sizeof *grown);
        if (grown == NULL)
            return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
        r->vertices = grown;
        r->vertex_capacity = capacity;
    }
    memcpy(r->vertices + r->vertex_count * 3, v, sizeof v);
    r->vertex_count++;
    return RAYO_OK;
}

/* The vertex a face's corner names ("7", "-1", "7/3", "7//2"). */
static rayo_status corner_vertex(const obj_reader *r, const char *word,
                                 size_t *vertex, rayo_error *err)
{
    char *end;
    long long index = strtoll(word, &end, 10);
    if (end == word || (*end != '\0' && *end != '/'))
        return rayo_error_set(err, RAYO_ERR_FORMAT,
                              "%s:%llu: found the corner '%.40s'; expected "
                              "a vertex index (N, N/T, N//M or N/T/M)",
                              r->name, line_of(r), word);
    if (index < 0) {
        /* The magnitude without negating (LLONG_MIN has none). */
        unsigned long long back = 0ull - (unsigned long long)index;
        if (back <= r->vertex_count) {
            *vertex = r->vertex_count - (size_t)back;
            return RAYO_OK;
        }
    }
    if (index > 0 && (unsigned long long)index <= r->vertex_count) {
        *vertex = (size_t)index - 1;
        return RAYO_OK;
    }
    return rayo_error_set(err, RAYO_ERR_FORMAT,
                          "%s:%llu: found the vertex index %lld; expected 1 "
                          "to %llu or -1 to -%llu (the vertices so far)",
                          r->name, line_of(r), index,
                          (unsigned long long)r->vertex_count,
                          (unsigned long long)r->vertex_count);
}

static rayo_status add_face(obj_reader *r, char *rest, rayo_error *err)
{
    char *word, *save = NULL;
    size_t first = 0, previous = 0, corner = 0, n = 0;
    rayo_status status = RAYO_OK;
    for (word = strtok_r(rest, " \t", &save); word != NULL;
         word = strtok_r(NULL, " \t", &save), n++) {
        status = corner_vertex(r, word, &corner, err);
        if (status != RAYO_OK)
            return status;
        if (n == 0)
            first = corner;
        if (n >= 2) {
            float corners[9];
            memcpy(corners, r->vertices + first * 3, 3 * sizeof *corners);
            memcpy(corners + 3, r->vertices + previous * 3,
                   3 * sizeof *corners);
            memcpy(corners + 6, r->vertices + corner * 3,
                   3 * sizeof *corners);
            status = mesh_push(r->b, corners, NULL, r->name, err);
            if (status != RAYO_OK)
                return status;
        }
        previous = corner;
    }
    if (n == 1)
        return rayo_error_set(err, RAYO_ERR_FORMAT,
                              "%s:%llu: found a face of 1 corner; expected "
                              "at least 3",
                              r->name, line_of(r));
    if (n < 3)
        return rayo_error_set(err, RAYO_ERR_FORMAT,
                              "%s:%llu: found a face of %lu corners; "
                              "expected at least 3",
                              r->name, line_of(r), (unsigned long)n);
    if (n > 3)
        r->report->polygons++;
    return RAYO_OK;
}

static rayo_status read_lines(obj_reader *r, rayo_error *err)
{
    for (;;) {
        char *p, *keyword, *rest;
        size_t length;
        int got = mesh_text_line(r->t, r->line, OBJ_LINE_MAX);
        if (got == 0)
            return r->t->src->read_errno != 0
                       ? rayo_source_end_error(r->t->src, "a line", err)
                       : RAYO_OK;
        if (got < 0)
            return rayo_error_set(err, RAYO_ERR_FORMAT,
                                  "%s:%llu: found a longer line; expected "
                                  "lines of at most %d bytes",
                                  r->name, line_of(r), OBJ_LINE_MAX - 1);
        for (p = r->line; *p == ' ' || *p == '\t'; p++)
            ;
        if (*p == '\0' || *p == '#')
            continue;
        keyword = p;
        length = strcspn(p, " \t");
        rest = p + length;
        if (*rest != '\0')
            *rest++ = '\0';
        if (strcmp(keyword, "v") == 0) {
            rayo_status status = add_vertex(r, rest, err);
            if (status != RAYO_OK)
                return status;
        } else if (strcmp(keyword, "f") == 0) {
            rayo_status status = add_face(r, rest, err);
            if (status != RAYO_OK)
                return status;
        } else {
            r->report->ignored++;
        }
    }
}

rayo_status rayo_mesh_read_obj(mesh_text *t, mesh_builder *b,
                               rayo_mesh_report *report, rayo_error *err)
{
    obj_reader r;
    rayo_status status;
    memset(&r, 0, sizeof r);
    r.t = t;
    r.b = b;
    r.report = report;
    r.name = t->src->name;
    r.line = malloc(OBJ_LINE_MAX);
    if (r.line == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    status = read_lines(&r, err);
    free(r.line);
    free(r.vertices);
    return status;
}
