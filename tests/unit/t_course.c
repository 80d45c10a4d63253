/*
 * t_course.c - the course's built-in exercises (course.h): the registry,
 * names and texts, the exact images against the renderer reached another
 * way (examples/ejN.scene: one scene, byte for byte), the two camera variations, and each modelled
 * mistake against an independent computation of what it does.
 *
 * The reference here shares no code with src/course: it holds the
 * statements' numbers itself, forms each pixel's direction from the
 * pixel convention, solves the assignment's beta/delta formula in double
 * precision and applies each mistake's formula as course.h and the
 * model's comments describe it.  It is compared at "stable" pixels of a
 * grid (the sphere seen and every light's lit and shadow state the same
 * at the grid's neighbours), where float and double must agree within
 * one level; a handful of pixels worked out by hand pin the meaning.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

#include "../../src/course/course_impl.h"

#define W 640
#define H 480
#define GRID 3 /* reference pixels every GRID columns and rows */

typedef struct ball {
    double c[3], r, m[3], ka, kd;
} ball;

typedef struct lamp {
    int point;
    double v[3], i[3];
} lamp;

typedef struct course_ref {
    const ball *balls;
    size_t n;
    const lamp *lamps;
    size_t lamp_count;
    double ambient;
    int gray;
} course_ref;

#define WH {1, 1, 1}

static const ball ej2_balls[] = {
    {{-0.4, 0.75, 1.55}, 0.3, WH, 1, 1}, {{-0.55, -0.4, 2}, 0.85, WH, 1, 1},
    {{3, 1.5, 4}, 0.4, WH, 1, 1},        {{3, 1.5, 5}, 0.4, WH, 1, 1},
    {{3, -1.5, 4}, 0.4, WH, 1, 1},       {{3, -1.5, 5}, 0.4, WH, 1, 1},
};
static const lamp ej2_lamps[] = {
    {0, {0.2873478855663454, 0.9578262852211513, 0}, {255, 255, 255}}};

static const ball ej3_balls[] = {
    {{0, 1, 2.4}, 0.3, WH, 1, 1},
    {{0, -0.4, 3}, 1, WH, 1, 1},
    {{-2, -0.6, 3}, 0.3, {1, 0, 0}, 1, 0.8},
    {{-1.73, -0.6, 2}, 0.3, {1, 1, 0}, 1, 1},
    {{-1, -0.6, 1.26}, 0.3, {0, 1, 0}, 1, 1},
    {{0, -0.6, 1}, 0.3, WH, 1, 1},
    {{1, -0.6, 1.26}, 0.3, {0, 1, 1}, 1, 1},
    {{1.73, -0.6, 2}, 0.3, {0, 0, 1}, 1, 1},
    {{2, -0.6, 3}, 0.3, {1, 0, 1}, 1, 1},
    {{-3, 2.5, 4.3}, 0.3, WH, 1, 0},
    {{-2, 2.5, 4.3}, 0.3, WH, 1, 0.16},
    {{-1, 2.5, 4.3}, 0.3, WH, 1, 0.33},
    {{0, 2.5, 4.3}, 0.3, WH, 1, 0.5},
    {{1, 2.5, 4.3}, 0.3, WH, 1, 0.66},
    {{2, 2.5, 4.3}, 0.3, WH, 1, 0.83},
    {{3, 2.5, 4.3}, 0.3, WH, 1, 1},
    {{-3, 1.5, 4}, 0.3, WH, 0, 1},
    {{-2, 1.5, 4}, 0.3, WH, 0.16, 1},
    {{-1, 1.5, 4}, 0.3, WH, 0.33, 1},
    {{0, 1.5, 4}, 0.3, WH, 0.5, 1},
    {{1, 1.5, 4}, 0.3, WH, 0.66, 1},
    {{2, 1.5, 4}, 0.3, WH, 0.83, 1},
    {{3, 1.5, 4}, 0.3, WH, 1, 1},
};
static const lamp ej3_lamps[] = {
    {0, {0, 1, 0}, {0.2, 0.2, 0.2}},
    {1, {-2, 10, 2.5}, {0.9, 0, 0}},
    {1, {2, 10, 2.5}, {0, 0.9, 0}},
    {1, {0, 10, 5}, {0, 0, 0.9}},
};

static const course_ref ref2 = {ej2_balls, 6, ej2_lamps, 1, 5, 1};
static const course_ref ref3 = {ej3_balls, 23, ej3_lamps, 4, 0.05, 0};

static double dot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void unit(double *v)
{
    double n = sqrt(dot(v, v));
    v[0] /= n;
    v[1] /= n;
    v[2] /= n;
}

/* The note's t with o and d as given (d not necessarily unit), or -1. */
static double meet(const ball *b, const double *o, const double *d, int far)
{
    double l[3], beta, delta, s;
    l[0] = b->c[0] - o[0];
    l[1] = b->c[1] - o[1];
    l[2] = b->c[2] - o[2];
    beta = dot(l, d);
    delta = beta * beta - dot(l, l) + b->r * b->r;
    if (delta < 0)
        return -1;
    s = sqrt(delta);
    if (!far && beta - s > 0)
        return beta - s;
    if (beta + s > 0)
        return beta + s;
    return -1;
}

static void direction(unsigned i, unsigned j, double *d)
{
    d[0] = (double)i - W / 2;
    d[1] = -((double)j - H / 2);
    d[2] = 320.0; /* 640 / (2 tan 45) */
    unit(d);
}

/* What the reference finds at a pixel: the value before it becomes a
   byte (EJ2: the level, EJ3: the channels), and a key for stability. */
typedef struct sample {
    double v[3];
    long key;
    int hit;
    double ln[4];
} sample;

/* The light's direction at p and how far a shadow ray counts. */
static void light_at(const lamp *l, const double *p, rayo_course_mistake m,
                     double *dir, double *limit)
{
    int k;
    *limit = INFINITY;
    if (!l->point || m == RAYO_MISTAKE_POINT_AS_DIRECTIONAL) {
        for (k = 0; k < 3; k++)
            dir[k] = m == RAYO_MISTAKE_LIGHT_REVERSED ? -l->v[k] : l->v[k];
        if (l->point)
            unit(dir);
        return;
    }
    for (k = 0; k < 3; k++)
        dir[k] = m == RAYO_MISTAKE_LIGHT_REVERSED ? p[k] - l->v[k]
                                                  : l->v[k] - p[k];
    *limit = sqrt(dot(dir, dir));
    if (m != RAYO_MISTAKE_UNNORMALISED_LIGHT)
        unit(dir);
}

/*
 * The pixel (i, j) with mistake m; bit k of blocked says light k is
 * taken as shadowed whatever the spheres (SELF_SHADOW's two extremes).
 */
static sample reference(const course_ref *s, rayo_course_mistake m,
                        unsigned i, unsigned j, unsigned blocked)
{
    sample out;
    double o[3] = {0, 0, 0}, d[3], p[3], n[3], best = INFINITY;
    double ka, kd, c[3] = {0, 0, 0};
    const ball *h;
    size_t b, k;
    int q;
    memset(&out, 0, sizeof out);
    out.hit = -1;
    direction(i, j, d);
    for (b = 0; b < s->n; b++) {
        double t = meet(&s->balls[b], o, d, m == RAYO_MISTAKE_FAR_ROOT);
        if (t > 0 && t < best) {
            best = t;
            out.hit = (int)b;
            if (m == RAYO_MISTAKE_FIRST_SPHERE)
                break;
        }
    }
    out.key = out.hit;
    if (out.hit < 0)
        return out;
    h = &s->balls[out.hit];
    for (q = 0; q < 3; q++) {
        p[q] = best * d[q];
        n[q] = p[q] - h->c[q];
        if (m != RAYO_MISTAKE_UNNORMALISED_NORMAL)
            n[q] /= h->r;
    }
    ka = m == RAYO_MISTAKE_KA_KD_SWAPPED ? h->kd : h->ka;
    kd = m == RAYO_MISTAKE_KA_KD_SWAPPED ? h->ka : h->kd;
    if (m != RAYO_MISTAKE_NO_AMBIENT &&
        m != RAYO_MISTAKE_AMBIENT_NOT_ABSORBED)
        c[0] = c[1] = c[2] = s->ambient * ka;
    for (k = 0; k < s->lamp_count; k++) {
        const lamp *l = &s->lamps[k];
        double dir[3], limit, ln;
        int shadow = (blocked >> k) & 1;
        light_at(l, p, m, dir, &limit);
        ln = dot(dir, n);
        out.ln[k] = ln;
        for (b = 0; !shadow && m != RAYO_MISTAKE_NO_SHADOWS && b < s->n; b++) {
            double t;
            if ((int)b == out.hit)
                continue;
            t = meet(&s->balls[b], p, dir, m == RAYO_MISTAKE_FAR_ROOT);
            shadow = t > 0 && t < limit;
        }
        out.key = out.key * 4 + (ln > 0) * 2 + shadow;
        if ((ln > 0 || m == RAYO_MISTAKE_NO_LN_TEST) && !shadow)
            for (q = 0; q < 3; q++)
                c[q] += l->i[q] * kd * ln;
    }
    for (q = 0; q < 3; q++) {
        out.v[q] = s->gray ? c[q] : c[q] * h->m[q];
        if (m == RAYO_MISTAKE_AMBIENT_NOT_ABSORBED)
            out.v[q] += s->ambient * ka;
    }
    return out;
}

/* The byte the formula's value prints as. */
static int byte_of(const course_ref *s, rayo_course_mistake m, double v)
{
    int wrapped = m == RAYO_MISTAKE_WRAPPED;
    double level = s->gray ? v : 255.0 * v;
    if (!wrapped && level > 255)
        return 255;
    if (level < 0)
        return 0;
    return wrapped ? (int)level % 256 : (int)level;
}

/* Levels a and b within one (around 256 when wrapped: 255 and 0). */
static int close_levels(int a, int b, int wrapped)
{
    int d = abs(a - b);
    return d <= 1 || (wrapped && d == 255);
}

static const unsigned char *pixel(const rayo_image *img, unsigned i,
                                  unsigned j)
{
    return rayo_image_row(img, j) + (size_t)i * img->info.channels;
}

static int render(rayo_course_exercise e, rayo_course_mistake m,
                  int literal, double focal, rayo_image *img)
{
    rayo_course_options o;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_course_options_init(&o);
    o.mistake = m;
    o.literal_rows = literal;
    o.focal_scale = focal;
    if (rayo_course_render(e, &o, img, &err) != RAYO_OK) {
        printf("# %s\n", err.message);
        return 0;
    }
    return 1;
}

/* The model without a mistake (course_student.c), not the renderer. */
static int render_model(rayo_course_exercise e, int literal,
                        rayo_image *img)
{
    rayo_course_options o;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_course_options_init(&o);
    o.literal_rows = literal;
    if (rayo_course_render_student(e, &o, img, &err) != RAYO_OK) {
        printf("# %s\n", err.message);
        return 0;
    }
    return 1;
}

static int same_bytes(const rayo_image *a, const rayo_image *b)
{
    uint32_t j;
    size_t n = rayo_image_info_row_bytes(&a->info);
    if (memcmp(&a->info, &b->info, sizeof a->info) != 0)
        return 0;
    for (j = 0; j < a->info.height; j++)
        if (memcmp(rayo_image_row(a, j), rayo_image_row(b, j), n) != 0)
            return 0;
    return 1;
}

/* Pixels of a and b differing in some channel, and by more than one. */
static void count_diff(const rayo_image *a, const rayo_image *b, long *any,
                       long *big)
{
    unsigned i, j, q, c = a->info.channels;
    *any = *big = 0;
    for (j = 0; j < H; j++)
        for (i = 0; i < W; i++) {
            const unsigned char *x = pixel(a, i, j), *y = pixel(b, i, j);
            int d = 0;
            for (q = 0; q < c; q++)
                if (abs(x[q] - y[q]) > d)
                    d = abs(x[q] - y[q]);
            *any += d > 0;
            *big += d > 1;
        }
}

static int render_file(const char *name, rayo_image *img)
{
    const char *root = getenv("RAYO_SOURCE");
    char path[4096];
    rayo_scene_file file;
    rayo_camera camera;
    rayo_render_options options;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    int good;
    snprintf(path, sizeof path, "%s/examples/%s", root ? root : ".", name);
    status = rayo_scene_file_load(&file, path, &err);
    if (status != RAYO_OK) {
        printf("# %s\n", err.message);
        return 0;
    }
    rayo_render_options_init(&options);
    options.shade = file.shade;
    options.samples = file.samples;
    options.threads = 2;
    good = rayo_camera_spec_build(&file.camera, &camera, &err) == RAYO_OK &&
           rayo_render_image(&camera, file.scene, &options, img, &err) ==
               RAYO_OK;
    if (!good)
        printf("# %s\n", err.message);
    rayo_scene_file_free(&file);
    return good;
}

/* The registry: each exercise as the statements define it. */
static void test_registry(void)
{
    static const rayo_course_kind kinds[] = {
        RAYO_COURSE_BILEVEL, RAYO_COURSE_GRAY, RAYO_COURSE_COLOUR};
    static const rayo_shade_mode shades[] = {
        RAYO_SHADE_HIT, RAYO_SHADE_COURSE_GRAY, RAYO_SHADE_COURSE_COLOR};
    static const int modelled[] = {0, 1, 1}, literal[] = {1, 1, 0};
    int e;
    is_int(RAYO_COURSE_EXERCISES, 3, "three exercises");
    for (e = 0; e < RAYO_COURSE_EXERCISES; e++) {
        rayo_course_exercise x = (rayo_course_exercise)e;
        const rayo_course_info *info = rayo_course_info_of(x);
        char name[8], title[32], reference[40];
        if (info == NULL) {
            ok(0, "exercise %d is in the registry", e);
            continue;
        }
        snprintf(name, sizeof name, "ej%d", e + 1);
        snprintf(title, sizeof title, "Ejercicio obligatorio %d: ", e + 1);
        snprintf(reference, sizeof reference, "referencia-catedra-ej%d.png",
                 e + 1);
        ok(info->exercise == x && strcmp(info->name, name) == 0 &&
               info->number == e + 1 &&
               strncmp(info->title, title, strlen(title)) == 0 &&
               strcmp(info->reference, reference) == 0,
           "%s: its name, number, title and reference file", name);
        ok(info->kind == kinds[e] && info->width == W && info->height == H &&
               info->magic == '1' + e && info->shade == shades[e],
           "%s: its kind, 640x480, P%c, its light model", name, '1' + e);
        ok(info->scene == rayo_course_data_of(x) && info->scene != NULL &&
               info->scene->shade == info->shade,
           "%s: its scene is the one rayo_course_data_of gives", name);
        ok(info->student_model == modelled[e] &&
               info->literal_rows == literal[e],
           "%s: student model %d, literal rows %d", name, modelled[e],
           literal[e]);
        is_int(rayo_course_of_kind(kinds[e]), e, "the %s picture is %s's",
               e == 0 ? "bilevel" : e == 1 ? "gray" : "colour", name);
    }
    ok(rayo_course_info_of(RAYO_COURSE_EXERCISES) == NULL,
       "no entry past the last exercise");
    is_int(rayo_course_of_kind((rayo_course_kind)7), RAYO_COURSE_EXERCISES,
           "no exercise of an unknown kind");
}

/* A 64x48 render of scene with exercise's shading into img. */
static int render_small(rayo_course_exercise e, rayo_scene *scene,
                        rayo_image *img)
{
    rayo_camera_spec spec;
    rayo_camera camera;
    rayo_render_options options;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_camera_spec_init(&spec);
    spec.width = 64;
    spec.height = 48;
    rayo_render_options_init(&options);
    options.shade = rayo_course_info_of(e)->shade;
    options.threads = 1;
    return rayo_camera_spec_build(&spec, &camera, &err) == RAYO_OK &&
           rayo_render_image(&camera, scene, &options, img, &err) == RAYO_OK;
}

/* The page's scene with spheres moved: the scene's own values give the
   scene's bytes, a smaller sphere other bytes, and what is not moved
   stays. */
static void test_moved(void)
{
    const rayo_course_data *d = rayo_course_data_of(RAYO_COURSE_EJ2);
    double at[4 * 8];
    rayo_scene *scene = NULL;
    rayo_image plain, same, moved;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    size_t i;
    int good;
    ok(d->ball_count <= 8, "scene 2 has at most 8 spheres");
    for (i = 0; i < d->ball_count; i++) {
        memcpy(at + 4 * i, d->balls[i].center, sizeof d->balls[i].center);
        at[4 * i + 3] = d->balls[i].radius;
    }
    good = rayo_course_scene_build(RAYO_COURSE_EJ2, &scene, &err) ==
               RAYO_OK &&
           render_small(RAYO_COURSE_EJ2, scene, &plain);
    rayo_scene_free(scene);
    good = good &&
           rayo_course_scene_build_moved(RAYO_COURSE_EJ2, at, d->ball_count,
                                         &scene, &err) == RAYO_OK &&
           render_small(RAYO_COURSE_EJ2, scene, &same);
    rayo_scene_free(scene);
    at[4 * 1 + 3] = 0.2; /* the big sphere, 0.85, much smaller */
    good = good &&
           rayo_course_scene_build_moved(RAYO_COURSE_EJ2, at, 2, &scene,
                                         &err) == RAYO_OK &&
           render_small(RAYO_COURSE_EJ2, scene, &moved);
    rayo_scene_free(scene);
    ok(good, "scene 2 builds and renders with and without moved spheres");
    if (!good)
        return;
    ok(same_bytes(&plain, &same), "its own values: the scene's bytes");
    ok(!same_bytes(&plain, &moved), "a smaller sphere: other bytes");
    is_int(rayo_course_scene_build_moved(RAYO_COURSE_EXERCISES, NULL, 0,
                                         &scene, &err),
           RAYO_ERR_INVALID, "no scene past the last exercise");
    ok(scene == NULL, "and no scene made");
    rayo_image_free(&plain);
    rayo_image_free(&same);
    rayo_image_free(&moved);
}

static void test_names(void)
{
    static const char *const names[RAYO_MISTAKE_COUNT] = {
        "none", "no-shadows", "self-shadow", "no-ambient",
        "ambient-not-absorbed", "light-reversed", "no-ln-test", "wrapped",
        "first-sphere", "far-root", "point-as-directional", "ka-kd-swapped",
        "unnormalised-normal", "unnormalised-light", "last-sphere",
        "shadow-behind", "no-clamp"};
    /* Which mistakes each exercise can show: 1 applies (the functions
       criterion's), 2 applies and pictured too (EJ2: FIRST_SPHERE never
       changes a pixel of scene 2). */
    static const char applies[RAYO_COURSE_EXERCISES][RAYO_MISTAKE_COUNT] = {
        {2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
        {2, 2, 2, 2, 0, 2, 2, 2, 1, 2, 0, 0, 2, 0, 1, 1, 1},
        {2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 2, 1, 0, 0}};
    const char *ex[] = {"ej1", "ej2", "ej3"};
    int e, m, clean = 1, right = 1;
    rayo_image img;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_course_options o;
    for (e = 0; e < RAYO_COURSE_EXERCISES; e++) {
        is_int(rayo_course_find(ex[e]), e, "find %s", ex[e]);
        is_string(rayo_course_name((rayo_course_exercise)e), ex[e],
                  "name of exercise %d", e);
    }
    is_int(rayo_course_find("ej4"), RAYO_COURSE_EXERCISES, "no ej4");
    is_int(rayo_course_find("EJ1"), RAYO_COURSE_EXERCISES, "names exact");
    is_int(rayo_course_find(NULL), RAYO_COURSE_EXERCISES, "NULL name");
    ok(rayo_course_name(RAYO_COURSE_EXERCISES) == NULL, "no 4th name");
    for (m = 0; m < RAYO_MISTAKE_COUNT; m++)
        is_string(rayo_course_mistake_name((rayo_course_mistake)m), names[m],
                  "mistake %d is %s", m, names[m]);
    ok(rayo_course_mistake_name(RAYO_MISTAKE_COUNT) == NULL,
       "no name past the last mistake");
    for (e = 0; e < RAYO_COURSE_EXERCISES; e++)
        for (m = 0; m < RAYO_MISTAKE_COUNT; m++) {
            rayo_course_exercise x = (rayo_course_exercise)e;
            rayo_course_mistake y = (rayo_course_mistake)m;
            const char *text = rayo_course_mistake_text(x, y);
            size_t k;
            if (rayo_course_mistake_applies(x, y) != (applies[e][m] > 0) ||
                rayo_course_mistake_pictured(x, y) != (applies[e][m] > 1)) {
                printf("# applies(%s, %s) wrong\n", ex[e], names[m]);
                right = 0;
            }
            if ((text != NULL) != (applies[e][m] > 0))
                right = 0;
            for (k = 0; text != NULL && text[k] != '\0'; k++)
                if ((unsigned char)text[k] < 32 ||
                    (unsigned char)text[k] > 126 || text[k] == '"' ||
                    text[k] == '\'' || text[k] == '\\')
                    clean = 0;
            if (text != NULL && (strlen(text) < 40 || strlen(text) > 300))
                clean = 0;
        }
    ok(right, "each exercise's mistakes apply as listed, with a text each");
    ok(clean, "texts: printable ASCII, no quotes or backslash, 40-300 bytes");
    ok(strstr(rayo_course_mistake_text(RAYO_COURSE_EJ2,
                                       RAYO_MISTAKE_NO_SHADOWS),
              "II (L.N)") != NULL &&
           strstr(rayo_course_mistake_text(RAYO_COURSE_EJ3,
                                           RAYO_MISTAKE_NO_SHADOWS),
                  "delta_i") != NULL,
       "the texts name each exercise's formula");
    ok(rayo_course_mistake_text_lang(RAYO_COURSE_EJ2, RAYO_MISTAKE_NO_SHADOWS,
                                     RAYO_LANG_EN) ==
               rayo_course_mistake_text(RAYO_COURSE_EJ2,
                                        RAYO_MISTAKE_NO_SHADOWS) &&
           strcmp(rayo_course_mistake_text_lang(RAYO_COURSE_EJ3,
                                                RAYO_MISTAKE_KA_KD_SWAPPED,
                                                RAYO_LANG_ES),
                  "ka y kd están intercambiados: C = Ia ka + sum delta_i Ii "
                  "kd (Li.N), ka con la luz ambiente y kd con cada luz") == 0 &&
           rayo_course_mistake_text_lang(RAYO_COURSE_EJ2,
                                         RAYO_MISTAKE_KA_KD_SWAPPED,
                                         RAYO_LANG_ES) == NULL,
       "a text in English and in Spanish, none where it does not apply");
    ok(!rayo_course_mistake_applies(RAYO_COURSE_EJ2, RAYO_MISTAKE_COUNT) &&
           !rayo_course_mistake_applies(RAYO_COURSE_EXERCISES,
                                        RAYO_MISTAKE_NONE),
       "out of range applies nowhere");

    rayo_course_options_init(&o);
    o.mistake = RAYO_MISTAKE_KA_KD_SWAPPED;
    is_int(rayo_course_render(RAYO_COURSE_EJ2, &o, &img, &err),
           RAYO_ERR_INVALID, "ka-kd-swapped does not apply to ej2");
    ok(strstr(err.message, "ka-kd-swapped") != NULL, "and says which");
    printf("# %s\n", err.message);
    o.mistake = RAYO_MISTAKE_NO_SHADOWS;
    is_int(rayo_course_render(RAYO_COURSE_EJ1, &o, &img, &err),
           RAYO_ERR_INVALID, "ej1 has no mistakes modelled");
    o.mistake = RAYO_MISTAKE_COUNT;
    is_int(rayo_course_render(RAYO_COURSE_EJ3, &o, &img, &err),
           RAYO_ERR_INVALID, "no mistake past the last");
    rayo_course_options_init(&o);
    is_int(rayo_course_render(RAYO_COURSE_EXERCISES, &o, &img, &err),
           RAYO_ERR_INVALID, "no 4th exercise");
    o.focal_scale = 0;
    is_int(rayo_course_render(RAYO_COURSE_EJ2, &o, &img, &err),
           RAYO_ERR_INVALID, "focal scale 0 refused");
    o.focal_scale = NAN;
    is_int(rayo_course_render(RAYO_COURSE_EJ2, &o, &img, &err),
           RAYO_ERR_INVALID, "focal scale NaN refused");
}

/* NONE is the renderer's image, as the example scene files give it:
   examples/NAME.scene and the registry's scene are one scene. */
static void test_exact(void)
{
    rayo_image mine, theirs;
    int e;
    for (e = 0; e < RAYO_COURSE_EXERCISES; e++) {
        rayo_course_exercise x = (rayo_course_exercise)e;
        char file[64];
        snprintf(file, sizeof file, "%s.scene", rayo_course_name(x));
        if (!render(x, RAYO_MISTAKE_NONE, 0, 1.0, &mine)) {
            ok(0, "%s renders", rayo_course_name(x));
            continue;
        }
        if (render_file(file, &theirs)) {
            ok(same_bytes(&mine, &theirs), "%s: byte for byte the render of "
               "examples/%s", rayo_course_name(x), file);
            rayo_image_free(&theirs);
        } else {
            ok(0, "examples/%s renders", file);
        }
        ok(mine.info.width == W && mine.info.height == H &&
               mine.info.sample ==
                   (e == 0 ? RAYO_SAMPLE_BIT : RAYO_SAMPLE_U8) &&
               mine.info.channels == (e == 2 ? 3u : 1u) &&
               mine.info.maxval == (e == 0 ? 1u : 255u),
           "%s: 640x480 %s", rayo_course_name(x),
           e == 0 ? "bilevel" : e == 1 ? "gray" : "RGB");
        if (e == 0) {
            /* The sphere's centre (0.5, 0.75, 1.9) is seen at
               x = 0.5 / 1.9 * 320 = 84, y = 126: column 404, row 114. */
            const unsigned char *row = rayo_image_row(&mine, 114);
            ok(rayo_bit_get(row, 404) == 1 &&
                   rayo_bit_get(rayo_image_row(&mine, 0), 0) == 0 &&
                   rayo_bit_get(rayo_image_row(&mine, 479), 639) == 0,
               "ej1: black at the sphere's centre, white in the corners");
        }
        rayo_image_free(&mine);
    }
}

/* Pixels of an EJ1 image that disagree with the hit test of the
   assignment's note, with focal distance f (double precision). */
static long ej1_mismatches(const rayo_image *img, double f)
{
    static const ball seed = {{0.5, 0.75, 1.9}, 0.8, WH, 1, 1};
    double o[3] = {0, 0, 0}, d[3];
    long wrong = 0;
    unsigned i, j;
    for (j = 0; j < H; j++)
        for (i = 0; i < W; i++) {
            d[0] = (double)i - W / 2;
            d[1] = -((double)j - H / 2);
            d[2] = f;
            unit(d);
            wrong += (meet(&seed, o, d, 0) > 0) !=
                     rayo_bit_get(rayo_image_row(img, j), i);
        }
    return wrong;
}

/* literal_rows: one row higher; focal_scale: a slightly larger picture. */
static void test_camera(void)
{
    rayo_image normal, literal, longer;
    long any, big;
    int e;
    for (e = 0; e < RAYO_COURSE_EXERCISES; e++) {
        rayo_course_exercise x = (rayo_course_exercise)e;
        size_t n;
        uint32_t j;
        int shifted = 1;
        if (!render(x, RAYO_MISTAKE_NONE, 0, 1.0, &normal) ||
            !render(x, RAYO_MISTAKE_NONE, 1, 1.0, &literal) ||
            !render(x, RAYO_MISTAKE_NONE, 0, 1.0047, &longer)) {
            ok(0, "%s renders", rayo_course_name(x));
            return;
        }
        n = rayo_image_info_row_bytes(&normal.info);
        for (j = 0; j + 1 < H; j++)
            if (memcmp(rayo_image_row(&literal, j),
                       rayo_image_row(&normal, j + 1), n) != 0)
                shifted = 0;
        ok(shifted, "%s: literal rows 0..478 are rows 1..479",
           rayo_course_name(x));
        ok(!same_bytes(&normal, &literal), "%s: literal rows differ",
           rayo_course_name(x));
        if (e == 0) {
            long wrong = ej1_mismatches(&longer, 320.0 * 1.0047);
            ok(wrong <= 2 && !same_bytes(&normal, &longer),
               "ej1: focal x 1.0047 is the sphere seen with f = 321.504 "
               "(%ld pixels off)",
               wrong);
        } else {
            count_diff(&normal, &longer, &any, &big);
            ok(any > 1000, "%s: focal x 1.0047 changes %ld pixels",
               rayo_course_name(x), any);
        }
        rayo_image_free(&normal);
        rayo_image_free(&literal);
        rayo_image_free(&longer);
    }
    /* The model shifts the same way. */
    if (render(RAYO_COURSE_EJ3, RAYO_MISTAKE_NO_SHADOWS, 0, 1.0, &normal) &&
        render(RAYO_COURSE_EJ3, RAYO_MISTAKE_NO_SHADOWS, 1, 1.0, &literal) &&
        render(RAYO_COURSE_EJ3, RAYO_MISTAKE_NO_SHADOWS, 0, 1.0047,
               &longer)) {
        uint32_t j;
        int shifted = 1;
        for (j = 0; j + 1 < H; j++)
            if (memcmp(rayo_image_row(&literal, j),
                       rayo_image_row(&normal, j + 1), 3 * W) != 0)
                shifted = 0;
        ok(shifted, "ej3 no-shadows: literal rows shift the model too");
        count_diff(&normal, &longer, &any, &big);
        ok(any > 1000, "ej3 no-shadows: focal x 1.0047 changes %ld pixels",
           any);
        rayo_image_free(&normal);
        rayo_image_free(&literal);
        rayo_image_free(&longer);
    }
}

/* The model without a mistake against the renderer: float against
   double, within a level but at a few pixels. */
static void test_model_none(void)
{
    rayo_image model, exact;
    long any, big;
    int e, literal;
    for (e = RAYO_COURSE_EJ2; e <= RAYO_COURSE_EJ3; e++)
        for (literal = 0; literal <= 1; literal++) {
            rayo_course_exercise x = (rayo_course_exercise)e;
            if (!render_model(x, literal, &model) ||
                !render(x, RAYO_MISTAKE_NONE, literal, 1.0, &exact)) {
                ok(0, "%s renders", rayo_course_name(x));
                continue;
            }
            count_diff(&model, &exact, &any, &big);
            printf("# %s%s: model vs renderer: %ld pixels differ, %ld by "
                   "more than one level\n",
                   rayo_course_name(x), literal ? " literal" : "", any, big);
            ok(big <= 20 && any <= 300,
               "%s%s: the model agrees with the renderer within a level "
               "(%ld pixels differ, %ld by more)",
               rayo_course_name(x), literal ? " literal rows" : "", any,
               big);
            rayo_image_free(&model);
            rayo_image_free(&exact);
        }
}

/* The reference's keys on the grid, for stability. */
static long *grid_keys(const course_ref *s, rayo_course_mistake m,
                       unsigned gw, unsigned gh)
{
    long *keys = malloc(sizeof *keys * gw * gh);
    unsigned a, b;
    if (keys == NULL)
        return NULL;
    for (b = 0; b < gh; b++)
        for (a = 0; a < gw; a++)
            keys[b * gw + a] =
                reference(s, m, a * GRID + 1, b * GRID + 1, 0).key;
    return keys;
}

static int stable(const long *keys, unsigned gw, unsigned gh, unsigned a,
                  unsigned b)
{
    long k = keys[b * gw + a];
    if (a == 0 || b == 0 || a + 1 >= gw || b + 1 >= gh)
        return 0;
    return keys[b * gw + a - 1] == k && keys[b * gw + a + 1] == k &&
           keys[(b - 1) * gw + a] == k && keys[(b + 1) * gw + a] == k;
}

/*
 * The model's image with mistake m against the reference at the grid's
 * stable pixels.  SELF_SHADOW's rounding cannot be reproduced: there the
 * model must lie between the picture with every light self-shadowed and
 * the one with none, and darken a fair share of the lit pixels.
 */
static void check_mistake(rayo_course_exercise x, const course_ref *s,
                          rayo_course_mistake m)
{
    unsigned gw = W / GRID, gh = H / GRID, a, b, q, c = s->gray ? 1 : 3;
    long checked = 0, wrong = 0, lit = 0, darker = 0;
    long any, big;
    rayo_image img, none;
    long *keys = grid_keys(s, m, gw, gh);
    const char *name = rayo_course_mistake_name(m);
    int self = m == RAYO_MISTAKE_SELF_SHADOW;
    if (keys == NULL || !render(x, m, 0, 1.0, &img)) {
        ok(0, "%s %s renders", rayo_course_name(x), name);
        free(keys);
        return;
    }
    for (b = 0; b < gh; b++)
        for (a = 0; a < gw; a++) {
            unsigned i = a * GRID + 1, j = b * GRID + 1;
            const unsigned char *got = pixel(&img, i, j);
            sample want, dark;
            int good = 1, was_darker = 0;
            if (!stable(keys, gw, gh, a, b))
                continue;
            checked++;
            want = reference(s, m, i, j, 0);
            dark = reference(s, m, i, j, self ? 0xf : 0);
            for (q = 0; q < c; q++) {
                int hi = byte_of(s, m, want.v[q]);
                int lo = byte_of(s, m, dark.v[q]);
                if (self) {
                    good &= got[q] + 1 >= lo && got[q] <= hi + 1;
                    was_darker |= got[q] + 1 < hi;
                } else {
                    good &= close_levels(got[q], hi,
                                         m == RAYO_MISTAKE_WRAPPED);
                }
            }
            if (self && byte_of(s, m, want.v[c - 1]) >
                            byte_of(s, m, dark.v[c - 1]) + 4) {
                lit++;
                darker += was_darker;
            }
            if (!good && wrong++ < 3)
                printf("# %s %s at (%u, %u): got %d, reference %.3f\n",
                       rayo_course_name(x), name, i, j, got[0], want.v[0]);
        }
    ok(wrong == 0 && checked > (long)gw * gh * 7 / 10,
       "%s %s: the reference's values at %ld stable pixels (%ld wrong)",
       rayo_course_name(x), name, checked, wrong);
    if (self)
        ok(lit > 100 && darker > lit / 5 && darker < lit * 19 / 20,
           "%s self-shadow: %ld of %ld lit grid pixels darkened",
           rayo_course_name(x), darker, lit);
    if (render(x, RAYO_MISTAKE_NONE, 0, 1.0, &none)) {
        count_diff(&img, &none, &any, &big);
        printf("# %s %s changes %ld pixels (%ld by more than a level)\n",
               rayo_course_name(x), name, any, big);
        ok(big >= 10, "%s %s: the image differs from the correct one",
           rayo_course_name(x), name);
        rayo_image_free(&none);
    }
    rayo_image_free(&img);
    free(keys);
}

static void test_mistakes(void)
{
    int m;
    for (m = 1; m < RAYO_MISTAKE_COUNT; m++) {
        rayo_course_mistake y = (rayo_course_mistake)m;
        if (rayo_course_mistake_pictured(RAYO_COURSE_EJ2, y))
            check_mistake(RAYO_COURSE_EJ2, &ref2, y);
        if (rayo_course_mistake_pictured(RAYO_COURSE_EJ3, y))
            check_mistake(RAYO_COURSE_EJ3, &ref3, y);
    }
}

/* Pixels worked out by hand from the scenes' numbers. */
static void test_by_hand(void)
{
    rayo_image none, img;
    sample s;
    /*
     * EJ2 (187, 213): P = (-0.55, 0.11, 1.32) on sphere 1, N near
     * (0, 0.6, -0.8), L.N near 0.575 > 0, but the ray from P along L
     * passes within 0.24 of sphere 0's centre (radius 0.3): shadow, IA.
     */
    if (!render(RAYO_COURSE_EJ2, RAYO_MISTAKE_NONE, 0, 1.0, &none))
        return;
    s = reference(&ref2, RAYO_MISTAKE_NONE, 187, 213, 0);
    ok(s.hit == 1 && s.ln[0] > 0.5 && s.ln[0] < 0.65 &&
           pixel(&none, 187, 213)[0] == 5,
       "ej2 (187, 213): in sphere 0's shadow, IA = %d",
       pixel(&none, 187, 213)[0]);
    if (render(RAYO_COURSE_EJ2, RAYO_MISTAKE_NO_SHADOWS, 0, 1.0, &img)) {
        int want = (int)(5 + 255 * s.ln[0]);
        ok(abs(pixel(&img, 187, 213)[0] - want) <= 1,
           "ej2 no-shadows (187, 213): IA + II L.N = %d, got %d", want,
           pixel(&img, 187, 213)[0]);
        rayo_image_free(&img);
    }
    /* EJ2 (232, 380): low on sphere 1, facing away from the light. */
    if (render(RAYO_COURSE_EJ2, RAYO_MISTAKE_NO_AMBIENT, 0, 1.0, &img)) {
        ok(pixel(&none, 232, 380)[0] == 5 && pixel(&img, 232, 380)[0] == 0,
           "ej2 no-ambient (232, 380): unlit 5 becomes %d",
           pixel(&img, 232, 380)[0]);
        rayo_image_free(&img);
    }
    if (render(RAYO_COURSE_EJ2, RAYO_MISTAKE_NO_LN_TEST, 0, 1.0, &img)) {
        /* (232, 440): P = (-0.35, -0.80, 1.28) on sphere 1, L.N = -0.38,
           nothing between P and the light: 5 + 255 L.N = -92. */
        s = reference(&ref2, RAYO_MISTAKE_NONE, 232, 440, 0);
        ok(s.ln[0] < -0.3 && pixel(&img, 232, 440)[0] == 0 &&
               pixel(&none, 232, 440)[0] == 5,
           "ej2 no-ln-test (232, 440): L.N = %.2f, IA + II L.N < 0 "
           "printed as 0",
           s.ln[0]);
        rayo_image_free(&img);
    }
    /* EJ2 (271, 172): where N is nearly L on sphere 1's limb,
       5 + 255 L.N >= 256 wraps to 0..4. */
    if (render(RAYO_COURSE_EJ2, RAYO_MISTAKE_WRAPPED, 0, 1.0, &img)) {
        s = reference(&ref2, RAYO_MISTAKE_NONE, 271, 172, 0);
        ok(s.v[0] >= 256 && pixel(&none, 271, 172)[0] == 255 &&
               pixel(&img, 271, 172)[0] <= 4,
           "ej2 wrapped (271, 172): I = %.2f, 255 becomes %d", s.v[0],
           pixel(&img, 271, 172)[0]);
        rayo_image_free(&img);
    }
    rayo_image_free(&none);
    /* EJ3 (60, 316): the green sphere 4 (z = 1.26) in front of the
       yellow sphere 3 (z = 2), which comes first in the array. */
    if (!render(RAYO_COURSE_EJ3, RAYO_MISTAKE_NONE, 0, 1.0, &none))
        return;
    if (render(RAYO_COURSE_EJ3, RAYO_MISTAKE_FIRST_SPHERE, 0, 1.0, &img)) {
        const unsigned char *g = pixel(&none, 60, 316),
                            *y = pixel(&img, 60, 316);
        ok(reference(&ref3, RAYO_MISTAKE_NONE, 60, 316, 0).hit == 4 &&
               reference(&ref3, RAYO_MISTAKE_FIRST_SPHERE, 60, 316, 0).hit ==
                   3 &&
               g[0] == 0 && g[1] > 100 && y[0] > 100 && y[1] > 100 &&
               y[2] == 0,
           "ej3 first-sphere (60, 316): green (%d %d %d) becomes yellow "
           "(%d %d %d)",
           g[0], g[1], g[2], y[0], y[1], y[2]);
        rayo_image_free(&img);
    }
    rayo_image_free(&none);
}

int main(void)
{
    test_registry();
    test_moved();
    test_names();
    test_exact();
    test_camera();
    test_model_none();
    test_mistakes();
    test_by_hand();
    return tap_done();
}
