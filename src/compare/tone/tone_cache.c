/*
 * tone_cache.c - the tone images a process compares against again and
 * again, kept with their maps: the page (web/) and `rayo grade --each`
 * compare many images with the same reference, and every gray or colour
 * comparison of a 640x480 reference renders the course's scene.  Without
 * it each comparison renders that scene again and makes the same edge and
 * window maps (tone_image_find_edges) once more.
 *
 * A hit is the very maps or render a comparison would make; callers get
 * copies, one lock guards the entries, and the cache is bounded (below).
 * Should memory run short it keeps nothing and the comparison makes what
 * it needs itself.
 */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "tone_impl.h"

/*
 * An entry is a copy of a tone image (its samples, and its maps when
 * they were made) with, for the course's render, the exercise it is, and
 * for a reference, which course scene it shows once that was found.  Maps
 * are found by the samples themselves (size, channels and every byte
 * compared, and the radius and levels they were made for); the course's
 * render by its exercise and channels (rayo_course_render with the
 * default options: the same image every time).  Callers get copies, so
 * nothing they hold changes under them; the lock (threads of `rayo grade
 * -j`) is held only to look up and copy, never while maps are made.
 * Bounded: at most CACHE_ENTRIES entries, an image of more than
 * CACHE_ENTRY_BYTES with its maps is never kept, the least recently used
 * entry goes first.
 *
 * The student model's render of each of the course's mistakes is kept
 * apart, as far down as a comparison made it (tone_diagnose.c renders a
 * mistake a band of rows at a time and stops once it is ruled out): a
 * slot per exercise and mistake, under the same lock, about 15 MB when
 * every mistake of EJ2 and EJ3 is kept whole.  What is kept stays
 * reachable until rayo_compare_release_cache (which the command calls
 * before it exits) or the process's end.
 */

#define CACHE_ENTRIES 4
/* 640 x 480 RGB with its maps is about 3.4 MB. */
#define CACHE_ENTRY_BYTES (8u << 20)

typedef struct cache_entry {
    int used;
    int course;        /* the exercise whose render it is, else -1 */
    unsigned long age; /* when last looked up or kept */
    tone_image t;      /* owned copies */
    /* the course scene this image shows (tone_diagnose.c's
       detect_course), known for one radius, levels and key */
    int detected, detected_course, detected_radius, detected_key;
    unsigned detected_levels;
} cache_entry;

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
static cache_entry entries[CACHE_ENTRIES];
static unsigned long clock_now;

static size_t samples_of(const tone_image *t)
{
    return (size_t)t->width * t->height * t->channels;
}

/* The bytes an image and its maps take (SIZE_MAX when too many). */
static size_t bytes_of(const tone_image *t)
{
    size_t pixels = (size_t)t->width * t->height;
    if (t->channels == 0 || pixels > SIZE_MAX / 8 / t->channels)
        return SIZE_MAX;
    return 3 * pixels * t->channels + 2 * pixels;
}

static unsigned char *copy_of(const unsigned char *v, size_t n)
{
    unsigned char *c;
    if (v == NULL || n == 0)
        return NULL;
    c = malloc(n);
    if (c != NULL)
        memcpy(c, v, n);
    return c;
}

static int has_maps(const tone_image *t)
{
    return t->near != NULL && t->slope != NULL && t->lo != NULL &&
           t->hi != NULL;
}

/* Copies from's maps into to (whose own are dropped); 0 when out of
   memory (to then has none). */
static int copy_maps(tone_image *to, const tone_image *from)
{
    size_t pixels = (size_t)from->width * from->height;
    tone_image_drop_maps(to);
    to->near = copy_of(from->near, pixels);
    to->slope = copy_of(from->slope, pixels);
    to->lo = copy_of(from->lo, samples_of(from));
    to->hi = copy_of(from->hi, samples_of(from));
    if (!has_maps(to)) {
        tone_image_drop_maps(to);
        return 0;
    }
    to->near_radius = from->near_radius;
    to->near_levels = from->near_levels;
    return 1;
}

static int same_samples(const tone_image *a, const tone_image *b)
{
    return a->width == b->width && a->height == b->height &&
           a->channels == b->channels && a->v != NULL && b->v != NULL &&
           memcmp(a->v, b->v, samples_of(a)) == 0;
}

/* The entry holding t's samples, else NULL (lock held). */
static cache_entry *entry_of(const tone_image *t)
{
    size_t i;
    for (i = 0; i < CACHE_ENTRIES; i++)
        if (entries[i].used && same_samples(&entries[i].t, t))
            return &entries[i];
    return NULL;
}

/* An entry to fill: a free one, else the least recently used, emptied
   (lock held). */
static cache_entry *free_entry(void)
{
    cache_entry *oldest = &entries[0];
    size_t i;
    for (i = 0; i < CACHE_ENTRIES; i++) {
        if (!entries[i].used)
            return &entries[i];
        if (entries[i].age < oldest->age)
            oldest = &entries[i];
    }
    tone_image_free(&oldest->t);
    oldest->used = 0;
    return oldest;
}

/* A new entry holding a copy of t's samples (lock held); NULL when out
   of memory. */
static cache_entry *new_entry(const tone_image *t, int course)
{
    cache_entry *e = free_entry();
    memset(&e->t, 0, sizeof e->t);
    e->t.v = copy_of(t->v, samples_of(t));
    if (e->t.v == NULL)
        return NULL;
    e->t.width = t->width;
    e->t.height = t->height;
    e->t.channels = t->channels;
    e->course = course;
    e->detected = 0;
    e->used = 1;
    return e;
}

int tone_cache_find_maps(tone_image *t, int radius, unsigned levels)
{
    cache_entry *e;
    int found = 0;
    if (bytes_of(t) > CACHE_ENTRY_BYTES)
        return 0;
    pthread_mutex_lock(&lock);
    e = entry_of(t);
    if (e != NULL && has_maps(&e->t) && e->t.near_radius == radius &&
        e->t.near_levels == levels) {
        e->age = ++clock_now;
        found = copy_maps(t, &e->t);
    }
    pthread_mutex_unlock(&lock);
    return found;
}

void tone_cache_keep_maps(const tone_image *t)
{
    cache_entry *e;
    if (!has_maps(t) || bytes_of(t) > CACHE_ENTRY_BYTES)
        return;
    pthread_mutex_lock(&lock);
    e = entry_of(t);
    if (e == NULL)
        e = new_entry(t, -1);
    if (e != NULL) {
        e->age = ++clock_now;
        copy_maps(&e->t, t); /* out of memory: the samples alone */
    }
    pthread_mutex_unlock(&lock);
}

int tone_cache_find_course(int course, unsigned channels, tone_image *t)
{
    size_t i;
    int found = 0;
    memset(t, 0, sizeof *t);
    pthread_mutex_lock(&lock);
    for (i = 0; i < CACHE_ENTRIES && !found; i++) {
        cache_entry *e = &entries[i];
        if (!e->used || e->course != course || e->t.channels != channels)
            continue;
        e->age = ++clock_now;
        t->v = copy_of(e->t.v, samples_of(&e->t));
        if (t->v != NULL) {
            t->width = e->t.width;
            t->height = e->t.height;
            t->channels = e->t.channels;
            found = 1;
        }
    }
    pthread_mutex_unlock(&lock);
    return found;
}

void tone_cache_keep_course(int course, const tone_image *t)
{
    cache_entry *e;
    if (bytes_of(t) > CACHE_ENTRY_BYTES)
        return;
    pthread_mutex_lock(&lock);
    e = entry_of(t);
    if (e == NULL) {
        e = new_entry(t, course);
        if (e != NULL && has_maps(t))
            copy_maps(&e->t, t);
    }
    if (e != NULL) {
        e->course = course;
        e->age = ++clock_now;
    }
    pthread_mutex_unlock(&lock);
}

int tone_cache_find_detected(const tone_image *t, int radius,
                             unsigned levels, int key, int *course)
{
    cache_entry *e;
    int found = 0;
    if (bytes_of(t) > CACHE_ENTRY_BYTES)
        return 0;
    pthread_mutex_lock(&lock);
    e = entry_of(t);
    if (e != NULL && e->detected && e->detected_radius == radius &&
        e->detected_levels == levels && e->detected_key == key) {
        e->age = ++clock_now;
        *course = e->detected_course;
        found = 1;
    }
    pthread_mutex_unlock(&lock);
    return found;
}

void tone_cache_keep_detected(const tone_image *t, int radius,
                              unsigned levels, int key, int course)
{
    cache_entry *e;
    if (bytes_of(t) > CACHE_ENTRY_BYTES)
        return;
    pthread_mutex_lock(&lock);
    e = entry_of(t); /* only with the image's entry, made for its maps */
    if (e != NULL) {
        e->detected = 1;
        e->detected_course = course;
        e->detected_radius = radius;
        e->detected_levels = levels;
        e->detected_key = key;
    }
    pthread_mutex_unlock(&lock);
}

/* The student model's renders of each course mistake, as far down as
   a comparison needed them: rows[course][mistake] of them made. */
#define CACHE_COURSES 3
#define CACHE_MISTAKES 32
typedef struct cache_rows {
    unsigned char *v; /* width x height x channels, rows 0..rows-1 set */
    uint32_t width, height, rows;
    unsigned channels;
} cache_rows;
static cache_rows mistakes[CACHE_COURSES][CACHE_MISTAKES];

uint32_t tone_cache_find_rows(int course, int mistake, tone_image *t)
{
    cache_rows *c;
    uint32_t rows = 0;
    if (course < 0 || course >= CACHE_COURSES || mistake < 0 ||
        mistake >= CACHE_MISTAKES)
        return 0;
    pthread_mutex_lock(&lock);
    c = &mistakes[course][mistake];
    if (c->v != NULL && c->width == t->width && c->height == t->height &&
        c->channels == t->channels) {
        rows = c->rows;
        memcpy(t->v, c->v, (size_t)rows * t->width * t->channels);
    }
    pthread_mutex_unlock(&lock);
    return rows;
}

void tone_cache_keep_rows(int course, int mistake, const tone_image *t,
                          uint32_t rows)
{
    cache_rows *c;
    size_t row = (size_t)t->width * t->channels;
    if (course < 0 || course >= CACHE_COURSES || mistake < 0 ||
        mistake >= CACHE_MISTAKES || rows > t->height ||
        bytes_of(t) > CACHE_ENTRY_BYTES)
        return;
    pthread_mutex_lock(&lock);
    c = &mistakes[course][mistake];
    if (c->v != NULL && (c->width != t->width || c->height != t->height ||
                         c->channels != t->channels)) {
        free(c->v);
        memset(c, 0, sizeof *c);
    }
    if (c->v == NULL) {
        c->v = malloc(row * t->height);
        c->width = t->width;
        c->height = t->height;
        c->channels = t->channels;
        c->rows = 0;
    }
    if (c->v != NULL && rows > c->rows) {
        memcpy(c->v + c->rows * row, t->v + c->rows * row,
               (rows - c->rows) * row);
        c->rows = rows;
    }
    pthread_mutex_unlock(&lock);
}

void rayo_compare_release_cache(void)
{
    size_t i, j;
    pthread_mutex_lock(&lock);
    for (i = 0; i < CACHE_ENTRIES; i++) {
        if (entries[i].used)
            tone_image_free(&entries[i].t);
        entries[i].used = 0;
    }
    for (i = 0; i < CACHE_COURSES; i++)
        for (j = 0; j < CACHE_MISTAKES; j++) {
            free(mistakes[i][j].v);
            memset(&mistakes[i][j], 0, sizeof mistakes[i][j]);
        }
    pthread_mutex_unlock(&lock);
    tone_scene_release_cache();
}

