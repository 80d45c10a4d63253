/*
 * t_grade_functions.c - the "functions" criterion for the course's
 * exercises 2 and 3, through its seam (grade_step_functions on a
 * grade_context built here, with an exercise of our own whose course is
 * EJ2 or EJ3), so it does not depend on the registry: each fixture of
 * tests/grade/functions has one mistake, and the criterion must fail on
 * it with the exact reason line that names it, and pass the right ones
 * with every function checked.  Also the harness's log reading and the
 * compiler-note parsing, which need no compiler.
 *
 * Needs a C compiler ($CC, else cc), as `rayo grade` does.
 */
#define _XOPEN_SOURCE 700

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "../../src/course/course_impl.h"
#include "../../src/grade/grade_impl.h"
#include "../../src/grade/functions/harness.h"
#include "../../src/grade/functions/table.h"
#include "rayo.h"
#include "tap.h"

typedef struct graded {
    rayo_grade_report report;
    rayo_status status;
} graded;

/* Runs the functions step of exercise course on one fixture file. */
static void grade_fixture(rayo_course_exercise course, const char *name,
                          graded *g)
{
    static const rayo_grade_exercise ej2 = {
        "ej2", "test", 640, 480, '2', RAYO_COURSE_EJ2, NULL, NULL};
    static const rayo_grade_exercise ej3 = {
        "ej3", "test", 640, 480, '3', RAYO_COURSE_EJ3, NULL, NULL};
    const char *root = getenv("RAYO_SOURCE");
    const char *cc = getenv("CC");
    char path[PATH_MAX], ccbuf[256];
    const char *sources[1];
    char *absolute[1], *words[16], *save = NULL, *w;
    rayo_grade_options o;
    grade_context ctx;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    size_t n = 0;
    snprintf(path, sizeof path, "%s/tests/grade/functions/%s",
             root != NULL ? root : ".", name);
    snprintf(ccbuf, sizeof ccbuf, "%s",
             cc != NULL && cc[0] != '\0' ? cc : "cc");
    for (w = strtok_r(ccbuf, " ", &save); w != NULL && n < 15;
         w = strtok_r(NULL, " ", &save))
        words[n++] = w;
    memset(&g->report, 0, sizeof g->report);
    rayo_grade_options_init(&o);
    o.exercise = course == RAYO_COURSE_EJ2 ? &ej2 : &ej3;
    o.timeout = 5;
    sources[0] = path;
    absolute[0] = realpath(path, NULL);
    memset(&ctx, 0, sizeof ctx);
    ctx.options = &o;
    ctx.report = &g->report;
    ctx.sources = sources;
    ctx.absolute = absolute;
    ctx.source_count = 1;
    ctx.cc = words;
    ctx.cc_words = n;
    g->status = absolute[0] == NULL ? RAYO_ERR_IO
                                    : grade_tempdir_create(&ctx.dir, &err);
    if (g->status == RAYO_OK)
        g->status = grade_step_functions(&ctx, &err);
    if (g->status != RAYO_OK)
        printf("# %s: %s\n", name, absolute[0] == NULL ? path : err.message);
    grade_tempdir_remove(ctx.dir);
    free(absolute[0]);
}

static const rayo_grade_item *item(const graded *g)
{
    return &g->report.items[RAYO_GRADE_FUNCTIONS];
}

/* "NAME: right on N known inputs" is looked for as "NAME (N)" in the
   one line that sums up the passing functions (functions/engine.c). */
static int has_line(const graded *g, const char *line)
{
    static const char sum[] = "right on all their known inputs: ";
    char name[64], want[96];
    unsigned n;
    size_t i;
    for (i = 0; i < item(g)->line_count; i++)
        if (strcmp(item(g)->lines[i], line) == 0)
            return 1;
    if (sscanf(line, "%63[a-z_]: right on %u known input", name, &n) != 2)
        return 0;
    snprintf(want, sizeof want, "%s (%u)", name, n);
    for (i = 0; i < item(g)->line_count; i++) {
        const char *l = item(g)->lines[i], *at;
        if (strncmp(l, sum, strlen(sum)) != 0)
            continue;
        at = strstr(l, want);
        if (at != NULL && (at[-1] == ' ') &&
            (at[strlen(want)] == ',' || at[strlen(want)] == '\0'))
            return 1;
    }
    return 0;
}

static int starts(const char *line, const char *prefix)
{
    return strncmp(line, prefix, strlen(prefix)) == 0;
}

static void show(const graded *g)
{
    size_t i;
    for (i = 0; i < item(g)->line_count; i++)
        printf("#   %s\n", item(g)->lines[i]);
}

/* fails FIXTURE LINE: the criterion fails and says LINE exactly. */
static void expect_fail(rayo_course_exercise course, const char *fixture,
                        const char *line)
{
    graded g;
    grade_fixture(course, fixture, &g);
    is_int(g.status, RAYO_OK, "%s: graded", fixture);
    is_int(item(&g)->result, RAYO_GRADE_FAIL, "%s: functions fail",
           fixture);
    ok(has_line(&g, line), "%s: says '%.60s...'", fixture, line);
    if (!has_line(&g, line))
        show(&g);
    rayo_grade_report_free(&g.report);
}

/* The same for a line that begins with head and ends with tail: where
   the line quotes a ray's direction, its last digit depends on the
   compiler that built rayo (gcc and clang round one operation apart). */
static void expect_fail_ends(rayo_course_exercise course,
                             const char *fixture, const char *head,
                             const char *tail)
{
    graded g;
    size_t i, found = 0;
    grade_fixture(course, fixture, &g);
    is_int(item(&g)->result, RAYO_GRADE_FAIL, "%s: functions fail",
           fixture);
    for (i = 0; i < item(&g)->line_count; i++) {
        const char *line = item(&g)->lines[i];
        size_t n = strlen(line), t = strlen(tail);
        if (strncmp(line, head, strlen(head)) == 0 && n >= t &&
            strcmp(line + n - t, tail) == 0)
            found = 1;
    }
    ok(found, "%s: says '%.40s...%.40s'", fixture, head, tail);
    if (!found)
        show(&g);
    rayo_grade_report_free(&g.report);
}

static void expect_pass(rayo_course_exercise course, const char *fixture,
                        size_t lines, const char *line)
{
    graded g;
    grade_fixture(course, fixture, &g);
    is_int(g.status, RAYO_OK, "%s: graded", fixture);
    is_int(item(&g)->result, RAYO_GRADE_PASS, "%s: functions pass", fixture);
    is_int(item(&g)->line_count, lines, "%s: the passing functions in one "
           "line (and its notes)", fixture);
    ok(has_line(&g, line), "%s: says '%s'", fixture, line);
    if (item(&g)->result != RAYO_GRADE_PASS)
        show(&g);
    rayo_grade_report_free(&g.report);
}

static void test_log(void)
{
    const char *log = "call norma 0\n1 2 3\nresult norma 0 1.5 -2 inf\n"
                      "x result norma 1 9\nmissing resta\nmissing restaX\n";
    double v[4];
    char text[32];
    is_int(harness_result(log, "norma", 0, v, 4), 3, "log: three numbers");
    is_double(v[0], 1.5, 0, "log: the first");
    is_double(v[1], -2, 0, "log: the second");
    is_int(harness_result(log, "norma", 1, v, 4), -1,
           "log: a result not at a line's start is not one");
    is_int(harness_result(log, "resta", 0, v, 4), -1, "log: no result");
    ok(harness_missing(log, "resta"), "log: missing resta");
    ok(!harness_missing(log, "norma"), "log: norma is not missing");
    ok(!harness_missing(log, "rest"), "log: a prefix is not a name");
    ok(harness_result_text(log, "norma", 0, text, sizeof text) &&
           strcmp(text, "1.5 -2 inf") == 0,
       "log: the result's text");
}

/* A quoted signature is cut at a space, outside quotes, with " ...". */
static void test_shorten(void)
{
    char text[256];
    snprintf(text, sizeof text, "conflicting types for 'color_sumar'; have "
                                "'color_t(color_t,  color_t,  double)'");
    harness_shorten(text, 200);
    is_string(text, "conflicting types for 'color_sumar'; have "
                    "'color_t(color_t,  color_t,  double)'",
              "shorten: short enough, unchanged");
    harness_shorten(text, 60);
    is_string(text, "conflicting types for 'color_sumar'; have ...",
              "shorten: not inside the open quote, not mid-word");
    snprintf(text, sizeof text, "previous definition of \xe2\x80\x98"
                                "norma\xe2\x80\x99 with type \xe2\x80\x98"
                                "float(const float *, const float *)"
                                "\xe2\x80\x99");
    harness_shorten(text, 60);
    is_string(text, "previous definition of \xe2\x80\x98norma\xe2\x80\x99 "
                    "with type ...",
              "shorten: UTF-8 quotes balanced");
    snprintf(text, sizeof text, "expected identifier before numeric constant");
    harness_shorten(text, 30);
    is_string(text, "expected identifier before ...",
              "shorten: at a word's end");
}

static void test_notes(void)
{
    char type[128];
    harness_previous_type(
        "p.c:9:9: error: conflicting types for \xe2\x80\x98" "color_sumar"
        "\xe2\x80\x99; have \xe2\x80\x98" "color_t(color_t, float)"
        "\xe2\x80\x99\nx.c:80:9: note: previous definition of "
        "\xe2\x80\x98" "color_sumar\xe2\x80\x99 with type \xe2\x80\x98"
        "color_t(color_t,  color_t,  double)\xe2\x80\x99\n",
        "color_sumar", type, sizeof type);
    is_string(type, "color_t(color_t,  color_t,  double)",
              "note: gcc's type, UTF-8 quotes");
    harness_previous_type("x.c:3:7: note: previous declaration of 'norma' "
                          "with type 'double(const float *)'\n",
                          "norma", type, sizeof type);
    is_string(type, "double(const float *)", "note: ASCII quotes");
    harness_previous_type("x.c:3:7: note: previous definition is here\n",
                          "norma", type, sizeof type);
    is_string(type, "", "note: clang's gives no type");
}


static int same_float(double got, double want)
{
    return (float)got == (float)want; /* %.9g gives a float back exactly */
}

/* The numbers of the first record "c computar_intensidad 0 ..." of an
   exercise's calls (every function usable) into v; how many. */
static size_t first_ray_record(const functions_exercise *ex, double *v,
                               size_t max)
{
    int usable[FUNCTIONS_MAX];
    char *calls, *p, *end;
    size_t n = 0, f;
    for (f = 0; f < FUNCTIONS_MAX; f++)
        usable[f] = 1;
    calls = functions_calls(ex, usable);
    p = calls != NULL ? strstr(calls, "\nc computar_intensidad 0 ") : NULL;
    if (p != NULL)
        p += strlen("\nc computar_intensidad 0 ");
    while (p != NULL && *p != '\n' && *p != '\0' && n < max) {
        v[n] = strtod(p, &end);
        if (end == p)
            break;
        n++;
        p = end;
    }
    free(calls);
    return n;
}

/* The harness is given the course's scene 3 exactly as the course
   module holds it: as many spheres and lights, every number the same
   (as a float), in the same order; and scene 2 the same way. */
static void test_course_scenes(void)
{
    const rayo_course_data *d3 = rayo_course_data_of(RAYO_COURSE_EJ3);
    const rayo_course_data *d2 = rayo_course_data_of(RAYO_COURSE_EJ2);
    static double v[4096];
    size_t n = first_ray_record(&functions_ej3, v, 4096), bad = 0, i, k;
    const double *at = v + 2;
    ok(n > 2, "ej3: the first ray case has a record");
    is_int((long)v[0], (long)d3->ball_count,
           "ej3: as many spheres as the course's scene 3 (%zu)",
           d3->ball_count);
    is_int((long)v[1], (long)d3->lamp_count, "ej3: as many lights");
    is_int((long)n, (long)(2 + 9 * d3->ball_count + 7 * d3->lamp_count + 9),
           "ej3: the record's length");
    for (i = 0; i < d3->ball_count && n > 2; i++, at += 9) {
        const rayo_course_ball *b = &d3->balls[i];
        double want[9] = {b->center[0], b->center[1], b->center[2],
                          b->radius,    b->color[0],  b->color[1],
                          b->color[2],  b->ka,        b->kd};
        for (k = 0; k < 9; k++)
            if (!same_float(at[k], want[k])) {
                bad++;
                printf("# sphere %zu value %zu: %.9g, not %.9g\n", i, k,
                       at[k], want[k]);
            }
    }
    is_int((long)bad, 0, "ej3: every sphere's numbers are the course's");
    bad = 0;
    for (i = 0; i < d3->lamp_count && n > 2; i++, at += 7) {
        const rayo_course_lamp *l = &d3->lamps[i];
        double length = sqrt(l->vector[0] * l->vector[0] +
                             l->vector[1] * l->vector[1] +
                             l->vector[2] * l->vector[2]);
        for (k = 0; k < 3; k++)
            bad += !same_float(at[k], l->point ? l->vector[k]
                                               : l->vector[k] / length) +
                   !same_float(at[3 + k], l->color[k]);
        bad += (at[6] != 0) != (l->point != 0);
    }
    is_int((long)bad, 0, "ej3: every light's numbers are the course's");

    n = first_ray_record(&functions_ej2, v, 4096);
    bad = 0;
    is_int((long)v[0], (long)d2->ball_count,
           "ej2: as many spheres as the course's scene 2");
    is_int((long)n, (long)(1 + 4 * d2->ball_count + 9),
           "ej2: the record's length");
    for (i = 0; i < d2->ball_count && n > 1; i++) {
        for (k = 0; k < 3; k++)
            bad += !same_float(v[1 + 3 * i + k], d2->balls[i].center[k]);
        bad += !same_float(v[1 + 3 * d2->ball_count + i],
                           d2->balls[i].radius);
    }
    is_int((long)bad, 0, "ej2: every centre and radius is the course's");
}

/* Each harness as `make check` builds it (RAYO_BUILD/harness/ejN, linked
   with the exercise's right program of tests/grade/) run on the records
   its table writes: every call record gets its result line, framed by
   the nonce, and the run says "done"; ej1's values are the expected
   ones. */
static void test_built_harness(const char *name, const functions_exercise *ex)
{
    const char *build = getenv("RAYO_BUILD");
    char harness[4096], in[64] = "/tmp/t_functions_inXXXXXX", out[64];
    char command[8400], line[1024], key[128];
    int usable[FUNCTIONS_MAX], fd;
    size_t f, calls = 0, results = 0, done = 0, right = 0;
    char *records, *p;
    FILE *file;
    snprintf(harness, sizeof harness, "%s/harness/%s",
             build != NULL ? build : "build", name);
    if (access(harness, X_OK) != 0) {
        ok(1, "# SKIP %s: no harness built (make check builds it)", name);
        return;
    }
    for (f = 0; f < FUNCTIONS_MAX; f++)
        usable[f] = 1;
    records = functions_calls(ex, usable);
    fd = mkstemp(in);
    file = fd >= 0 ? fdopen(fd, "w") : NULL;
    ok(records != NULL && file != NULL, "%s: the records written", name);
    if (records == NULL || file == NULL) {
        free(records);
        return;
    }
    fprintf(file, "0123456789abcdef0123456789abcdef\n%s", records);
    fclose(file);
    snprintf(out, sizeof out, "%s.out", in);
    snprintf(command, sizeof command, "'%s' <'%s' >'%s' 2>/dev/null",
             harness, in, out);
    ok(system(command) == 0, "%s: the harness exits 0", name);
    for (p = records; (p = strstr(p, "\nc ")) != NULL; p++)
        calls++;
    calls += strncmp(records, "c ", 2) == 0;
    file = fopen(out, "r");
    while (file != NULL && fgets(line, sizeof line, file) != NULL) {
        double v;
        unsigned k;
        if (strncmp(line, "0123456789abcdef0123456789abcdef result ", 40) ==
                0 &&
            sscanf(line + 40, "%127s %u %lf", key, &k, &v) == 3) {
            results++;
            right += strcmp(key, "producto_interno") == 0 && k == 0 &&
                     v == 32;
            right += strcmp(key, "norma") == 0 && k == 0 && v == 13;
        }
        done += strcmp(line, "0123456789abcdef0123456789abcdef done\n") == 0;
    }
    if (file != NULL)
        fclose(file);
    ok(calls > 0 && results >= calls,
       "%s: a result for each of its %zu calls (%zu)", name, calls, results);
    is_int((long)done, 1, "%s: the harness says done", name);
    if (strcmp(name, "ej1") == 0)
        is_int((long)right, 2, "ej1: the right program's values come back");
    remove(in);
    remove(out);
    free(records);
}

/* Every function of names has a reason line of its own, beginning with
   its name, that contains needle (or needle2 when not NULL). */
static void expect_every(rayo_course_exercise course, const char *fixture,
                         const char *const *names, const char *needle,
                         const char *needle2)
{
    graded g;
    size_t f, i, missing = 0;
    grade_fixture(course, fixture, &g);
    is_int(item(&g)->result, RAYO_GRADE_FAIL, "%s: functions fail",
           fixture);
    for (f = 0; names[f] != NULL; f++) {
        int found = 0;
        for (i = 0; i < item(&g)->line_count && !found; i++) {
            const char *line = item(&g)->lines[i];
            found = starts(line, names[f]) &&
                    (line[strlen(names[f])] == '(' ||
                     line[strlen(names[f])] == ' ') &&
                    (strstr(line, needle) != NULL ||
                     (needle2 != NULL && strstr(line, needle2) != NULL));
        }
        if (!found) {
            printf("# %s: no line for %s\n", fixture, names[f]);
            missing++;
        }
    }
    is_int((long)missing, 0, "%s: every function's comparison says '%s'",
           fixture, needle);
    if (missing > 0)
        show(&g);
    rayo_grade_report_free(&g.report);
}

/* NaN and infinity in every function's comparison. */
static void test_not_finite(void)
{
    static const char *const ej2[] = {
        "producto_interno", "norma",          "normalizar",
        "resta",            "interpolar_recta", "distancia_esfera",
        "normal_esfera",    NULL};
    static const char *const ej3[] = {
        "vector_producto_interno", "vector_norma",   "vector_resta",
        "vector_interpolar_recta", "vector_normalizar", "color_sumar",
        "color_absorber",          "esfera_distancia", "computar_intensidad",
        NULL};
    static const char *const ej2_int[] = {"computar_intensidad", NULL};
    static const char *const ej3_print[] = {"color_imprimir", NULL};
    expect_every(RAYO_COURSE_EJ2, "ej2_nan.c", ej2, "nan (not a number)",
                 NULL);
    expect_every(RAYO_COURSE_EJ2, "ej2_inf.c", ej2, " (infinity): ",
                 "with an infinity in it");
    expect_every(RAYO_COURSE_EJ2, "ej2_nan.c", ej2_int,
                 "returned -2147483648, what a NaN (not a number) or a "
                 "value past the int range becomes through (int)",
                 NULL);
    expect_every(RAYO_COURSE_EJ3, "ej3_nan.c", ej3, "nan (not a number)",
                 NULL);
    expect_every(RAYO_COURSE_EJ3, "ej3_inf.c", ej3, " (infinity): ",
                 "with an infinity in it");
    expect_every(RAYO_COURSE_EJ3, "ej3_nan.c", ej3_print,
                 "printed \"-2147483648 -2147483648 -2147483648\"", NULL);
    expect_fail(RAYO_COURSE_EJ2, "ej2_nan.c",
                "distancia_esfera((0, 0, 2), 0.8, (0, 0, 0), (0, 0, 1)) "
                "returned nan (not a number): likely the square root of a "
                "negative discriminant (delta < 0: the ray misses; test it "
                "before taking the root) or 0/0");
    expect_fail(RAYO_COURSE_EJ3, "ej3_inf.c",
                "esfera_distancia(a sphere at (0, 0, 2) r 0.8, (0, 0, 0), "
                "(0, 0, 1), &punto, &normal) returned inf (infinity): the "
                "statement's INFINITO is FLT_MAX, the largest float, not an "
                "infinity");
}

static void test_ej2(void)
{
    expect_pass(RAYO_COURSE_EJ2, "ej2_right.c", 1,
                "computar_intensidad: right on 11 known inputs");
    expect_fail(RAYO_COURSE_EJ2, "ej2_resta_reversed.c",
                "resta(r, (1, 2, 3), (4, 6, 8)) gave (3, 4, 5), which is "
                "b - a; expected (-3, -4, -5): r = a - b");
    expect_fail(RAYO_COURSE_EJ2, "ej2_normalizar_copy.c",
                "normalizar((3, 4, 12)) left a unchanged (3, 4, 12); "
                "expected (0.2307692, 0.3076923, 0.9230769): normalizar "
                "divides the array it is given by its norm");
    expect_fail(RAYO_COURSE_EJ2, "ej2_miss_zero.c",
                "distancia_esfera((0, 0, 3), 1, (0, 0, 0), (1, 0, 0)) "
                "returned 0 for a ray that misses the sphere; expected "
                "INFINITO (FLT_MAX)");
    expect_fail(RAYO_COURSE_EJ2, "ej2_near_root_always.c",
                "distancia_esfera((0, 0, 1), 2, (0, 0, 0), (0, 0, 1)) "
                "returned -1, a root behind the origin (t < 0), for a ray "
                "that starts inside the sphere; expected 3: when "
                "beta - sqrt(delta) <= 0 the answer is beta + sqrt(delta)");
    expect_fail(RAYO_COURSE_EJ2, "ej2_shadow_behind.c",
                "computar_intensidad on a sphere (0, 0, 3) r 1 with a "
                "sphere (0, -2.5, 2) r 0.5 below it and the light straight "
                "up, luz = (0, 1, 0), along d = (0, 0.2873479, 0.9578263) "
                "returned 5; expected 178, as the sphere at (0, -2.5, 2) is "
                "behind the point, away from the light: spheres behind the "
                "point cast shadows: only a sphere hit at t > 0 on the ray "
                "from P towards L lies between P and the light");
    expect_fail(RAYO_COURSE_EJ2, "ej2_no_intensidad.c",
                "computar_intensidad: not defined; the statement asks for "
                "int computar_intensidad(const float cs[][3], const float "
                "rs[], size_t n_esferas, const float luz[3], const float "
                "o[3], const float d[3])");
    expect_fail(RAYO_COURSE_EJ2, "ej2_exit_early.c",
                "norma((3, 4, 12)) ended the program (exit status 0) before "
                "the other calls were made: a function returns to its "
                "caller, it does not call exit");
    expect_fail(RAYO_COURSE_EJ2, "ej2_normal_crash.c",
                "normal_esfera(n, (1, 2, 3), 2, (1, 2, 5)) crashed: "
                "segmentation fault (SIGSEGV)");
    {
        graded g;
        grade_fixture(RAYO_COURSE_EJ2, "ej2_norma_double.c", &g);
        /* The finding comes first, before the functions that were
           right (functions/engine.c). */
        ok(item(&g)->result == RAYO_GRADE_FAIL && item(&g)->line_count > 1 &&
               starts(item(&g)->lines[0],
                       "norma: the signature differs from the statement's "
                       "float norma(const float a[3]) (the compiler says: ") &&
               (strstr(item(&g)->lines[0], "double") != NULL ||
                strstr(item(&g)->lines[0], "conflicting types") != NULL),
           "ej2_norma_double.c: the signature, first (gcc: with the "
           "student's double)");
        ok(has_line(&g, "computar_intensidad: right on 11 known inputs"),
           "ej2_norma_double.c: the others are still called");
        rayo_grade_report_free(&g.report);
    }
}

static void test_ej3(void)
{
    expect_pass(RAYO_COURSE_EJ3, "ej3_right.c", 2,
                "arreglo_agregar: right on 2 known inputs");
    expect_fail(RAYO_COURSE_EJ3, "ej3_realloc_direct.c",
                "arreglo_agregar lost the array when realloc failed: a->v "
                "became NULL; keep realloc's result in a temporary and "
                "assign it only when it is not NULL");
    expect_fail(RAYO_COURSE_EJ3, "ej3_write_past_end.c",
                "arreglo_agregar wrote past the end of a->v: after three "
                "additions to an empty array its last realloc asked for 16 "
                "bytes, and a pointer was written beyond them; ask for "
                "(a->n + 1) * sizeof(void *) before writing a->v[a->n]");
    expect_fail(RAYO_COURSE_EJ3, "ej3_n_first.c",
                "arreglo_agregar changed a->n from 3 to 4 when realloc "
                "failed; on failure the array is left exactly as it was");
    /* The statements' two readings: each accepted, and named. */
    expect_pass(RAYO_COURSE_EJ3, "ej3_beyond_light.c", 2,
                "computar_intensidad: a sphere beyond a point light casts a "
                "shadow: the statement's rule (an object in the light's "
                "direction casts a shadow) read to the letter, accepted; the "
                "other reading, a shadow only from a sphere between the "
                "point and the light, is accepted too, and the course's "
                "scenes look the same either way");
    expect_pass(RAYO_COURSE_EJ3, "ej3_right.c", 2,
                "computar_intensidad: only a sphere between the point and a "
                "point light casts a shadow, not one beyond the light: one "
                "of the statement's two readings, accepted; the other, to "
                "the letter (an object in the light's direction casts a "
                "shadow), is accepted too, and the course's scenes look the "
                "same either way");
    expect_pass(RAYO_COURSE_EJ3, "ej3_imprimir_rounds.c", 3,
                "color_imprimir: rounds 255 c to the nearest integer (0.999 "
                "prints 255) instead of taking its integer part (254): a "
                "reading of the statement's 'scale 0..1 to the integers "
                "0..255', accepted");
    expect_fail(RAYO_COURSE_EJ3, "ej3_crear_swaps.c",
                "esfera_crear((0.5, -0.6, 3), 0.3, (1, 0.5, 0.25), 0.3, "
                "0.8) returned a sphere whose ka is 0.8, not the 0.3 it was "
                "given");
    expect_fail(RAYO_COURSE_EJ3, "ej3_luz_always_point.c",
                "luz_crear((0, 1, 0), (0.2, 0.3, 0.4), false) returned a "
                "light whose es_puntual is 1, not the 0 it was given");
    expect_fail_ends(RAYO_COURSE_EJ3, "ej3_normal_unnormalised.c",
                     "computar_intensidad on the course's scene 3, along "
                     "d = (-0.546576",
                     "returned (0.0955, 0, 0); expected (0.202, 0, 0): the "
                     "shading is wrong in brightness: N = (P - C) / r must "
                     "be the unit normal in (Li.N), the one "
                     "esfera_distancia returns");
    expect_fail(RAYO_COURSE_EJ3, "ej3_double_vector.c",
                "vector_t: its member x is not of the statement's type; the "
                "statement gives typedef struct { float x, y, z; } "
                "vector_t;");
    expect_fail(RAYO_COURSE_EJ3, "ej3_no_typedef.c",
                "not called, as they use a type that is not the "
                "statement's: vector_producto_interno, vector_norma, "
                "vector_resta, vector_interpolar_recta, vector_normalizar, "
                "esfera_crear, esfera_destruir, luz_crear, luz_destruir, "
                "esfera_distancia, computar_intensidad");
    {
        graded g;
        grade_fixture(RAYO_COURSE_EJ3, "ej3_no_typedef.c", &g);
        ok(item(&g)->line_count > 0 &&
               starts(item(&g)->lines[0],
                       "vector_t: not defined as the statement's type (the "
                       "compiler says: "),
           "ej3_no_typedef.c: vector_t is not defined");
        if (item(&g)->line_count > 0 &&
            strstr(item(&g)->lines[0], "not defined") == NULL)
            show(&g);
        ok(has_line(&g, "color_imprimir: right on 4 known inputs") &&
               has_line(&g, "arreglo_agregar: right on 2 known inputs"),
           "ej3_no_typedef.c: the functions without vector_t are called");
        rayo_grade_report_free(&g.report);
        grade_fixture(RAYO_COURSE_EJ3, "ej3_sumar_double.c", &g);
        ok(item(&g)->line_count > 0 &&
               starts(item(&g)->lines[0],
                       "color_sumar: the signature differs from the "
                       "statement's color_t color_sumar(color_t c, color_t "
                       "m, float p) (") &&
               (strstr(item(&g)->lines[0], "double") != NULL ||
                strstr(item(&g)->lines[0], "conflicting types") != NULL),
           "ej3_sumar_double.c: the signature is named");
        ok(has_line(&g, "color_absorber: right on 1 known input"),
           "ej3_sumar_double.c: the others are still called");
        rayo_grade_report_free(&g.report);
    }
}

int main(void)
{
    test_log();
    test_notes();
    test_shorten();
    test_course_scenes();
    test_built_harness("ej1", &functions_ej1);
    test_built_harness("ej2", &functions_ej2);
    test_built_harness("ej3", &functions_ej3);
    test_not_finite();
    test_ej2();
    test_ej3();
    return tap_done();
}
