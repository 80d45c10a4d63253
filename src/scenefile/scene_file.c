/*
 * scene_file.c - the grammar of scene files (docs/scene-format.md): one
 * statement per line, a keyword and its values, each statement read by
 * its own function (scene_file_settings.c, scene_file_objects.c,
 * scene_file_mesh.c) into calls on the scene (scene.h) and a camera
 * description (camera_spec.h).  Here: the keywords, the reader that
 * takes a file's text a window at a time (scene_file_impl.h), and the
 * spheres a long window's parts read ahead on several threads
 * (scene_file_split.c), taken in file order and added in batches
 * (rayo_scene_add_spheres).  Reading the file from disk is
 * scene_file_load.c's job.
 */
#include "scene_file_parser.h"

#include <stdlib.h>
#include <string.h>

#include "rayo/cpu.h"
#include "scene_file_impl.h"

/* ---- statements ------------------------------------------------------ */

typedef struct statement {
    const char *keyword;
    rayo_status (*parse)(parser *p);
} statement;

/* Spheres first: a large scene is mostly their lines. */
static const statement statements[] = {
    {"sphere", scene_parse_sphere},
    {"camera", scene_parse_camera},
    {"shade", scene_parse_shade},
    {"samples", scene_parse_samples},
    {"depth", scene_parse_depth},
    {"background", scene_parse_background},
    {"ambient", scene_parse_ambient},
    {"light", scene_parse_light},
    {"material", scene_parse_material},
    {"plane", scene_parse_plane},
    {"triangle", scene_parse_triangle},
    {"mesh", scene_parse_mesh},
};
#define STATEMENT_COUNT (sizeof statements / sizeof statements[0])

static rayo_status parse_statement(parser *p)
{
    scene_word word;
    char text[WORD_SHOW + 32];
    size_t i;
    scene_lexer_word(&p->lx, &word);
    for (i = 0; i < STATEMENT_COUNT; i++)
        if (scene_word_is(&word, statements[i].keyword))
            return statements[i].parse(p);
    return scene_lexer_fail(&p->lx, word.column, RAYO_ERR_FORMAT,
                            "unknown keyword %s; expected camera, shade, "
                            "samples, depth, background, ambient, light, "
                            "material, sphere, plane, triangle or mesh",
                            scene_quoted(&word, text, sizeof text));
}

static void file_defaults(rayo_scene_file *file)
{
    file->scene = NULL;
    rayo_camera_spec_init(&file->camera);
    file->camera_given = 0;
    file->shade = RAYO_SHADE_PHONG;
    file->shade_given = 0;
    file->samples = 1;
    file->depth = 5;
    rayo_tp1_reading_init(&file->tp1);
    file->mesh_triangles = 0;
    file->mesh_left_out = 0;
    file->mesh_ignored = 0;
}

static rayo_status parse_all(parser *p)
{
    for (;;) {
        int more = 0;
        rayo_status status = scene_lexer_next_line(&p->lx, &more);
        if (status != RAYO_OK || !more)
            return status;
        status = parse_statement(p);
        if (status != RAYO_OK)
            return status;
    }
}

/* Reads the line at offset, numbered line, as parse_all does. */
static rayo_status parse_line_at(parser *p, size_t offset,
                                 unsigned long line)
{
    int more = 0;
    rayo_status status;
    p->lx.next_line = offset;
    p->lx.line = line - 1;
    status = scene_lexer_next_line(&p->lx, &more);
    if (status != RAYO_OK || !more)
        return status;
    return parse_statement(p);
}

/* The material of a sphere read ahead (scene_file_split.c), looked up
 * by name once a part (names are never defined twice, so a name found
 * stays found): 1 with *id, or 0 when no earlier line defines it (the
 * line is then read again, to say so). */
static int read_material(const parser *p, split_part *part,
                         const split_line *l, unsigned *id)
{
    split_name *name;
    *id = 0;
    if (l->name == SPLIT_NO_NAME)
        return 1;
    name = &part->names[l->name];
    if (!name->found) {
        const material_name *m = scene_find_name(p, name->text, name->length);
        if (m == NULL)
            return 0;
        name->id = m->id;
        name->found = 1;
    }
    *id = name->id;
    return 1;
}

/*
 * Adds the batch, the spheres of the part's lines from `first` on; when
 * the scene refuses it (the object limit, memory), nothing is added and
 * those lines are read one at a time as parse_all reads them, which says
 * which line fails.
 */
static rayo_status add_batch(parser *p, const split_part *part, size_t first)
{
    size_t j, count = p->batch_count;
    rayo_status status = RAYO_OK;
    p->batch_count = 0;
    if (count == 0 ||
        rayo_scene_add_spheres(p->file->scene, p->batch, p->batch_material,
                               count, NULL) == RAYO_OK)
        return RAYO_OK;
    for (j = first; j < first + count && status == RAYO_OK; j++)
        status = parse_line_at(p, part->lines[j].offset,
                               p->base + part->lines[j].line);
    return status;
}

/*
 * Every line of the window's parts, in order, numbered from p->base: a
 * sphere read ahead joins the batch, added when full and before any
 * other line, which is read as parse_all reads it; so the objects come
 * in file order.
 */
static rayo_status take_parts(parser *p)
{
    size_t i, j;
    for (i = 0; i < p->split.count; i++) {
        split_part *part = &p->split.parts[i];
        size_t first = 0;
        rayo_status status = RAYO_OK;
        for (j = 0; j < part->count && status == RAYO_OK; j++) {
            const split_line *l = &part->lines[j];
            unsigned id;
            if (l->sphere && read_material(p, part, l, &id)) {
                rayo_sphere *s = &p->batch[p->batch_count];
                if (p->batch_count == 0)
                    first = j;
                s->center = rayo_vec3_make(l->center[0], l->center[1],
                                           l->center[2]);
                s->radius = l->radius;
                p->batch_material[p->batch_count++] = id;
                if (p->batch_count == SPHERE_BATCH)
                    status = add_batch(p, part, first);
            } else {
                status = add_batch(p, part, first);
                if (status == RAYO_OK)
                    status = parse_line_at(p, l->offset, p->base + l->line);
            }
        }
        if (status == RAYO_OK)
            status = add_batch(p, part, first);
        if (status != RAYO_OK)
            return status;
        p->base += part->line_count;
    }
    return RAYO_OK;
}

/* ---- the reader: a file's text, a window at a time ------------------- */

struct scene_reader {
    parser p;
};

rayo_status scene_reader_new(scene_reader **result, rayo_scene_file *file,
                             const char *name, unsigned threads,
                             rayo_error *err)
{
    scene_reader *r;
    rayo_status status;
    file_defaults(file);
    *result = NULL;
    r = calloc(1, sizeof *r);
    if (r == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "%s: out of memory reading the scene", name);
    r->p.file = file;
    r->p.parts = threads ? threads : rayo_cpu_count();
    scene_lexer_init(&r->p.lx, name, "", 0, err);
    status = rayo_scene_create(&file->scene, err);
    if (status != RAYO_OK) {
        free(r);
        return status;
    }
    *result = r;
    return RAYO_OK;
}

/*
 * The window's lines, continuing the file: on several threads when it
 * is long enough (scene_file_split.h), then taken in file order; on one
 * when it is short, or when the parts cannot be made (out of memory).
 */
rayo_status scene_reader_take(scene_reader *r, const char *text,
                              size_t length)
{
    parser *p = &r->p;
    rayo_status status;
    scene_lexer_init(&p->lx, p->lx.name, text, length, p->lx.err);
    if (p->parts > 1 && length >= SCENE_SPLIT_MIN_BYTES &&
        scene_split_read(&p->split, p->lx.name, text, length, p->parts))
        return take_parts(p);
    p->lx.line = p->base;
    status = parse_all(p);
    p->base = p->lx.line;
    return status;
}

rayo_status scene_reader_end(scene_reader *r, rayo_status status)
{
    if (r == NULL)
        return status;
    scene_split_free(&r->p.split);
    free(r->p.names);
    free(r->p.slots);
    if (status != RAYO_OK)
        rayo_scene_file_free(r->p.file);
    free(r);
    return status;
}

rayo_status rayo_scene_file_parse(rayo_scene_file *file, const char *name,
                                  const char *text, size_t length,
                                  rayo_error *err)
{
    return rayo_scene_file_parse_threads(file, name, text, length, 0, err);
}

/* Whole lines of the text from `from`: about SCENE_WINDOW bytes, to just
 * after a newline (or the text's end). */
static size_t window_end(const char *text, size_t from, size_t length)
{
    const char *nl;
    if (length - from <= SCENE_WINDOW)
        return length;
    nl = memchr(text + from + SCENE_WINDOW, '\n',
                length - from - SCENE_WINDOW);
    return nl ? (size_t)(nl - text) + 1 : length;
}

rayo_status scene_file_read_text(rayo_scene_file *file, const char *name,
                                 const char *text, size_t length,
                                 unsigned threads, rayo_error *err)
{
    scene_reader *r;
    size_t from = 0;
    rayo_status status = scene_reader_new(&r, file, name, threads, err);
    if (status != RAYO_OK)
        return status;
    /* One window when it would not be split: the lexer takes any text. */
    if (r->p.parts < 2)
        status = scene_reader_take(r, text, length);
    else
        while (status == RAYO_OK && from < length) {
            size_t end = window_end(text, from, length);
            status = scene_reader_take(r, text + from, end - from);
            from = end;
        }
    return scene_reader_end(r, status);
}

rayo_status rayo_scene_file_parse_threads(rayo_scene_file *file,
                                          const char *name, const char *text,
                                          size_t length, unsigned threads,
                                          rayo_error *err)
{
    rayo_status status =
        scene_file_read_text(file, name, text, length, threads, err);
    if (status == RAYO_OK)
        status = scene_file_prepare(file, threads, err);
    return status;
}

rayo_status scene_file_prepare(rayo_scene_file *file, unsigned threads,
                               rayo_error *err)
{
    rayo_status status =
        rayo_scene_prepare_threads(file->scene, threads, err);
    if (status != RAYO_OK)
        rayo_scene_file_free(file);
    return status;
}

void rayo_scene_file_free(rayo_scene_file *file)
{
    if (file == NULL)
        return;
    rayo_scene_free(file->scene);
    file->scene = NULL;
}
