/*
 * t_course_scenes.c - the course's scenes 2 and 3, as rayo renders
 * examples/ej2.scene and examples/ej3.scene, against an independent
 * computation of the course's formulas (escenas-del-curso.md).
 *
 * The reference below shares no code with the library: it holds the
 * course's numbers itself (not read from the example files, so a typo
 * there is caught), forms each pixel's direction from the convention,
 * finds the nearest sphere with the assignment's beta/delta formula
 * written out again, and shades with the course's models to the letter.
 * Every pixel is compared.  Pixels on an outline (where the reference's
 * nearest sphere differs from a neighbour's) may differ, since a ray that
 * grazes a sphere can fall either way; every other pixel must agree
 * within one level per channel, and nearly all of them exactly.  The
 * same is checked for 2 x 2 anti-aliased renders (the reference
 * averaging its own four sub-pixel rays), and the threads must not
 * change a byte.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

#define W 640
#define H 480
#define MAX_BALLS 32
#define MAX_LIGHTS 4

typedef struct ball {
    double c[3], r, m[3], ka, kd;
} ball;

typedef struct lamp {
    int point;     /* 0: directional, towards v; 1: point at v */
    double v[3], i[3];
} lamp;

typedef struct course {
    ball balls[MAX_BALLS];
    size_t n;
    lamp lamps[MAX_LIGHTS];
    size_t lamp_count;
    double ambient[3];
    int gray; /* scene 2's model (levels) instead of scene 3's */
} course;

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Smallest t > 0 of the ray o + t d (unit d) on ball b, or -1. */
static double meet(const ball *b, const double *o, const double *d)
{
    double l[3], beta, delta;
    l[0] = b->c[0] - o[0];
    l[1] = b->c[1] - o[1];
    l[2] = b->c[2] - o[2];
    beta = dot3(l, d);
    delta = beta * beta - dot3(l, l) + b->r * b->r;
    if (delta < 0)
        return -1;
    if (beta - sqrt(delta) > 0)
        return beta - sqrt(delta);
    if (beta + sqrt(delta) > 0)
        return beta + sqrt(delta);
    return -1;
}

static void add_ball(course *s, double x, double y, double z, double r,
                     double mr, double mg, double mb, double ka, double kd)
{
    ball *b = &s->balls[s->n++];
    b->c[0] = x, b->c[1] = y, b->c[2] = z, b->r = r;
    b->m[0] = mr, b->m[1] = mg, b->m[2] = mb;
    b->ka = ka, b->kd = kd;
}

static void add_lamp(course *s, int point, double x, double y, double z,
                     double r, double g, double b)
{
    lamp *l = &s->lamps[s->lamp_count++];
    l->point = point;
    l->v[0] = x, l->v[1] = y, l->v[2] = z;
    l->i[0] = r, l->i[1] = g, l->i[2] = b;
}

static void scene2(course *s)
{
    memset(s, 0, sizeof *s);
    s->gray = 1;
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 5;
    add_lamp(s, 0, 0.2873478855663454, 0.9578262852211513, 0, 255, 255, 255);
    add_ball(s, -0.4, 0.75, 1.55, 0.3, 1, 1, 1, 1, 1);
    add_ball(s, -0.55, -0.4, 2, 0.85, 1, 1, 1, 1, 1);
    add_ball(s, 3, 1.5, 4, 0.4, 1, 1, 1, 1, 1);
    add_ball(s, 3, 1.5, 5, 0.4, 1, 1, 1, 1, 1);
    add_ball(s, 3, -1.5, 4, 0.4, 1, 1, 1, 1, 1);
    add_ball(s, 3, -1.5, 5, 0.4, 1, 1, 1, 1, 1);
}

static void scene3(course *s)
{
    static const double k[7] = {0, 0.16, 0.33, 0.5, 0.66, 0.83, 1};
    int x;
    memset(s, 0, sizeof *s);
    s->ambient[0] = s->ambient[1] = s->ambient[2] = 0.05;
    add_lamp(s, 0, 0, 1, 0, 0.2, 0.2, 0.2);
    add_lamp(s, 1, -2, 10, 2.5, 0.9, 0, 0);
    add_lamp(s, 1, 2, 10, 2.5, 0, 0.9, 0);
    add_lamp(s, 1, 0, 10, 5, 0, 0, 0.9);
    add_ball(s, 0, 1, 2.4, 0.3, 1, 1, 1, 1, 1);
    add_ball(s, 0, -0.4, 3, 1, 1, 1, 1, 1, 1);
    add_ball(s, -2, -0.6, 3, 0.3, 1, 0, 0, 1, 0.8);
    add_ball(s, -1.73, -0.6, 2, 0.3, 1, 1, 0, 1, 1);
    add_ball(s, -1, -0.6, 1.26, 0.3, 0, 1, 0, 1, 1);
    add_ball(s, 0, -0.6, 1, 0.3, 1, 1, 1, 1, 1);
    add_ball(s, 1, -0.6, 1.26, 0.3, 0, 1, 1, 1, 1);
    add_ball(s, 1.73, -0.6, 2, 0.3, 0, 0, 1, 1, 1);
    add_ball(s, 2, -0.6, 3, 0.3, 1, 0, 1, 1, 1);
    for (x = -3; x <= 3; x++)
        add_ball(s, x, 2.5, 4.3, 0.3, 1, 1, 1, 1, k[x + 3]);
    for (x = -3; x <= 3; x++)
        add_ball(s, x, 1.5, 4, 0.3, 1, 1, 1, k[x + 3], 1);
}

/* 1 when no ball but `self` lies on the half-line from p along l. */
static int lit(const course *s, size_t self, const double *p, const double *l)
{
    size_t k;
    for (k = 0; k < s->n; k++)
        if (k != self && meet(&s->balls[k], p, l) > 0)
            return 0;
    return 1;
}

/*
 * The course's value of the ray through image position (px, py): levels
 * (gray) or channels in [0, 1] (colour), clamped; *which is the ball hit
 * or -1.
 */
static void shade(const course *s, double px, double py, double out[3],
                  int *which)
{
    const double pi = 3.14159265358979323846;
    double f = W / (2.0 * tan(90.0 * pi / 360.0));
    double x = px - W / 2, y = py - H / 2, n = sqrt(x * x + y * y + f * f);
    double d[3], o[3] = {0, 0, 0}, best = INFINITY, p[3], nn[3], c[3];
    size_t k, hit = 0;
    int ch;
    d[0] = x / n, d[1] = -y / n, d[2] = f / n;
    *which = -1;
    out[0] = out[1] = out[2] = 0;
    for (k = 0; k < s->n; k++) {
        double t = meet(&s->balls[k], o, d);
        if (t > 0 && t < best)
            best = t, hit = k;
    }
    if (best == INFINITY)
        return;
    *which = (int)hit;
    for (ch = 0; ch < 3; ch++) {
        p[ch] = best * d[ch];
        nn[ch] = (p[ch] - s->balls[hit].c[ch]) / s->balls[hit].r;
        c[ch] = s->ambient[ch] * (s->gray ? 1 : s->balls[hit].ka);
    }
    for (k = 0; k < s->lamp_count; k++) {
        const lamp *q = &s->lamps[k];
        double l[3], cosine;
        if (q->point) {
            double len;
            for (ch = 0; ch < 3; ch++)
                l[ch] = q->v[ch] - p[ch];
            len = sqrt(dot3(l, l));
            for (ch = 0; ch < 3; ch++)
                l[ch] /= len;
        } else {
            memcpy(l, q->v, sizeof l);
        }
        cosine = dot3(l, nn);
        if (cosine > 0 && lit(s, hit, p, l))
            for (ch = 0; ch < 3; ch++)
                c[ch] += q->i[ch] * (s->gray ? 1 : s->balls[hit].kd) * cosine;
    }
    for (ch = 0; ch < 3; ch++) {
        double v = s->gray ? c[ch] : c[ch] * s->balls[hit].m[ch];
        double top = s->gray ? 255 : 1;
        out[ch] = v > top ? top : v;
    }
}

/* The reference pixel with n x n samples, as bytes; *which as shade's, or
 * -2 when the samples hit different balls. */
static void reference_pixel(const course *s, unsigned n, int i, int j,
                            unsigned char bytes[3], int *which)
{
    double sum[3] = {0, 0, 0}, v[3];
    unsigned a, b;
    int ch, first = 0, w;
    for (b = 0; b < n; b++) {
        for (a = 0; a < n; a++) {
            shade(s, i + (a + 0.5) / n - 0.5, j + (b + 0.5) / n - 0.5, v, &w);
            if (a == 0 && b == 0)
                first = w;
            else if (w != first)
                first = -2;
            for (ch = 0; ch < 3; ch++)
                sum[ch] += v[ch];
        }
    }
    *which = first;
    for (ch = 0; ch < 3; ch++) {
        double mean = sum[ch] / (n * n);
        bytes[ch] = (unsigned char)(s->gray ? mean : 255 * mean);
    }
}

typedef struct tally {
    long outline, exact, off_by_one, wrong;
} tally;

static void compare(const course *s, unsigned n, const rayo_image *img,
                    tally *t)
{
    static int which[H][W];
    static unsigned char ref[H][W][3];
    int i, j, di, dj, ch;
    unsigned channels = img->info.channels;
    memset(t, 0, sizeof *t);
    for (j = 0; j < H; j++)
        for (i = 0; i < W; i++)
            reference_pixel(s, n, i, j, ref[j][i], &which[j][i]);
    for (j = 0; j < H; j++) {
        for (i = 0; i < W; i++) {
            const unsigned char *got =
                rayo_image_row(img, (uint32_t)j) + (size_t)i * channels;
            int outline = which[j][i] == -2, worst = 0;
            for (dj = -1; dj <= 1; dj++)
                for (di = -1; di <= 1; di++)
                    if (j + dj >= 0 && j + dj < H && i + di >= 0 &&
                        i + di < W && which[j + dj][i + di] != which[j][i])
                        outline = 1;
            for (ch = 0; ch < (int)channels; ch++) {
                int diff = abs((int)got[ch] - (int)ref[j][i][ch]);
                if (diff > worst)
                    worst = diff;
            }
            if (outline)
                t->outline++;
            else if (worst == 0)
                t->exact++;
            else if (worst == 1)
                t->off_by_one++;
            else
                t->wrong++;
        }
    }
}

static int render_example(const char *file, unsigned samples,
                          unsigned threads, rayo_image *img,
                          rayo_shade_mode *mode)
{
    const char *root = getenv("RAYO_SOURCE");
    char path[4096];
    rayo_scene_file scene;
    rayo_camera camera;
    rayo_render_options options;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    int good;
    snprintf(path, sizeof path, "%s/examples/%s", root ? root : ".", file);
    if (rayo_scene_file_load(&scene, path, &err) != RAYO_OK) {
        printf("# %s\n", err.message);
        return 0;
    }
    rayo_render_options_init(&options);
    options.shade = scene.shade;
    options.samples = samples;
    options.threads = threads;
    *mode = scene.shade;
    good = rayo_camera_spec_build(&scene.camera, &camera, &err) == RAYO_OK &&
           rayo_render_image(&camera, scene.scene, &options, img, &err) ==
               RAYO_OK;
    if (!good)
        printf("# %s\n", err.message);
    rayo_scene_file_free(&scene);
    return good;
}

static void check_scene(const char *file, const course *s,
                        rayo_shade_mode want, unsigned samples)
{
    rayo_image img, again;
    rayo_shade_mode mode;
    tally t;
    long inner;
    if (!render_example(file, samples, 1, &img, &mode)) {
        ok(0, "%s renders", file);
        return;
    }
    is_int(mode, want, "%s asks for its course mode", file);
    is_int(img.info.channels, s->gray ? 1 : 3, "%s: %s layout", file,
           s->gray ? "gray" : "RGB");
    compare(s, samples, &img, &t);
    inner = t.exact + t.off_by_one + t.wrong;
    printf("# %s, %ux%u samples: %ld exact, %ld off by one, %ld wrong, "
           "%ld outline\n",
           file, samples, samples, t.exact, t.off_by_one, t.wrong,
           t.outline);
    is_int(t.wrong, 0,
           "%s, %u samples: every pixel off the outlines within one level",
           file, samples);
    ok(t.exact * 1000 >= inner * 999,
       "%s, %u samples: at least 99.9%% of them exact", file, samples);
    ok(t.outline * 20 < W * H, "%s: outlines are under 5%% of the picture",
       file);
    if (render_example(file, samples, 2, &again, &mode)) {
        ok(memcmp(img.pixels, again.pixels, img.stride * H) == 0,
           "%s, %u samples: 1 thread and 2 threads give the same bytes",
           file, samples);
        rayo_image_free(&again);
    }
    rayo_image_free(&img);
}

int main(void)
{
    course s;
    scene2(&s);
    check_scene("ej2.scene", &s, RAYO_SHADE_COURSE_GRAY, 1);
    check_scene("ej2.scene", &s, RAYO_SHADE_COURSE_GRAY, 2);
    scene3(&s);
    check_scene("ej3.scene", &s, RAYO_SHADE_COURSE_COLOR, 1);
    check_scene("ej3.scene", &s, RAYO_SHADE_COURSE_COLOR, 2);
    return tap_done();
}
