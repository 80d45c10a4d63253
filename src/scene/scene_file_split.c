/*
 * scene_file_split.c - a large scene file's sphere lines read on several
 * threads (scene_file_split.h).
 *
 * Why: reading a file of 100,000 spheres is mostly splitting their lines
 * into words and reading numbers, line by line, each line on its own.
 * Why the scene is the same: a record carries values only for a sphere
 * line that the parser would accept as it stands, read with the same
 * lexer (scene_lexer.c) and number reader (scene_number.c) and checked
 * by the same rules as parse_sphere (each number finite and within
 * RAYO_SCENE_MAX_NUMBER, the radius > 0, then nothing, or 'material' and
 * one more word and nothing); the material's name is looked up, and the
 * sphere added, by the parser in file order, so materials defined on
 * earlier lines are the ones found, objects are numbered in file order,
 * and the first error is the earliest line's.  Anything else is left to
 * the parser, whole.
 */
#include "scene_file_split.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/scene_file.h"
#include "scene_lexer.h"
#include "scene_number.h"

typedef struct part_job {
    const char *name, *text;
    size_t begin, end;
    split_part *part;
    pthread_t thread;
} part_job;

static split_line *add_line(split_part *part, const scene_lexer *lx)
{
    split_line *l;
    if (part->count == part->capacity) {
        size_t capacity = part->capacity ? 2 * part->capacity : 1024;
        split_line *grown = realloc(part->lines, capacity * sizeof *grown);
        if (grown == NULL) {
            part->failed = 1;
            return NULL;
        }
        part->lines = grown;
        part->capacity = capacity;
    }
    l = &part->lines[part->count++];
    l->offset = lx->line_start;
    l->line = (uint32_t)lx->line; /* a part holds fewer than 2^28 lines */
    l->sphere = 0;
    l->material_length = 0;
    return l;
}

/* One number as read_number in scene_file.c accepts it. */
static int clean_number(scene_lexer *lx, double *value)
{
    scene_word word;
    return scene_lexer_word(lx, &word) &&
           scene_number_read(word.text, word.length, value) &&
           fabs(*value) <= RAYO_SCENE_MAX_NUMBER;
}

/* The rest of a sphere line (after 'sphere') into l, if parse_sphere
 * would take it as it stands; 0 otherwise. */
static int clean_sphere(scene_lexer *lx, split_line *l)
{
    scene_word word;
    int i;
    for (i = 0; i < 3; i++)
        if (!clean_number(lx, &l->center[i]))
            return 0;
    if (!clean_number(lx, &l->radius) || !(l->radius > 0.0))
        return 0;
    if (!scene_lexer_word(lx, &word))
        return 1;
    if (!scene_word_is(&word, "material") || !scene_lexer_word(lx, &word))
        return 0;
    /* a line is at most RAYO_SCENE_MAX_LINE bytes */
    l->material_at = (uint32_t)(word.column - 1);
    l->material_length = (uint32_t)word.length;
    return !scene_lexer_more(lx);
}

static void *read_part(void *argument)
{
    part_job *job = argument;
    split_part *part = job->part;
    scene_lexer lx;
    scene_lexer_init(&lx, job->name, job->text, job->end, NULL);
    lx.next_line = job->begin;
    for (;;) {
        scene_word word;
        split_line *l;
        int more = 0;
        if (scene_lexer_next_line(&lx, &more) != RAYO_OK) {
            add_line(part, &lx); /* the parser will refuse it too */
            break;
        }
        if (!more)
            break;
        l = add_line(part, &lx);
        if (l == NULL)
            break;
        scene_lexer_word(&lx, &word);
        if (scene_word_is(&word, "sphere") && clean_sphere(&lx, l))
            l->sphere = 1;
    }
    part->line_count = lx.line;
    return NULL;
}

int scene_split_read(const char *name, const char *text, size_t from,
                     size_t length, unsigned parts, split_part **out,
                     size_t *count)
{
    part_job jobs[64];
    split_part *result;
    size_t begin = from;
    unsigned n = parts < 1 ? 1 : parts > 64 ? 64 : parts, i, started;
    result = calloc(n, sizeof *result);
    if (result == NULL)
        return 0;
    for (i = 0; i < n; i++) {
        size_t end =
            i + 1 == n ? length : from + (length - from) / n * (i + 1);
        if (end < begin)
            end = begin;
        if (i + 1 < n) { /* just after the next newline */
            const char *nl = memchr(text + end, '\n', length - end);
            end = nl ? (size_t)(nl - text) + 1 : length;
        }
        jobs[i].name = name;
        jobs[i].text = text;
        jobs[i].begin = begin;
        jobs[i].end = end;
        jobs[i].part = &result[i];
        begin = end;
    }
    for (started = 1; started < n; started++)
        if (pthread_create(&jobs[started].thread, NULL, read_part,
                           &jobs[started]) != 0)
            break;
    for (i = started; i < n; i++) /* those that did not start */
        read_part(&jobs[i]);
    read_part(&jobs[0]);
    for (i = 1; i < started; i++)
        pthread_join(jobs[i].thread, NULL);
    for (i = 0; i < n; i++)
        if (result[i].failed) {
            scene_split_free(result, n);
            return 0;
        }
    *out = result;
    *count = n;
    return 1;
}

void scene_split_free(split_part *parts, size_t count)
{
    size_t i;
    if (parts == NULL)
        return;
    for (i = 0; i < count; i++)
        free(parts[i].lines);
    free(parts);
}
