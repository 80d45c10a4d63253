/*
 * t_scene_split.c - a large scene file read on several threads
 * (scene_file_split.c) gives the scene, and the error, it gives on one.
 *
 * Texts over the 1 MiB threshold mix every statement: materials defined
 * between the spheres that use them, spheres with and without materials,
 * planes, triangles, lights, comments, blank lines, CRLF endings, and
 * sphere lines the fast reader must leave to the parser (long numbers,
 * hex-looking words, an extra word, numbers out of range).  Each is read
 * on 1, 2, 3 and 7 threads: every object (kind, number, shape, material),
 * material and light must be the same bytes, and the camera and settings
 * equal.  Then errors are planted early, late and right at the places
 * the text is cut, of every kind (a bad number, an unknown material, a
 * material used before its line, a second camera, a NUL byte, a line too
 * long, a bad keyword): the status and the message (file, line, column)
 * must be the one-thread ones.  Each text is also written to a file and
 * loaded (1 MiB windows of whole lines, scene_file_load.c) on 1, 2, 3 and
 * 7 threads: the same scene, the same error.  A text of many windows
 * gets errors either side of the cuts, lines across them and a line
 * longer than a window.  And the batches the spheres read ahead are
 * added in (rayo_scene_add_spheres) give the bytes that one add at a
 * time gives, and are refused whole, with one add's message.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "rayo.h"
#include "tap.h"

#include "../../src/scene/scene_impl.h"
#include "../../src/scenefile/scene_file_impl.h"
#include "../../src/scenefile/scene_file_split.h"

typedef struct text {
    char *data;
    size_t length, capacity;
} text;

static void add(text *t, const char *s)
{
    size_t n = strlen(s);
    if (t->length + n + 1 > t->capacity) {
        t->capacity = 2 * (t->length + n + 1);
        t->data = realloc(t->data, t->capacity);
        if (t->data == NULL)
            abort();
    }
    memcpy(t->data + t->length, s, n + 1);
    t->length += n;
}

static uint64_t next64(uint64_t *state)
{
    uint64_t z = (*state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static double unit(uint64_t *state)
{
    return (double)(next64(state) >> 11) / 9007199254740992.0;
}

/* Every kind of line, about 62 bytes a line. */
static text make_scene(uint64_t seed, int lines)
{
    text t = {NULL, 0, 0};
    uint64_t s = seed;
    char line[512];
    int i, materials = 0;
    add(&t, "# a large scene\ncamera size 64 48 fov 60 origin 0 1 -5\n");
    add(&t, "shade phong\nambient 0.1\nlight point 0 10 0 color 0.8\n");
    for (i = 0; i < lines; i++) {
        unsigned k = (unsigned)(next64(&s) % 100);
        if (k < 2 || materials == 0) {
            snprintf(line, sizeof line,
                     "material m%d color %.3f %.3f %.3f ks 0.2\n", materials,
                     unit(&s), unit(&s), unit(&s));
            materials++;
        } else if (k < 4) {
            snprintf(line, sizeof line, "plane 0 %.17g 0 0 1 0\n",
                     -1.0 - unit(&s));
        } else if (k < 6) {
            snprintf(line, sizeof line,
                     "triangle %.17g 0 0  0 %.17g 0  0 0 1 material m%d\n",
                     1.0 + unit(&s), 1.0 + unit(&s),
                     (int)(next64(&s) % (unsigned)materials));
        } else if (k < 8) {
            snprintf(line, sizeof line, "%s\n",
                     k == 6 ? "# a comment" : "   ");
        } else if (k < 9) {
            snprintf(line, sizeof line,
                     "sphere 1.00000000000000000000000001 2 3 0.5\r\n");
        } else if (k < 10) {
            snprintf(line, sizeof line,
                     "sphere\t%.17g %.17g %.17g %.17g # trailing\n",
                     unit(&s) * 20 - 10, unit(&s), unit(&s) * 30,
                     0.01 + unit(&s));
        } else if (k < 11) {
            snprintf(line, sizeof line, "light directional 1 1 %.5f\n",
                     unit(&s));
        } else {
            snprintf(line, sizeof line,
                     "sphere %.17g %.17g %.17g %.17g material m%d\n",
                     unit(&s) * 20 - 10, unit(&s), unit(&s) * 30,
                     0.01 + unit(&s),
                     (int)(next64(&s) % (unsigned)materials));
        }
        add(&t, line);
    }
    add(&t, "sphere 0 0 0 1"); /* no newline at the end */
    return t;
}

static int same_scene(const rayo_scene_file *a, const rayo_scene_file *b)
{
    const rayo_scene *x = a->scene, *y = b->scene;
    size_t i;
    if (x->object_count != y->object_count ||
        x->sphere_count != y->sphere_count ||
        x->plane_count != y->plane_count ||
        x->triangle_count != y->triangle_count ||
        x->material_count != y->material_count ||
        x->light_count != y->light_count)
        return 0;
    if (memcmp(x->objects, y->objects, x->object_count * sizeof *x->objects) ||
        memcmp(x->spheres, y->spheres, x->sphere_count * sizeof *x->spheres) ||
        memcmp(x->planes, y->planes, x->plane_count * sizeof *x->planes) ||
        memcmp(x->triangles, y->triangles,
               x->triangle_count * sizeof *x->triangles) ||
        memcmp(x->materials, y->materials,
               x->material_count * sizeof *x->materials))
        return 0;
    for (i = 0; i < x->light_count; i++)
        if (x->lights[i].kind != y->lights[i].kind ||
            memcmp(&x->lights[i].vector, &y->lights[i].vector,
                   sizeof x->lights[i].vector) ||
            memcmp(&x->lights[i].color, &y->lights[i].color,
                   sizeof x->lights[i].color))
            return 0;
    return a->camera_given == b->camera_given &&
           a->camera.width == b->camera.width &&
           a->camera.height == b->camera.height &&
           a->shade == b->shade && a->samples == b->samples &&
           a->depth == b->depth;
}

/* The text as the file big.scene in the current folder (a temporary
 * one, made by main), which the loader reads a window at a time. */
static void write_file(const text *t)
{
    FILE *out = fopen("big.scene", "wb");
    if (out == NULL || fwrite(t->data, 1, t->length, out) != t->length ||
        fclose(out) != 0)
        abort();
}

static const unsigned thread_counts[] = {2, 3, 7};
#define THREAD_COUNTS (sizeof thread_counts / sizeof thread_counts[0])

static void check_same(const char *name, const text *t)
{
    rayo_scene_file one, many;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    size_t i;
    if (rayo_scene_file_parse_threads(&one, "big.scene", t->data, t->length,
                                      1, &err) != RAYO_OK) {
        ok(0, "%s: one thread reads it", name);
        printf("# %.200s\n", err.message);
        return;
    }
    ok(one.scene->sphere_count > 15000 && one.scene->plane_count > 0 &&
           one.scene->triangle_count > 0 && one.scene->material_count > 100,
       "%s: %lu bytes, %lu spheres, %lu materials", name,
       (unsigned long)t->length, (unsigned long)one.scene->sphere_count,
       (unsigned long)one.scene->material_count);
    for (i = 0; i < THREAD_COUNTS; i++) {
        int good = rayo_scene_file_parse_threads(&many, "big.scene", t->data,
                                                 t->length, thread_counts[i],
                                                 &err) == RAYO_OK;
        ok(good && same_scene(&one, &many),
           "%s: %u threads read the same scene", name, thread_counts[i]);
        if (good)
            rayo_scene_file_free(&many);
    }
    /* from the file: windows cut where the buffer's last line ends */
    write_file(t);
    for (i = 0; i <= THREAD_COUNTS; i++) {
        unsigned threads = i == 0 ? 1 : thread_counts[i - 1];
        int good = rayo_scene_file_load_threads(&many, "big.scene", threads,
                                                &err) == RAYO_OK;
        ok(good && same_scene(&one, &many),
           "%s: the file on %u threads, the same scene", name, threads);
        if (good)
            rayo_scene_file_free(&many);
        else
            printf("#   %.200s\n", err.message);
    }
    rayo_scene_file_free(&one);
}

/* The text with the line holding byte `at` replaced by bad (a line
 * without its newline; "<NUL>" at its end stands for a NUL byte). */
static text plant(const text *t, size_t at, const char *bad)
{
    text u = {NULL, 0, 0};
    size_t start = at, end = at;
    char *head;
    while (start > 0 && t->data[start - 1] != '\n')
        start--;
    while (end < t->length && t->data[end] != '\n')
        end++;
    head = malloc(start + 1);
    if (head == NULL)
        abort();
    memcpy(head, t->data, start);
    head[start] = '\0';
    add(&u, head);
    free(head);
    add(&u, bad);
    if (strstr(bad, "<NUL>") != NULL) /* the '<' becomes a NUL byte */
        u.data[u.length - 5] = '\0';
    add(&u, t->data + end);
    return u;
}

static void check_error(const char *name, const text *t)
{
    rayo_scene_file f;
    rayo_error one = RAYO_ERROR_INIT(RAYO_LANG_EN), many = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status s1, s;
    size_t i;
    s1 = rayo_scene_file_parse_threads(&f, "big.scene", t->data, t->length, 1,
                                       &one);
    if (s1 == RAYO_OK)
        rayo_scene_file_free(&f);
    ok(s1 != RAYO_OK, "%s: refused on one thread", name);
    if (s1 != RAYO_OK)
        printf("# %s\n", one.message);
    for (i = 0; i < THREAD_COUNTS; i++) {
        s = rayo_scene_file_parse_threads(&f, "big.scene", t->data, t->length,
                                          thread_counts[i], &many);
        if (s == RAYO_OK)
            rayo_scene_file_free(&f);
        ok(s == s1 && s != RAYO_OK && strcmp(one.message, many.message) == 0,
           "%s: %u threads: the same status and message", name,
           thread_counts[i]);
        if (s != s1 || (s != RAYO_OK && strcmp(one.message, many.message)))
            printf("#   got '%s'\n", s == RAYO_OK ? "ok" : many.message);
    }
    write_file(t);
    for (i = 0; i <= THREAD_COUNTS; i++) {
        unsigned threads = i == 0 ? 1 : thread_counts[i - 1];
        s = rayo_scene_file_load_threads(&f, "big.scene", threads, &many);
        if (s == RAYO_OK)
            rayo_scene_file_free(&f);
        ok(s == s1 && s != RAYO_OK && strcmp(one.message, many.message) == 0,
           "%s: the file on %u threads: the same status and message", name,
           threads);
        if (s != s1 || (s != RAYO_OK && strcmp(one.message, many.message)))
            printf("#   got '%s'\n", s == RAYO_OK ? "ok" : many.message);
    }
}

/* A few spheres and their materials for check_add_spheres. */
#define BATCH 5
static const rayo_sphere batch[BATCH] = {
    {{1, 2, 3}, 0.5}, {{-1, 0.25, 7}, 2}, {{0, 0, 0}, 1e-3},
    {{1e6, -3, 2}, 40}, {{0.1, 0.2, 0.3}, 0.4}};
static const unsigned batch_materials[BATCH] = {1, 0, 2, 2, 1};

/* A scene with materials 1 and 2 and a plane (object 0). */
static rayo_scene *batch_scene(void)
{
    rayo_scene *scene;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_material m = {{0.5, 0.5, 0.5}, 1, 1, 0, 0, 0};
    unsigned id;
    if (rayo_scene_create(&scene, &err) != RAYO_OK ||
        rayo_scene_add_material(scene, &m, &id, &err) != RAYO_OK ||
        rayo_scene_add_material(scene, &m, &id, &err) != RAYO_OK ||
        rayo_scene_add_plane(scene, rayo_vec3_make(0, -1, 0),
                             rayo_vec3_make(0, 1, 0), 0, &err) != RAYO_OK)
        abort();
    return scene;
}

/* The spheres added in batches (rayo_scene_add_spheres, which the
 * reader uses) give the bytes one add at a time gives; a batch with one
 * sphere refused is refused whole, with the message one add gives it. */
static void check_add_spheres(void)
{
    rayo_scene *one = batch_scene(), *all = batch_scene();
    rayo_error e1 = RAYO_ERROR_INIT(RAYO_LANG_EN), e2 = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_sphere bad[BATCH];
    rayo_status s1, s2;
    unsigned materials[BATCH];
    size_t i, count, capacity;
    for (i = 0; i < BATCH; i++)
        rayo_scene_add_sphere_material(one, batch[i].center, batch[i].radius,
                                       batch_materials[i], &e1);
    for (i = 0; i < BATCH; i++)
        rayo_scene_add_sphere(one, batch[i].center, batch[i].radius, &e1);
    s1 = rayo_scene_add_spheres(all, batch, batch_materials, BATCH, &e2);
    s2 = rayo_scene_add_spheres(all, batch, NULL, BATCH, &e2);
    ok(s1 == RAYO_OK && s2 == RAYO_OK && one->object_count == 11 &&
           all->object_count == 11 && all->sphere_count == 10 &&
           memcmp(one->objects, all->objects,
                  11 * sizeof *one->objects) == 0 &&
           memcmp(one->spheres, all->spheres,
                  10 * sizeof *one->spheres) == 0 &&
           all->spheres[0].object == 1 && all->spheres[0].material == 1 &&
           all->spheres[9].object == 10 && all->spheres[9].material == 0 &&
           all->objects[10].kind == RAYO_OBJECT_SPHERE &&
           all->objects[10].index == 9,
       "two batches of spheres: the bytes of ten adds, in order");
    ok(rayo_scene_add_spheres(all, batch, NULL, 0, &e2) == RAYO_OK &&
           all->object_count == 11,
       "an empty batch adds nothing");

    memcpy(bad, batch, sizeof bad);
    bad[3].radius = -2;
    bad[4].center.x = 1.0 / 0.0;
    count = all->object_count;
    s1 = rayo_scene_add_sphere(one, bad[3].center, bad[3].radius, &e1);
    s2 = rayo_scene_add_spheres(all, bad, NULL, BATCH, &e2);
    ok(s1 == RAYO_ERR_INVALID && s2 == s1 &&
           strcmp(e1.message, e2.message) == 0 &&
           strcmp(e2.message, "sphere radius -2 is not accepted; expected "
                              "a finite number > 0") == 0 &&
           all->object_count == count && all->sphere_count == 10,
       "a batch with a bad radius: refused whole, with its message");
    memcpy(materials, batch_materials, sizeof materials);
    materials[1] = 3;
    s1 = rayo_scene_add_sphere_material(one, batch[1].center,
                                        batch[1].radius, 3, &e1);
    s2 = rayo_scene_add_spheres(all, batch, materials, BATCH, &e2);
    ok(s1 == RAYO_ERR_INVALID && s2 == s1 &&
           strcmp(e1.message, e2.message) == 0 &&
           all->object_count == count,
       "a batch with an unknown material: refused whole (%.60s)",
       e2.message);

    /* The object limit, without the memory: the count is set just
     * below it (the arrays are not touched, as nothing is added). */
    capacity = all->object_capacity;
    all->object_count = RAYO_MAX_OBJECTS - 2;
    s2 = rayo_scene_add_spheres(all, batch, NULL, 3, &e2);
    ok(s2 == RAYO_ERR_LIMIT &&
           all->object_count == RAYO_MAX_OBJECTS - 2 &&
           all->object_capacity == capacity && all->sphere_count == 10,
       "a batch past the object limit: refused, nothing changed (%.60s)",
       e2.message);
    all->object_count = count;
    rayo_scene_free(one);
    rayo_scene_free(all);
}

int main(void)
{
    text t = make_scene(2026, 24000);
    static const char *const bad[] = {
        "sphere 1 2 x 4",
        "sphere 1 2 3 4 material nowhere",
        "sphere 1 2 3 4 material m99999",
        "sphere 1 2 3 -4",
        "sphere 1 2 3 2e12",
        "camera size 10 10",
        "sphere 1 2 3 4 <NUL>",
        "bogus 1 2 3",
        "sphere 1 2 3 4 material m1 extra",
        "material m0 color 1 1 1",
    };
    /* where: early, at the cuts of 2, 3 and 7 parts, late */
    double where[] = {0.01, 0.5, 1.0 / 3, 2.0 / 3, 1.0 / 7, 6.0 / 7, 0.999};
    static char long_line[RAYO_SCENE_MAX_LINE + 40];
    char name[160], folder[] = "/tmp/t_scene_split.XXXXXX";
    size_t i, j;

    if (mkdtemp(folder) == NULL || chdir(folder) != 0)
        abort();
    check_add_spheres();

    ok(t.length > SCENE_SPLIT_MIN_BYTES, "the text is over the threshold");
    check_same("mixed scene", &t);
    {
        /* many windows (SCENE_WINDOW): errors either side of the cuts,
         * and lines across them */
        text big = make_scene(7, 60000), u;
        static const long around[] = {-70, -1, 0, 1, 30};
        size_t k;
        ok(big.length > 3 * SCENE_WINDOW + 100000, "a text of %lu bytes",
           (unsigned long)big.length);
        check_same("many windows", &big);
        for (k = 0; k < sizeof around / sizeof around[0]; k++) {
            size_t at = (size_t)((long)(1 + k % 3) * (long)SCENE_WINDOW +
                                 around[k]);
            snprintf(name, sizeof name, "window cut %+ld: unknown material",
                     around[k]);
            u = plant(&big, at, "sphere 1 2 3 4 material x");
            check_error(name, &u);
            free(u.data);
            snprintf(name, sizeof name, "window cut %+ld: a second camera",
                     around[k]);
            u = plant(&big, at, "camera fov 200");
            check_error(name, &u);
            free(u.data);
            snprintf(name, sizeof name, "window cut %+ld: a NUL byte",
                     around[k]);
            u = plant(&big, at, "sphere 1 2 3 4 material m0 <NUL>");
            check_error(name, &u);
            free(u.data);
        }
        memset(long_line, 'x', sizeof long_line - 1);
        long_line[sizeof long_line - 1] = '\0';
        u = plant(&big, SCENE_WINDOW - 100, long_line);
        check_error("a line too long across the first cut", &u);
        free(u.data);
        {
            /* a line longer than a window: the lexer refuses it where it
             * starts; a NUL after the window's end changes nothing */
            text w = {NULL, 0, 0};
            char *huge = malloc(SCENE_WINDOW + 5000);
            if (huge == NULL)
                abort();
            memset(huge, 'y', SCENE_WINDOW + 4994);
            memcpy(huge + SCENE_WINDOW + 4994, "<NUL>", 6);
            u = plant(&big, SCENE_WINDOW / 2, huge);
            check_error("a line longer than a window", &u);
            free(u.data);
            add(&w, "sphere 0 0 0 1\n");
            add(&w, huge);
            check_error("a file of one huge line after one sphere", &w);
            free(w.data);
            free(huge);
        }
        u = plant(&big, big.length - 5, "sphere 1 2 3");
        check_error("the last line", &u);
        free(u.data);
        free(big.data);
    }
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++)
        for (j = 0; j < sizeof where / sizeof where[0]; j++) {
            text u;
            if ((i + j) % 3 != 0)
                continue; /* a spread, not every pair */
            u = plant(&t, (size_t)(where[j] * (double)t.length), bad[i]);
            snprintf(name, sizeof name, "'%s' at %.0f%%", bad[i],
                     where[j] * 100);
            check_error(name, &u);
            free(u.data);
        }
    memset(long_line, 'x', sizeof long_line - 1);
    long_line[sizeof long_line - 1] = '\0';
    {
        text u = plant(&t, t.length / 2, long_line);
        check_error("a line too long, at the middle", &u);
        free(u.data);
    }
    {
        /* two errors: the earlier line's is reported */
        text u = plant(&t, t.length * 3 / 4, "sphere 1 2 3 bad"), v;
        v = plant(&u, u.length / 5, "sphere 1 2 3 4 material nowhere");
        check_error("two errors: the earlier one", &v);
        free(u.data);
        free(v.data);
    }
    free(t.data);
    unlink("big.scene");
    if (chdir("/") != 0 || rmdir(folder) != 0)
        ok(0, "the temporary folder %s is removed", folder);
    return tap_done();
}
