/*
 * peers.c - rayo against Embree and POV-Ray on the benchmark's field of
 * 100,000 spheres (issue 17), side by side in one run.
 *
 * The field is bench/field_scene.py's scene file (1920x1080, one point
 * light), written once into $BENCH_TMP.  Every row is a whole process
 * run from here, its processor time (user + system, from wait4) the
 * figure unless the row says wall: rayo's `--shade hit` and phong
 * renders on one thread; the Embree program of the project's own
 * ($RAYO_BUILD/bench/embree-rays, bench/embree/embree_rays.c), which
 * casts the same primary rays as occlusion queries, or as nearest-hit
 * queries with one shadow ray per lit hit, and prints its own timings;
 * POV-Ray 3.7 on one thread (+WT1) on the scene translated by
 * bench/scene_to_pov.py.  Setup (reading the file, building the
 * hierarchy) is rayo's render at -W 1 -H 1 against Embree's own timer
 * around its read and build; per ray is rayo's whole process less its
 * one-thread setup, over the rays Embree counts for the same frame.
 * Embree's rows put the ground plane in its scene as a quad; the "plane
 * first" rows test it in the program before Embree's hierarchy, as rayo
 * tests its unbounded planes before its own (per ray figures only).
 * The runs of all rows are interleaved, each the best of twice --repeat
 * (POV-Ray's of --repeat).
 * Without the Embree program (no libembree-dev when it was built) or
 * without `povray`, their rows and targets say "skipped".
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench.h"

#define FIELD_WIDTH 1920
#define FIELD_HEIGHT 1080
#define CAPTURE_BYTES 4096
#define CHECKSUM_LABEL "peers: Embree's hits - rayo's black pixels"

/* One command and the best of its runs. */
typedef struct row {
    const char *command;
    int captures;           /* its standard output is "key value" lines */
    double wall, cpu;       /* best of the runs; -1 when one failed */
    double rays_s, setup_s; /* the best of the program's own timers */
    double read_s, build_s;
    char output[CAPTURE_BYTES];
    int failed;
} row;

enum {
    RAYO_HIT,
    RAYO_PHONG,
    RAYO_PHONG_J2,
    RAYO_SETUP_1,
    RAYO_SETUP_ALL,
    EMBREE_OCCLUSION,
    EMBREE_OCCLUSION_16,
    EMBREE_SHADOW,
    EMBREE_SHADOW_16,
    EMBREE_SETUP_ALL,
    EMBREE_FIRST_OCCLUSION,
    EMBREE_FIRST_OCCLUSION_16,
    EMBREE_FIRST_SHADOW,
    EMBREE_FIRST_SHADOW_16,
    POVRAY,
    ROW_COUNT
};

#define RAYO_FIELD "\"$RAYO\" render \"$BENCH_TMP/field.scene\" --raw "
#define EMBREE "\"$RAYO_BUILD/bench/embree-rays\" \"$BENCH_TMP/field.scene\" "

static const char *const commands[ROW_COUNT] = {
    RAYO_FIELD "--shade hit -j 1 --format pbm -o /dev/null",
    RAYO_FIELD "--shade phong -j 1 --format ppm -o /dev/null",
    RAYO_FIELD "--shade phong -j 2 --format ppm -o /dev/null",
    RAYO_FIELD "-W 1 -H 1 -j 1 --format ppm -o /dev/null",
    RAYO_FIELD "-W 1 -H 1 --format ppm -o /dev/null",
    EMBREE "--mode occlusion --threads 1",
    EMBREE "--mode occlusion --packet 16 --threads 1",
    EMBREE "--mode shadow --threads 1",
    EMBREE "--mode shadow --packet 16 --threads 1",
    EMBREE "--threads 0 --repeat 0",
    EMBREE "--planes first --mode occlusion --threads 1",
    EMBREE "--planes first --mode occlusion --packet 16 --threads 1",
    EMBREE "--planes first --mode shadow --threads 1",
    EMBREE "--planes first --mode shadow --packet 16 --threads 1",
    ("povray +I\"$BENCH_TMP/field.pov\" +O\"$BENCH_TMP/field-pov.png\" "
     "+W1920 +H1080 -D +WT1 -A +FN -GA File_Gamma=1.0 2>/dev/null"),
};

/* A row that failed once has no figures. */
static void fail_row(row *r)
{
    r->failed = 1;
    r->wall = r->cpu = r->rays_s = r->setup_s = r->read_s = r->build_s = -1;
}

static void run_once(row *r)
{
    double cpu = -1, wall;
    char output[CAPTURE_BYTES];
    if (r->failed)
        return;
    wall = bench_run_measured(r->command, r->captures ? output : NULL,
                              sizeof output, &cpu);
    if (wall < 0) {
        fail_row(r);
        return;
    }
    r->wall = bench_best(r->wall, wall);
    r->cpu = bench_best(r->cpu, cpu);
    if (r->captures) {
        double rays_s = bench_output_value(output, "rays_s");
        double setup_s = bench_output_value(output, "setup_s");
        if (rays_s < 0 || setup_s < 0) {
            fail_row(r);
            return;
        }
        if (r->rays_s < 0 || rays_s < r->rays_s)
            memcpy(r->output, output, sizeof output);
        r->rays_s = bench_best(r->rays_s, rays_s);
        r->setup_s = bench_best(r->setup_s, setup_s);
        r->read_s =
            bench_best(r->read_s, bench_output_value(output, "read_s"));
        r->build_s =
            bench_best(r->build_s, bench_output_value(output, "build_s"));
    }
}

/* Black pixels (set bits) of a raw PBM as rayo writes it; -1 if none. */
static long pbm_black(const char *path)
{
    FILE *in = fopen(path, "rb");
    unsigned w, h, i, j;
    long black = 0;
    if (in == NULL)
        return -1;
    if (fscanf(in, "P4 %u %u", &w, &h) != 2 || fgetc(in) == EOF) {
        fclose(in);
        return -1;
    }
    for (j = 0; j < h; j++)
        for (i = 0; i < w; i += 8) {
            int byte = fgetc(in), bit;
            if (byte == EOF) {
                fclose(in);
                return -1;
            }
            for (bit = 0; bit < 8 && i + (unsigned)bit < w; bit++)
                black += (byte >> (7 - bit)) & 1;
        }
    fclose(in);
    return black;
}

/* A figure in ms (seconds given), or "skipped" / "failed". */
static void add_ms(bench_table *table, const char *key, const char *label,
                   double seconds, int available)
{
    if (!available)
        bench_add(table, key, label, -1, "skipped");
    else if (seconds < 0)
        bench_add(table, key, label, -1, "failed");
    else
        bench_add(table, key, label, seconds * 1e3, "ms");
}

/* Nanoseconds per ray of rayo's render after setup (processor time). */
static double rayo_ns_per_ray(const row *render, const row *setup, double rays)
{
    if (render->cpu < 0 || setup->cpu < 0 || !(rays > 0))
        return -1;
    return (render->cpu - setup->cpu) * 1e9 / rays;
}

static double embree_ns_per_ray(const row *r)
{
    return r->failed ? -1 : bench_output_value(r->output, "ns_per_ray");
}

void bench_peers(bench_table *table)
{
    static row rows[ROW_COUNT];
    const char *build = getenv("RAYO_BUILD");
    char embree_path[4096];
    int embree, povray, i, k, repeats = bench_repeats(table);
    double primary = (double)FIELD_WIDTH * FIELD_HEIGHT, shadow_rays;
    long black;

    printf("peers: field_scene.py, 100000 spheres, %dx%d, one point light; "
           "processor time unless wall\n",
           FIELD_WIDTH, FIELD_HEIGHT);
    fflush(stdout);
    if (bench_run_measured(
            "python3 \"$RAYO_SOURCE/bench/field_scene.py\" "
            "--size 1920x1080 > \"$BENCH_TMP/field.scene\" && " RAYO_FIELD
            "--shade hit --format pbm -o "
            "\"$BENCH_TMP/field-hit.pbm\"",
            NULL, 0, NULL) < 0) {
        bench_add(table, "peers_error", "peers: writing the field scene", -1,
                  "failed");
        return;
    }
    snprintf(embree_path, sizeof embree_path, "%s/bench/embree-rays",
             build != NULL ? build : "build");
    embree = access(embree_path, X_OK) == 0;
    povray = bench_run_measured("command -v povray >/dev/null && python3 "
                                "\"$RAYO_SOURCE/bench/scene_to_pov.py\" "
                                "\"$BENCH_TMP/field.scene\" > "
                                "\"$BENCH_TMP/field.pov\"",
                                NULL, 0, NULL) >= 0;
    for (i = 0; i < ROW_COUNT; i++) {
        rows[i].command = commands[i];
        rows[i].captures =
            i >= EMBREE_OCCLUSION && i <= EMBREE_FIRST_SHADOW_16;
        rows[i].wall = rows[i].cpu = rows[i].rays_s = rows[i].setup_s = -1;
        rows[i].read_s = rows[i].build_s = -1;
        rows[i].output[0] = '\0';
        rows[i].failed =
            (rows[i].captures && !embree) || (i == POVRAY && !povray);
    }
    /* Twice --repeat rounds (rayo's per ray is a difference of two
     * figures, which noise hits twice); POV-Ray, seconds a run, in the
     * first --repeat of them. */
    for (k = 0; k < 2 * repeats; k++)
        for (i = 0; i < ROW_COUNT; i++)
            if (i != POVRAY || k < repeats)
                run_once(&rows[i]);

    add_ms(table, "peers_rayo_hit_s", "peers: rayo --shade hit, -j 1",
           rows[RAYO_HIT].cpu, 1);
    add_ms(table, "peers_embree_occlusion_s",
           "peers: Embree occlusion rays, 1 thread",
           rows[EMBREE_OCCLUSION].cpu, embree);
    add_ms(table, "peers_rayo_phong_s", "peers: rayo phong, -j 1",
           rows[RAYO_PHONG].cpu, 1);
    add_ms(table, "peers_embree_shadow_s",
           "peers: Embree primary + shadow rays, 1 thread",
           rows[EMBREE_SHADOW].cpu, embree);
    add_ms(table, "peers_povray_s", "peers: POV-Ray, +WT1", rows[POVRAY].cpu,
           povray);
    add_ms(table, "peers_rayo_setup_s",
           "peers: rayo setup (-W 1 -H 1), all threads, wall",
           rows[RAYO_SETUP_ALL].wall, 1);
    add_ms(table, "peers_rayo_setup_1_s", "peers: rayo setup, -j 1",
           rows[RAYO_SETUP_1].cpu, 1);
    add_ms(table, "peers_embree_setup_s",
           "peers: Embree read + build, all threads, wall",
           rows[EMBREE_SETUP_ALL].setup_s, embree);
    add_ms(table, "peers_embree_read_s",
           "peers:   of which reading the file (1 thread)",
           rows[EMBREE_SETUP_ALL].read_s, embree);
    add_ms(table, "peers_embree_build_s",
           "peers:   and Embree's build, all threads",
           rows[EMBREE_SETUP_ALL].build_s, embree);
    add_ms(table, "peers_embree_setup_1_s",
           "peers: Embree read + build, 1 thread, wall",
           rows[EMBREE_OCCLUSION].setup_s, embree);
    add_ms(table, "peers_rayo_phong_j1_wall_s",
           "peers: rayo phong, -j 1, wall", rows[RAYO_PHONG].wall, 1);
    add_ms(table, "peers_rayo_phong_j2_wall_s",
           "peers: rayo phong, -j 2, wall", rows[RAYO_PHONG_J2].wall, 1);

    /* Per ray after setup: rayo's primary rays are the pixels; its phong
     * rays are counted as Embree counts them (rayo also reflects). */
    shadow_rays = rows[EMBREE_SHADOW].failed
                      ? -1
                      : bench_output_value(rows[EMBREE_SHADOW].output, "rays");
    bench_add_peer(table, "peers_rayo_hit_ns",
              "peers: rayo hit, per ray after setup",
              rayo_ns_per_ray(&rows[RAYO_HIT], &rows[RAYO_SETUP_1], primary),
              "ns", 1);
    bench_add_peer(table, "peers_embree_occlusion_ns",
              "peers: Embree occlusion, per ray",
              embree_ns_per_ray(&rows[EMBREE_OCCLUSION]), "ns", embree);
    bench_add_peer(table, "peers_embree_occlusion16_ns",
              "peers: Embree occlusion, 16-ray packets, per ray",
              embree_ns_per_ray(&rows[EMBREE_OCCLUSION_16]), "ns", embree);
    bench_add_peer(
        table, "peers_rayo_phong_ns", "peers: rayo phong, per ray after setup",
        rayo_ns_per_ray(&rows[RAYO_PHONG], &rows[RAYO_SETUP_1], shadow_rays),
        "ns", embree);
    bench_add_peer(table, "peers_embree_shadow_ns",
              "peers: Embree primary + shadow, per ray",
              embree_ns_per_ray(&rows[EMBREE_SHADOW]), "ns", embree);
    bench_add_peer(table, "peers_embree_shadow16_ns",
              "peers: Embree primary + shadow, packets, per ray",
              embree_ns_per_ray(&rows[EMBREE_SHADOW_16]), "ns", embree);
    /* The same with the plane tested first, outside Embree (rayo's way). */
    bench_add_peer(table, "peers_embree_first_occlusion_ns",
              "peers: Embree, plane first: occlusion, per ray",
              embree_ns_per_ray(&rows[EMBREE_FIRST_OCCLUSION]), "ns", embree);
    bench_add_peer(table, "peers_embree_first_occlusion16_ns",
              "peers: Embree, plane first: occlusion, packets",
              embree_ns_per_ray(&rows[EMBREE_FIRST_OCCLUSION_16]), "ns",
              embree);
    bench_add_peer(table, "peers_embree_first_shadow_ns",
              "peers: Embree, plane first: + shadow, per ray",
              embree_ns_per_ray(&rows[EMBREE_FIRST_SHADOW]), "ns", embree);
    bench_add_peer(table, "peers_embree_first_shadow16_ns",
              "peers: Embree, plane first: + shadow, packets",
              embree_ns_per_ray(&rows[EMBREE_FIRST_SHADOW_16]), "ns", embree);
    bench_add_peer(table, "peers_hit_per_ray_ratio",
              "peers: per ray, rayo hit / Embree single rays",
              bench_ratio(bench_value(table, "peers_rayo_hit_ns"),
                    bench_value(table, "peers_embree_occlusion_ns")),
              "x", embree);
    bench_add_peer(table, "peers_hit_per_ray_ratio16",
              "peers: per ray, rayo hit / Embree packets",
              bench_ratio(bench_value(table, "peers_rayo_hit_ns"),
                    bench_value(table, "peers_embree_occlusion16_ns")),
              "x", embree);
    bench_add_peer(table, "peers_phong_per_ray_ratio",
              "peers: per ray, rayo phong / Embree single rays",
              bench_ratio(bench_value(table, "peers_rayo_phong_ns"),
                    bench_value(table, "peers_embree_shadow_ns")),
              "x", embree);
    bench_add_peer(table, "peers_phong_per_ray_ratio16",
              "peers: per ray, rayo phong / Embree packets",
              bench_ratio(bench_value(table, "peers_rayo_phong_ns"),
                    bench_value(table, "peers_embree_shadow16_ns")),
              "x", embree);

    /* The checksum: Embree's hits are rayo's black pixels (a difference
     * of a few pixels would be float against double; none is seen). */
    {
        const char *tmp = getenv("BENCH_TMP");
        char path[4096];
        snprintf(path, sizeof path, "%s/field-hit.pbm", tmp ? tmp : ".");
        black = pbm_black(path);
        if (!embree)
            bench_add(table, "peers_hit_checksum", CHECKSUM_LABEL, -1,
                      "skipped");
        else if (rows[EMBREE_OCCLUSION].failed || black < 0)
            bench_add(table, "peers_hit_checksum", CHECKSUM_LABEL, -1,
                      "failed");
        else
            bench_add(table, "peers_hit_checksum", CHECKSUM_LABEL,
                      bench_output_value(rows[EMBREE_OCCLUSION].output,
                                         "hits") - (double)black,
                      "px");
    }

    bench_target_peer(
        table, "peers: hit, rayo / Embree occlusion",
        bench_ratio(rows[RAYO_HIT].cpu, rows[EMBREE_OCCLUSION].cpu), 1.0, 1,
        embree);
    bench_target_peer(
        table, "peers: phong, rayo / Embree primary + shadow",
        bench_ratio(rows[RAYO_PHONG].cpu, rows[EMBREE_SHADOW].cpu), 1.2, 1,
        embree);
    bench_target_peer(
        table, "peers: setup, rayo / Embree read + build (wall)",
        bench_ratio(rows[RAYO_SETUP_ALL].wall, rows[EMBREE_SETUP_ALL].setup_s),
        1.0, 1, embree);
    bench_target_peer(
        table, "peers: phong speed-up, -j 1 / -j 2 (wall)",
        bench_ratio(rows[RAYO_PHONG].wall, rows[RAYO_PHONG_J2].wall), 1.8, 0,
        1);
    bench_target_peer(table, "peers: rayo phong / POV-Ray",
                      bench_ratio(rows[RAYO_PHONG].cpu, rows[POVRAY].cpu),
                      0.25, 1, povray);
}
