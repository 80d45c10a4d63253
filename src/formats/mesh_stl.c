/*
 * mesh_stl.c - STL, binary and ASCII.
 *
 * Binary, as the course's TP1 statement describes it: an 80-byte header
 * (ignored), a little-endian uint32 count n, then n records of 50 bytes:
 * the facet's normal and its three corners as little-endian IEEE-754
 * floats, and a uint16 (ignored).  The count is checked against the
 * file's size before anything is allocated for it; bytes after the last
 * record are counted, not read.  The records are decoded where they lie in
 * the source's window, straight into the mesh's arrays (a file of
 * millions of triangles is mostly this loop).  ASCII: "solid NAME", then
 * "facet normal X Y Z / outer loop / vertex X Y Z (three) / endloop /
 * endfacet" per triangle, "endsolid [NAME]".
 *
 * A corner that is not a finite number is an error; a normal that is
 * not (or is zero) is kept as (0, 0, 0) and counted, so the scene can
 * compute that facet's normal from its corners.  Not the OBJ reader.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "mesh_impl.h"
#include "rayo/lang.h"
#include "rayo/limits.h"

static float float_at(const unsigned char *p)
{
    uint32_t bits = (uint32_t)p[0] | ((uint32_t)p[1] << 8) |
                    ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
    float value;
    memcpy(&value, &bits, sizeof value);
    return value;
}

/* A normal that is not finite, or zero, becomes (0, 0, 0), counted. */
static void take_normal(float normal[3], rayo_mesh_report *report)
{
    if (!isfinite(normal[0]) || !isfinite(normal[1]) ||
        !isfinite(normal[2]) ||
        (normal[0] == 0 && normal[1] == 0 && normal[2] == 0)) {
        normal[0] = normal[1] = normal[2] = 0;
        report->zero_normals++;
    }
}

/*
 * Record i (of count) at rec, at byte at of the file, decoded straight
 * into the mesh's next slot (room reserved), which it then takes.
 */
static rayo_status take_record(mesh_builder *b, const unsigned char *rec,
                               uint64_t at, uint64_t i,
                               rayo_mesh_report *report, const char *name,
                               rayo_error *err)
{
    rayo_mesh *m = b->mesh;
    float *corners = m->corners + m->count * 9;
    float *normal = m->normals + m->count * 3;
    int k;
    for (k = 0; k < 9; k++) {
        corners[k] = float_at(rec + 12 + 4 * k);
        if (!isfinite(corners[k]))
            return rayo_error_set(
                err, RAYO_ERR_FORMAT,
                "%s: byte %llu: found %s as coordinate %d of triangle "
                "%llu's corner %d; expected a finite number",
                name, (unsigned long long)(at + 12 + 4 * k),
                isnan(corners[k]) ? "nan" : "an infinity", k % 3 + 1,
                (unsigned long long)i + 1, k / 3 + 1);
    }
    for (k = 0; k < 3; k++)
        normal[k] = float_at(rec + 4 * k);
    take_normal(normal, report);
    m->count++;
    return RAYO_OK;
}

rayo_status rayo_mesh_read_stl_binary(rayo_source *src,
                                      const unsigned char head[84],
                                      mesh_builder *b,
                                      rayo_mesh_report *report,
                                      rayo_error *err)
{
    uint32_t count = (uint32_t)head[80] | ((uint32_t)head[81] << 8) |
                     ((uint32_t)head[82] << 16) | ((uint32_t)head[83] << 24);
    uint64_t remaining = 0, need = (uint64_t)count * 50, i = 0;
    int size_known = rayo_source_remaining(src, &remaining);
    rayo_status status;
    if (count > RAYO_MAX_OBJECTS)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "%s: byte 80: found a count of %lu triangles; "
                              "expected at most %lu (2^24, the objects of a "
                              "scene)",
                              src->name, (unsigned long)count,
                              RAYO_MAX_OBJECTS);
    if (size_known && remaining < need)
        return rayo_error_set(err, RAYO_ERR_FORMAT,
                              "%s: byte 80: found a count of %lu triangles, "
                              "which need 84 + 50 x %lu = %llu bytes; "
                              "expected at most %llu triangles (the file has "
                              "%llu bytes)",
                              src->name, (unsigned long)count,
                              (unsigned long)count,
                              (unsigned long long)(84 + need),
                              (unsigned long long)(remaining / 50),
                              (unsigned long long)(84 + remaining));
    /* From a pipe, memory follows the records that arrive. */
    status = mesh_reserve(b, size_known ? count : (count < 65536 ? count
                                                                 : 65536),
                          src->name, err);
    while (status == RAYO_OK && i < count) {
        /* The whole records in the source's window, decoded where they
         * lie; a record cut by the window's end is copied out whole. */
        size_t whole = (size_t)(src->end - src->next) / 50, r;
        uint64_t at = rayo_source_offset(src);
        if (whole > count - i)
            whole = (size_t)(count - i);
        if (whole > 0) {
            status = mesh_reserve(b, whole, src->name, err);
            for (r = 0; status == RAYO_OK && r < whole; r++, i++)
                status = take_record(b, src->next + 50 * r, at + 50 * r, i,
                                     report, src->name, err);
            src->next += 50 * r;
        } else {
            unsigned char record[50];
            size_t got;
            rayo_source_read(src, record, sizeof record, &got);
            if (got != sizeof record) {
                char what[64];
                snprintf(what, sizeof what,
                         rayo_gettext(rayo_error_lang(err),
                                      "the rest of triangle %llu of %lu"),
                         (unsigned long long)i + 1, (unsigned long)count);
                return rayo_source_end_error(src, what, err);
            }
            status = mesh_reserve(b, 1, src->name, err);
            if (status == RAYO_OK)
                status = take_record(b, record, at, i, report, src->name,
                                     err);
            i++;
        }
    }
    if (status == RAYO_OK && size_known)
        report->trailing_bytes = remaining - need;
    return status;
}

/* The ASCII grammar, one expected word at a time. */
typedef struct stl_words {
    mesh_text *t;
    const char *name;
    char word[80];
    uint64_t line;
    size_t length;
} stl_words;

static int next(stl_words *w)
{
    w->length = mesh_text_word(w->t, w->word, sizeof w->word, &w->line);
    return w->length > 0;
}

/* what is the phrase expected, English (marked with this function's
 * keyword in scripts/update_pot.sh), put in in the error's language. */
static rayo_status stl_expected(const stl_words *w, const char *what,
                                rayo_error *err)
{
    if (w->length == 0) {
        if (w->t->src->read_errno != 0)
            return rayo_source_end_error(w->t->src, what, err);
        return rayo_error_set(err, RAYO_ERR_FORMAT,
                              "%s:%llu: found the end of the file; expected "
                              "%s",
                              w->name, (unsigned long long)w->line,
                              rayo_gettext(rayo_error_lang(err), what));
    }
    return rayo_error_set(err, RAYO_ERR_FORMAT,
                          "%s:%llu: found '%.40s'; expected %s", w->name,
                          (unsigned long long)w->line, w->word,
                          rayo_gettext(rayo_error_lang(err), what));
}

static rayo_status keyword(stl_words *w, const char *word, rayo_error *err)
{
    char what[40];
    if (next(w) && strcmp(w->word, word) == 0)
        return RAYO_OK;
    snprintf(what, sizeof what, "'%s'", word);
    return stl_expected(w, what, err);
}

static rayo_status stl_numbers(stl_words *w, float *to, int count,
                               const char *what, rayo_error *err)
{
    int k;
    for (k = 0; k < count; k++)
        if (!next(w) || !mesh_number(w->word, &to[k]))
            return stl_expected(w, what, err);
    return RAYO_OK;
}

rayo_status rayo_mesh_read_stl_ascii(mesh_text *t, mesh_builder *b,
                                     rayo_mesh_report *report,
                                     rayo_error *err)
{
    stl_words w;
    char name_line[4096];
    rayo_status status;
    memset(&w, 0, sizeof w);
    w.t = t;
    w.name = t->src->name;
    /* "solid" and the rest of its line, the solid's name. */
    if (mesh_text_line(t, name_line, sizeof name_line) < 0)
        return rayo_error_set(err, RAYO_ERR_FORMAT,
                              "%s:1: found a 'solid' line over %lu bytes; "
                              "expected 'solid NAME'",
                              w.name, (unsigned long)sizeof name_line - 1);
    t->line = 2;
    for (;;) {
        float corners[9], normal[3];
        int k;
        if (!next(&w))
            return stl_expected(&w, "'facet' or 'endsolid'", err);
        if (strcmp(w.word, "endsolid") == 0)
            return RAYO_OK;
        if (strcmp(w.word, "facet") != 0)
            return stl_expected(&w, "'facet' or 'endsolid'", err);
        status = keyword(&w, "normal", err);
        if (status == RAYO_OK)
            status =
                stl_numbers(&w, normal, 3, "a normal's three numbers", err);
        if (status == RAYO_OK)
            status = keyword(&w, "outer", err);
        if (status == RAYO_OK)
            status = keyword(&w, "loop", err);
        for (k = 0; k < 3 && status == RAYO_OK; k++) {
            status = keyword(&w, "vertex", err);
            if (status == RAYO_OK)
                status = stl_numbers(&w, corners + 3 * k, 3,
                                     "a vertex's three finite numbers", err);
        }
        if (status == RAYO_OK)
            status = keyword(&w, "endloop", err);
        if (status == RAYO_OK)
            status = keyword(&w, "endfacet", err);
        if (status != RAYO_OK)
            return status;
        take_normal(normal, report);
        status = mesh_push(b, corners, normal, w.name, err);
        if (status != RAYO_OK)
            return status;
    }
}
