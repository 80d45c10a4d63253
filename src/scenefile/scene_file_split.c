/*
 * scene_file_split.c - a large scene file's sphere lines read on several
 * threads (scene_file_split.h).
 *
 * Why: reading a file of 100,000 spheres is mostly splitting their lines
 * into words and reading numbers, line by line, each line on its own.
 * Why the scene is the same: a record carries values only for a sphere
 * line that the parser would accept as it stands, read with the same
 * lexer (scene_lexer.c) and number reader (core/decimal.c) and checked
 * by the same rules as scene_parse_sphere (each number finite and within
 * RAYO_SCENE_MAX_NUMBER, the radius > 0, then nothing, or 'material' and
 * one more word and nothing); the material's name is looked up (once a
 * part: a name found defined stays so), and the sphere added, by the
 * parser in file order, so materials defined on
 * earlier lines are the ones found, objects are numbered in file order,
 * and the first error is the earliest line's.  Anything else is left to
 * the parser, whole.
 */
#include "scene_file_split.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../core/thread_start.h"
#include "rayo/scene_file.h"
#include "scene_lexer.h"
#include "../core/decimal.h"

typedef struct part_job {
    const char *name, *text;
    size_t begin, end;
    split_part *part;
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
    l->name = SPLIT_NO_NAME;
    return l;
}

/* The slot of the part's table that holds the name, or the empty one
 * where it would go (the table has one: it is at most half full). */
static uint32_t *name_slot(const split_part *part, const char *text,
                           size_t length)
{
    size_t mask = part->slot_capacity - 1;
    size_t k = scene_word_hash(text, length) & mask;
    for (;; k = (k + 1) & mask) {
        const split_name *n;
        if (part->slots[k] == 0)
            return &part->slots[k];
        n = &part->names[part->slots[k] - 1];
        if (n->length == length && memcmp(n->text, text, length) == 0)
            return &part->slots[k];
    }
}

/* Room for one more name: the names' array grown, and the hash table
 * doubled (every name placed again) when one more would fill it past
 * half; 0 when out of memory. */
static int reserve_name(split_part *part)
{
    size_t capacity, i;
    uint32_t *slots;
    if (part->name_count == part->name_capacity) {
        size_t more = part->name_capacity ? 2 * part->name_capacity : 16;
        split_name *grown = realloc(part->names, more * sizeof *grown);
        if (grown == NULL)
            return 0;
        part->names = grown;
        part->name_capacity = more;
    }
    if (2 * (part->name_count + 1) <= part->slot_capacity)
        return 1;
    capacity = part->slot_capacity ? 2 * part->slot_capacity : 64;
    slots = calloc(capacity, sizeof *slots);
    if (slots == NULL)
        return 0;
    free(part->slots);
    part->slots = slots;
    part->slot_capacity = capacity;
    for (i = 0; i < part->name_count; i++) {
        const split_name *n = &part->names[i];
        *name_slot(part, n->text, n->length) = (uint32_t)i + 1;
    }
    return 1;
}

/* The number of the name in the part's names, added there on its first
 * use; SPLIT_NO_NAME when out of memory (part->failed set then). */
static uint32_t part_name(split_part *part, const scene_word *word)
{
    uint32_t *slot;
    split_name *n;
    if (part->slot_capacity > 0) {
        slot = name_slot(part, word->text, word->length);
        if (*slot != 0)
            return *slot - 1;
    }
    if (!reserve_name(part)) {
        part->failed = 1;
        return SPLIT_NO_NAME;
    }
    n = &part->names[part->name_count];
    n->text = word->text;
    n->length = word->length;
    n->id = 0;
    n->found = 0;
    *name_slot(part, word->text, word->length) = (uint32_t)++part->name_count;
    return (uint32_t)(part->name_count - 1);
}

/* One number as read_number in scene_file_values.c accepts it. */
static int clean_number(scene_lexer *lx, double *value)
{
    scene_word word;
    return scene_lexer_word(lx, &word) &&
           decimal_read(word.text, word.length, value) &&
           fabs(*value) <= RAYO_SCENE_MAX_NUMBER;
}

/* The rest of a sphere line (after 'sphere') into l, if scene_parse_sphere
 * would take it as it stands (its material's name then in the part's
 * names); 0 otherwise. */
static int clean_sphere(scene_lexer *lx, split_part *part, split_line *l)
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
    if (!scene_word_is(&word, "material") || !scene_lexer_word(lx, &word) ||
        scene_lexer_more(lx))
        return 0;
    l->name = part_name(part, &word);
    return l->name != SPLIT_NO_NAME;
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
        if (scene_word_is(&word, "sphere") && clean_sphere(&lx, part, l))
            l->sphere = 1;
    }
    part->line_count = lx.line;
    return NULL;
}

/* Empties a part for the next window, keeping its arrays. */
static void part_reset(split_part *part)
{
    part->count = 0;
    part->name_count = 0;
    part->line_count = 0;
    part->failed = 0;
    if (part->slots != NULL)
        memset(part->slots, 0, part->slot_capacity * sizeof *part->slots);
}

int scene_split_read(split_set *set, const char *name, const char *text,
                     size_t length, unsigned parts)
{
    part_job jobs[64];
    size_t begin = 0;
    unsigned n = parts < 1 ? 1 : parts > 64 ? 64 : parts, i;
    if (set->count < n) {
        split_part *grown = realloc(set->parts, n * sizeof *grown);
        if (grown == NULL)
            return 0;
        memset(grown + set->count, 0, (n - set->count) * sizeof *grown);
        set->parts = grown;
        set->count = n;
    }
    for (i = 0; i < n; i++) {
        size_t end = i + 1 == n ? length : length / n * (i + 1);
        if (end < begin)
            end = begin;
        if (i + 1 < n) { /* just after the next newline */
            const char *nl = memchr(text + end, '\n', length - end);
            end = nl ? (size_t)(nl - text) + 1 : length;
        }
        part_reset(&set->parts[i]);
        jobs[i].name = name;
        jobs[i].text = text;
        jobs[i].begin = begin;
        jobs[i].end = end;
        jobs[i].part = &set->parts[i];
        begin = end;
    }
    for (i = n; i < set->count; i++) /* from a window cut in more parts */
        part_reset(&set->parts[i]);
    thread_run_each(n, read_part, jobs, sizeof *jobs);
    for (i = 0; i < n; i++)
        if (set->parts[i].failed)
            return 0;
    return 1;
}

void scene_split_free(split_set *set)
{
    size_t i;
    for (i = 0; i < set->count; i++) {
        free(set->parts[i].lines);
        free(set->parts[i].names);
        free(set->parts[i].slots);
    }
    free(set->parts);
    set->parts = NULL;
    set->count = 0;
}
