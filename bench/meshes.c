/*
 * meshes.c - rayo against Embree and POV-Ray on triangle meshes: the
 * scan-like STL of bench/scan/scan_mesh.c at 100,000, 1,000,000 and
 * 10,000,000 triangles on a floor under one point light, 1920x1080, the
 * same scene file for all three (the Makefile writes them into
 * $RAYO_BUILD/bench once).
 *
 * The 1M mesh's rows are whole processes, their processor time (wait4)
 * the figure unless the row says wall, and their peak resident size from
 * GNU time, whose children are copies of a small process (process.c says
 * why not wait4's): rayo's `--shade hit` and phong renders on one thread
 * and its setup (-W 1 -H 1) on one and two; the Embree program casting
 * the same rays on one thread (occlusion queries at the default and the
 * high build quality, nearest hits plus shadow rays) and building on
 * every thread; POV-Ray once on one thread (a run takes tens of seconds).
 * Each row runs --repeat times, the rows interleaved, and the figure is
 * the median.  Per ray: rayo's render alone, in this process on a scene
 * loaded once, one thread (its whole process less its setup would be a
 * difference of seconds for tens of milliseconds); Embree's own timer
 * around its rays.  The 10M mesh runs once a process: rayo's phong render
 * on every thread for its peak memory, Embree's two modes building on
 * every thread; its cost per ray against the 100k's is the growth target.
 * Without the Embree program, `povray` or a mesh ($RAYO_BENCH_MESHES,
 * from the Makefile's BENCH_MESHES), those rows and targets say
 * "skipped".
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "bench.h"
#include "rayo/scene_file.h"

#define MAX_RUNS 16
#define CAPTURE_BYTES 4096
#define MESH_PIXELS (1920.0 * 1080.0)

/* One command and its runs. */
typedef struct mrow {
    char command[1024];
    int captures; /* the Embree program: "key value" lines */
    int runs;     /* at most this many (0: every round) */
    int available, failed;
    int n;
    double wall[MAX_RUNS], cpu[MAX_RUNS], rss[MAX_RUNS], ns[MAX_RUNS];
    double setup[MAX_RUNS], read[MAX_RUNS], build[MAX_RUNS];
    double setup_cpu[MAX_RUNS];
    char output[CAPTURE_BYTES]; /* the last run's */
} mrow;

enum {
    M_HIT,
    M_PHONG,
    M_SETUP_1,
    M_SETUP_2,
    M_E_OCC,
    M_E_OCC_HIGH,
    M_E_SHADOW,
    M_E_SETUP,
    M_POVRAY,
    T_RAYO,
    T_E_OCC,
    T_E_SHADOW,
    K_E_OCC,
    K_E_SHADOW,
    ROW_COUNT
};

#define TIMED "/usr/bin/time -f %M -o \"$BENCH_TMP/mesh-rss\" "
#define RAYO_MESH                                                            \
    TIMED "\"$RAYO\" render \"$RAYO_BUILD/bench/scan-{M}.scene\" --raw "
#define EMBREE_MESH TIMED "\"$RAYO_BUILD/bench/embree-rays\" " \
                    "\"$RAYO_BUILD/bench/scan-{M}.scene\" "

static double median(const double *values, int n)
{
    double sorted[MAX_RUNS], t;
    int i, j;
    if (n <= 0)
        return -1;
    memcpy(sorted, values, (size_t)n * sizeof *sorted);
    for (i = 1; i < n; i++)
        for (j = i; j > 0 && sorted[j - 1] > sorted[j]; j--) {
            t = sorted[j];
            sorted[j] = sorted[j - 1];
            sorted[j - 1] = t;
        }
    return n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
}

static double read_rss_kib(void)
{
    const char *tmp = getenv("BENCH_TMP");
    char path[4096];
    snprintf(path, sizeof path, "%s/mesh-rss", tmp != NULL ? tmp : ".");
    return bench_read_number(path);
}

static void run_once(mrow *r)
{
    double cpu = -1, wall;
    if (!r->available || r->failed || r->n == MAX_RUNS ||
        (r->runs > 0 && r->n >= r->runs))
        return;
    wall = bench_run_measured(r->command, r->captures ? r->output : NULL,
                              sizeof r->output, &cpu);
    if (wall < 0 ||
        (r->captures && bench_output_value(r->output, "rays_s") < 0)) {
        r->failed = 1;
        return;
    }
    r->wall[r->n] = wall;
    r->cpu[r->n] = cpu;
    r->rss[r->n] = read_rss_kib();
    r->ns[r->n] = bench_output_value(r->output, "ns_per_ray");
    r->setup[r->n] = bench_output_value(r->output, "setup_s");
    r->read[r->n] = bench_output_value(r->output, "read_s");
    r->build[r->n] = bench_output_value(r->output, "build_s");
    r->setup_cpu[r->n] = bench_output_value(r->output, "setup_cpu_s");
    r->n++;
}

/* A row's median of one of its series; -1 when it has none. */
static double row_median(const mrow *r, const double *series)
{
    return r->available && !r->failed ? median(series, r->n) : -1;
}

/* The mesh's scene is there, and $RAYO_BENCH_MESHES (the Makefile's
 * BENCH_MESHES: words such as 100k 1m 10m) names it, when it is set. */
static int mesh_exists(const char *size)
{
    const char *build = getenv("RAYO_BUILD");
    const char *wanted = getenv("RAYO_BENCH_MESHES");
    char path[4096];
    if (wanted != NULL) {
        size_t n = strlen(size);
        const char *p = wanted;
        while ((p = strstr(p, size)) != NULL &&
               !((p == wanted || p[-1] == ' ') &&
                 (p[n] == '\0' || p[n] == ' ')))
            p += n;
        if (p == NULL)
            return 0;
    }
    snprintf(path, sizeof path, "%s/bench/scan-%s.scene",
             build != NULL ? build : "build", size);
    return access(path, R_OK) == 0;
}

static double cpu_now(void)
{
    struct timespec t;
    if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t) != 0)
        return bench_now();
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* rayo's cost per ray, in this process: the mesh's scene loaded once on
 * every thread, then `repeats` renders of each mode on one thread,
 * interleaved; the medians of their processor time in *hit_s, *phong_s. */
static int rayo_in_process(const char *size, int repeats, double *hit_s,
                           double *phong_s)
{
    const char *build = getenv("RAYO_BUILD");
    char path[4096];
    rayo_scene_file file;
    rayo_camera camera;
    rayo_render_options options;
    rayo_error err;
    double hit[MAX_RUNS], phong[MAX_RUNS];
    int k, mode, ok = 1;
    snprintf(path, sizeof path, "%s/bench/scan-%s.scene",
             build != NULL ? build : "build", size);
    if (rayo_scene_file_load_threads(&file, path, 0, &err) != RAYO_OK)
        return 0;
    if (rayo_camera_spec_build(&file.camera, &camera, &err) != RAYO_OK) {
        rayo_scene_file_free(&file);
        return 0;
    }
    if (repeats > MAX_RUNS)
        repeats = MAX_RUNS;
    for (k = 0; k < repeats && ok; k++)
        for (mode = 0; mode < 2 && ok; mode++) {
            rayo_image image;
            double start;
            rayo_render_options_init(&options);
            options.shade = mode == 0 ? RAYO_SHADE_HIT : RAYO_SHADE_PHONG;
            options.depth = file.depth;
            options.threads = 1;
            start = cpu_now();
            ok = rayo_render_image(&camera, file.scene, &options, &image,
                                   &err) == RAYO_OK;
            (mode == 0 ? hit : phong)[k] = cpu_now() - start;
            if (ok)
                rayo_image_free(&image);
        }
    rayo_scene_file_free(&file);
    *hit_s = median(hit, repeats);
    *phong_s = median(phong, repeats);
    return ok;
}

enum { CPU, WALL, RSS, SETUP, READ, BUILD, SETUP_CPU };

static double series_median(const mrow *r, int series)
{
    return row_median(r, series == CPU     ? r->cpu
                         : series == WALL  ? r->wall
                         : series == RSS   ? r->rss
                         : series == SETUP ? r->setup
                         : series == READ  ? r->read
                         : series == BUILD ? r->build
                                           : r->setup_cpu);
}

/* The rows: which mesh, Embree's (captured) or not, at most how many runs
 * (0: one a round), the command with {M} for the mesh. */
typedef struct row_spec {
    int row;
    const char *mesh;
    int captures, runs;
    const char *command;
} row_spec;

static const row_spec specs[] = {
    {M_HIT, "1m", 0, 0,
     RAYO_MESH "--shade hit -j 1 --format pbm -o /dev/null"},
    {M_PHONG, "1m", 0, 0,
     RAYO_MESH "--shade phong -j 1 --format ppm -o /dev/null"},
    {M_SETUP_1, "1m", 0, 0,
     RAYO_MESH "-W 1 -H 1 -j 1 --format ppm -o /dev/null"},
    {M_SETUP_2, "1m", 0, 0,
     RAYO_MESH "-W 1 -H 1 -j 2 --format ppm -o /dev/null"},
    {M_E_OCC, "1m", 1, 0, EMBREE_MESH "--mode occlusion --threads 1"},
    {M_E_OCC_HIGH, "1m", 1, 0,
     EMBREE_MESH "--mode occlusion --quality high --threads 1"},
    {M_E_SHADOW, "1m", 1, 0, EMBREE_MESH "--mode shadow --threads 1"},
    {M_E_SETUP, "1m", 1, 0, EMBREE_MESH "--threads 0 --repeat 0"},
    {M_POVRAY, "1m", 0, 1,
     TIMED "povray +I\"$BENCH_TMP/scan-{M}.pov\" "
           "+O\"$BENCH_TMP/scan-pov.png\" +W1920 +H1080 -D +WT1 -A +FN "
           "-GA File_Gamma=1.0 2>/dev/null"},
    {T_RAYO, "10m", 0, 1, RAYO_MESH "--shade phong --format ppm -o /dev/null"},
    {T_E_OCC, "10m", 1, 1, EMBREE_MESH "--mode occlusion --threads 0"},
    {T_E_SHADOW, "10m", 1, 1, EMBREE_MESH "--mode shadow --threads 0"},
    {K_E_OCC, "100k", 1, 0, EMBREE_MESH "--mode occlusion --threads 1"},
    {K_E_SHADOW, "100k", 1, 0, EMBREE_MESH "--mode shadow --threads 1"},
};

/* A figure: a row's median of a series, times scale, in unit. */
typedef struct figure_spec {
    const char *key, *label;
    int row, series;
    double scale;
    const char *unit;
} figure_spec;

#define MIB (1.0 / 1024)
#define GIB (1.0 / 1048576)
static const figure_spec figures[] = {
    {"mesh_rayo_hit_s", "meshes 1M: rayo --shade hit, -j 1", M_HIT, CPU, 1e3,
     "ms"},
    {"mesh_embree_occlusion_s", "meshes 1M: Embree occlusion, 1 thread",
     M_E_OCC, CPU, 1e3, "ms"},
    {"mesh_embree_occlusion_high_s",
     "meshes 1M: Embree occlusion, high quality, 1 thread", M_E_OCC_HIGH, CPU,
     1e3, "ms"},
    {"mesh_rayo_phong_s", "meshes 1M: rayo phong, -j 1", M_PHONG, CPU, 1e3,
     "ms"},
    {"mesh_embree_shadow_s", "meshes 1M: Embree primary + shadow, 1 thread",
     M_E_SHADOW, CPU, 1e3, "ms"},
    {"mesh_povray_s", "meshes 1M: POV-Ray, +WT1 (one run)", M_POVRAY, CPU,
     1e3, "ms"},
    {"mesh_rayo_setup_1_s", "meshes 1M: rayo setup, -j 1, wall", M_SETUP_1,
     WALL, 1e3, "ms"},
    {"mesh_rayo_setup_2_s", "meshes 1M: rayo setup, -j 2, wall", M_SETUP_2,
     WALL, 1e3, "ms"},
    {"mesh_rayo_setup_1_cpu_s", "meshes 1M: rayo setup, -j 1", M_SETUP_1, CPU,
     1e3, "ms"},
    {"mesh_rayo_setup_2_cpu_s", "meshes 1M: rayo setup, -j 2", M_SETUP_2, CPU,
     1e3, "ms"},
    {"mesh_embree_setup_s",
     "meshes 1M: Embree read + build, all threads, wall",
     M_E_SETUP, SETUP, 1e3, "ms"},
    {"mesh_embree_read_s", "meshes 1M:   of which reading the STL", M_E_SETUP,
     READ, 1e3, "ms"},
    {"mesh_embree_setup_1_cpu_s", "meshes 1M: Embree read + build, 1 thread",
     M_E_OCC, SETUP_CPU, 1e3, "ms"},
    {"mesh_embree_build_1_s", "meshes 1M: Embree build, 1 thread, wall",
     M_E_OCC, BUILD, 1e3, "ms"},
    {"mesh_embree_build_high_1_s",
     "meshes 1M: Embree build, high quality, 1 thread, wall", M_E_OCC_HIGH,
     BUILD, 1e3, "ms"},
    {"mesh_rayo_rss_mib", "meshes 1M: rayo phong -j 1, peak RSS", M_PHONG, RSS,
     MIB, "MiB"},
    {"mesh_embree_rss_mib", "meshes 1M: Embree primary + shadow, peak RSS",
     M_E_SHADOW, RSS, MIB, "MiB"},
    {"mesh_rayo_10m_rss_gib", "meshes 10M: rayo phong, peak RSS", T_RAYO, RSS,
     GIB, "GiB"},
    {"mesh_embree_10m_rss_gib",
     "meshes 10M: Embree primary + shadow, peak RSS",
     T_E_SHADOW, RSS, GIB, "GiB"},
    {"mesh_rayo_10m_wall_s", "meshes 10M: rayo phong, all threads, wall",
     T_RAYO, WALL, 1, "s"},
};

/* A target: a row's figure over another's, at most limit (the other
 * row's availability decides whether it is judged). */
typedef struct ratio_target {
    const char *label;
    int row, series, peer, peer_series;
    double limit;
} ratio_target;

static const ratio_target ratios[] = {
    {"meshes 1M: hit, rayo / Embree occlusion", M_HIT, CPU, M_E_OCC, CPU,
     1.0},
    {"meshes 1M: hit, rayo / Embree high quality", M_HIT, CPU, M_E_OCC_HIGH,
     CPU, 1.0},
    {"meshes 1M: phong, rayo / Embree primary + shadow", M_PHONG, CPU,
     M_E_SHADOW, CPU, 1.0},
    {"meshes 1M: setup -j 2, rayo / Embree (wall)", M_SETUP_2, WALL,
     M_E_SETUP, SETUP, 1.0},
    {"meshes 1M: peak RSS, rayo / Embree", M_PHONG, RSS, M_E_SHADOW, RSS,
     1.0},
    {"meshes 1M: phong, rayo / POV-Ray", M_PHONG, CPU, M_POVRAY, CPU, 0.1},
    {"meshes 1M: setup, -j 2 / -j 1 (wall)", M_SETUP_2, WALL, M_SETUP_1,
     WALL, 0.55},
};

/* The command: its template with each {M} replaced by the mesh's size. */
static void set_row(mrow *r, int available, int captures, int runs,
                    const char *command, const char *size)
{
    size_t n = 0, m = strlen(size);
    while (*command != '\0' && n + m + 1 < sizeof r->command) {
        if (strncmp(command, "{M}", 3) == 0) {
            memcpy(r->command + n, size, m);
            n += m;
            command += 3;
        } else {
            r->command[n++] = *command++;
        }
    }
    r->command[n] = '\0';
    r->available = available;
    r->captures = captures;
    r->runs = runs;
}

void bench_meshes(bench_table *table)
{
    static mrow rows[ROW_COUNT];
    const char *build = getenv("RAYO_BUILD");
    char path[4096];
    int embree, povray, have_k, have_m, have_t, i, k;
    int repeats = bench_repeats(table);
    double ns[3][2], shadow_rays[3];
    const char *sizes[3] = {"100k", "1m", "10m"};

    printf("meshes: bench/scan/scan_mesh.c's scan on a floor, 1920x1080, "
           "one point light; medians; processor time unless wall\n");
    fflush(stdout);
    snprintf(path, sizeof path, "%s/bench/embree-rays",
             build != NULL ? build : "build");
    embree = access(path, X_OK) == 0;
    have_k = mesh_exists("100k");
    have_m = mesh_exists("1m");
    have_t = mesh_exists("10m");
    povray = have_m &&
             bench_run_measured("command -v povray >/dev/null && python3 "
                                "\"$RAYO_SOURCE/bench/scene_to_pov.py\" "
                                "\"$RAYO_BUILD/bench/scan-1m.scene\" > "
                                "\"$BENCH_TMP/scan-1m.pov\"",
                                NULL, 0, NULL) >= 0;
    memset(rows, 0, sizeof rows);
    for (i = 0; i < (int)(sizeof specs / sizeof specs[0]); i++) {
        const row_spec *r = &specs[i];
        int available = mesh_exists(r->mesh) && (!r->captures || embree) &&
                        (r->row != M_POVRAY || povray);
        set_row(&rows[r->row], available, r->captures, r->runs, r->command,
                r->mesh);
    }
    for (k = 0; k < repeats; k++)
        for (i = 0; i < ROW_COUNT; i++)
            run_once(&rows[i]);

    /* Per ray, rayo in process: hit over the pixels, phong over the rays
     * Embree counts for the same frame (primary and shadow). */
    shadow_rays[0] = bench_output_value(rows[K_E_SHADOW].output, "rays");
    shadow_rays[1] = bench_output_value(rows[M_E_SHADOW].output, "rays");
    shadow_rays[2] = bench_output_value(rows[T_E_SHADOW].output, "rays");
    for (i = 0; i < 3; i++) {
        double hit_s = -1, phong_s = -1;
        int have = i == 0 ? have_k : i == 1 ? have_m : have_t;
        ns[i][0] = ns[i][1] = -1;
        if (have && rayo_in_process(sizes[i], i == 2 ? 1 : repeats, &hit_s,
                                    &phong_s)) {
            ns[i][0] = hit_s * 1e9 / MESH_PIXELS;
            ns[i][1] = shadow_rays[i] > 0 ? phong_s * 1e9 / shadow_rays[i]
                                          : -1;
        }
    }

    for (i = 0; i < (int)(sizeof figures / sizeof figures[0]); i++) {
        const figure_spec *f = &figures[i];
        const mrow *r = &rows[f->row];
        double value = series_median(r, f->series);
        bench_add_peer(table, f->key, f->label,
                       value < 0 ? -1 : value * f->scale, f->unit,
                       r->available);
    }
    /* Setup in processor time, which a busy machine disturbs less than
     * the wall clock the target is in. */
    bench_add_peer(table, "mesh_setup_cpu_ratio",
                   "meshes 1M: setup processor time, rayo / Embree",
                   bench_ratio(series_median(&rows[M_SETUP_1], CPU),
                               series_median(&rows[M_E_OCC], SETUP_CPU)),
                   "x", rows[M_E_OCC].available);
    for (i = 0; i < 3; i++) {
        char key[64], label[128];
        int have = i == 0 ? have_k : i == 1 ? have_m : have_t;
        const mrow *occ = &rows[i == 0 ? K_E_OCC : i == 1 ? M_E_OCC : T_E_OCC];
        const mrow *shadow =
            &rows[i == 0 ? K_E_SHADOW : i == 1 ? M_E_SHADOW : T_E_SHADOW];
        snprintf(key, sizeof key, "mesh_%s_rayo_hit_ns", sizes[i]);
        snprintf(label, sizeof label, "meshes %s: rayo hit, per ray",
                 sizes[i]);
        bench_add_peer(table, key, label, ns[i][0], "ns", have);
        snprintf(key, sizeof key, "mesh_%s_embree_occlusion_ns", sizes[i]);
        snprintf(label, sizeof label, "meshes %s: Embree occlusion, per ray",
                 sizes[i]);
        bench_add_peer(table, key, label, row_median(occ, occ->ns), "ns",
                       occ->available);
        if (i == 1)
            bench_add_peer(
                table, "mesh_1m_embree_occlusion_high_ns",
                "meshes 1m: Embree occlusion, high quality, per ray",
                row_median(&rows[M_E_OCC_HIGH], rows[M_E_OCC_HIGH].ns), "ns",
                rows[M_E_OCC_HIGH].available);
        snprintf(key, sizeof key, "mesh_%s_rayo_phong_ns", sizes[i]);
        snprintf(label, sizeof label, "meshes %s: rayo phong, per ray",
                 sizes[i]);
        bench_add_peer(table, key, label, ns[i][1], "ns",
                       have && shadow->available);
        snprintf(key, sizeof key, "mesh_%s_embree_shadow_ns", sizes[i]);
        snprintf(label, sizeof label,
                 "meshes %s: Embree primary + shadow, per ray", sizes[i]);
        bench_add_peer(table, key, label, row_median(shadow, shadow->ns),
                       "ns", shadow->available);
    }

    for (i = 0; i < (int)(sizeof ratios / sizeof ratios[0]); i++) {
        const ratio_target *t = &ratios[i];
        bench_target_peer(
            table, t->label,
            bench_ratio(series_median(&rows[t->row], t->series),
                        series_median(&rows[t->peer], t->peer_series)),
            t->limit, 1, rows[t->peer].available);
    }
    bench_target_peer(table, "meshes 10M: rayo peak RSS (GiB)",
                      series_median(&rows[T_RAYO], RSS) * GIB, 24, 1,
                      have_t);
    {
        double e_occ =
            bench_ratio(row_median(&rows[T_E_OCC], rows[T_E_OCC].ns),
                        row_median(&rows[K_E_OCC], rows[K_E_OCC].ns));
        double e_sh =
            bench_ratio(row_median(&rows[T_E_SHADOW], rows[T_E_SHADOW].ns),
                        row_median(&rows[K_E_SHADOW], rows[K_E_SHADOW].ns));
        int peers = have_k && have_t && embree;
        int both = peers && e_occ > 0 && e_sh > 0;
        bench_add_peer(table, "mesh_embree_growth_occlusion",
                       "meshes: Embree occlusion per ray, 10M / 100k", e_occ,
                       "x", peers);
        bench_add_peer(table, "mesh_embree_growth_shadow",
                       "meshes: Embree primary + shadow per ray, 10M / 100k",
                       e_sh, "x", peers);
        /* The limit is Embree's growth in this run; without it, the
         * issue's figures for Embree (skipped all the same). */
        bench_target_peer(table, "meshes: rayo hit per ray, 10M / 100k",
                          bench_ratio(ns[2][0], ns[0][0]),
                          both ? e_occ : 1.88, 1, both);
        bench_target_peer(table, "meshes: rayo phong per ray, 10M / 100k",
                          bench_ratio(ns[2][1], ns[0][1]),
                          both ? e_sh : 1.66, 1, both);
    }
}
