/*
 * embree_rays.c - the benchmark's yardstick: the rays rayo casts for a
 * scene file, cast through Embree 3 instead (issue 17).
 *
 * `make bench` compares rayo with the state of the art in CPU ray
 * intersection on the same work.  This program reads the scene file that
 * bench/field_scene.py writes (scene.c: only that subset, the camera's
 * size, fov, origin, look-at and up, point lights, planes, spheres and
 * binary STL meshes; materials and settings are read past), puts the
 * spheres into one Embree RTC_GEOMETRY_TYPE_SPHERE_POINT geometry, the
 * meshes' triangles into one RTC_GEOMETRY_TYPE_TRIANGLE geometry (mesh.c)
 * and each plane into a large
 * quad (PLANE_HALF_SIZE from the camera's foot on the plane), and casts
 * through it exactly the primary rays of rayo's camera (include/rayo/
 * camera.h: x = i - w/2, y = j - h/2, direction x right - y up + f
 * forward normalised, computed in doubles as rayo does, then rounded to
 * floats, Embree's precision).  Modes:
 *   occlusion  every primary ray as an occlusion query: the work of
 *              `rayo render --shade hit`;
 *   shadow     every primary ray as a nearest-hit query, and from each
 *              hit whose normal (turned to face the ray) faces the first
 *              point light, one shadow ray towards it: the rays of a
 *              phong render with shadows, shading nothing (rayo also
 *              follows mirror reflections; this does not).
 * Rays (trace.c) go one at a time (rtcIntersect1/rtcOccluded1) or in
 * 16-ray packets of 4x4 pixels (--packet 16), always on the calling thread;
 * --planes first tests the planes in the program, before Embree's
 * hierarchy and without it (rayo keeps its unbounded planes outside its
 * hierarchy and tests them first: a primary ray's occlusion query that
 * meets the ground is then one plane test); the default puts each plane
 * in Embree's scene with the spheres, the way Embree is meant to be used.
 * --threads sets Embree's device threads, which build the hierarchy
 * (0, the default: every CPU); --quality high builds with Embree's
 * RTC_BUILD_QUALITY_HIGH (spatial splits) instead of its default; --repeat
 * N casts them N times (0: none, setup alone) and reports the best pass.
 *
 *   embree-rays SCENE [--mode occlusion|shadow] [--packet 1|16]
 *               [--threads N] [--repeat N] [--planes bvh|first]
 *               [--quality default|high] [--pbm FILE]
 *
 * It prints "key value" lines: read_s, build_s, setup_s (wall seconds),
 * setup_cpu_s (the processor time of reading and building, all threads),
 * rays (cast in one pass), rays_s (the calling thread's processor
 * seconds of the best pass), ns_per_ray, the checksums hits (primary rays
 * that hit: the black pixels of rayo's --shade hit PBM) and lit (shadow
 * rays that reached the light), and peak_rss_kib (getrusage's, which on
 * Linux also counts what the process held before its exec).  --pbm
 * writes the hits as a raw PBM, for tests.  Errors: one line on stderr
 * (with the line number for the scene), exit 2 (bad input) or 1 (I/O,
 * Embree).  This is a benchmark tool: rayo never links Embree.
 */
#define _POSIX_C_SOURCE 200809L

#include "scene.h"

#include <embree3/rtcore.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "mesh.h"
#include "trace.h"

#define PLANE_HALF_SIZE 1e5


static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* The calling thread's processor time: the rays are all cast on it, and
 * Embree's own threads (the build's, when --threads is not 1) may still
 * be spinning while they are. */
static double process_cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static camera make_camera(const scene *s)
{
    camera c;
    c.origin = s->origin;
    c.focal = (double)s->width /
              (2.0 * tan(s->fov * 3.14159265358979323846 / 360.0));
    c.right = rayo_vec3_make(1, 0, 0);
    c.up = rayo_vec3_make(0, 1, 0);
    c.forward = rayo_vec3_make(0, 0, 1);
    if (s->aimed) {
        rayo_vec3 f = rayo_vec3_sub(s->look_at, s->origin), right;
        if (rayo_vec3_dot(f, f) == 0) {
            fprintf(stderr, "embree-rays: the look-at point equals the "
                            "camera origin\n");
            exit(2);
        }
        f = rayo_vec3_normalize(f);
        right = rayo_vec3_cross(s->up, f);
        if (!(sqrt(rayo_vec3_dot(right, right)) > 1e-12 * sqrt(rayo_vec3_dot(s->up, s->up)))) {
            fprintf(stderr, "embree-rays: the up vector is parallel to the "
                            "view direction\n");
            exit(2);
        }
        c.forward = f;
        c.right = rayo_vec3_normalize(right);
        c.up = rayo_vec3_cross(f, c.right);
    }
    return c;
}

/* ---- Embree ---- */

static void embree_error(void *user, enum RTCError code, const char *text)
{
    (void)user;
    fprintf(stderr, "embree-rays: Embree error %d: %s\n", (int)code,
            text ? text : "");
    exit(1);
}

static RTCScene build(RTCDevice device, const scene *s, const camera *cam,
                      int planes_first, int high_quality)
{
    RTCScene es = rtcNewScene(device);
    size_t k;
    if (high_quality)
        rtcSetSceneBuildQuality(es, RTC_BUILD_QUALITY_HIGH);
    attach_meshes(device, es, s);
    if (s->sphere_count > 0) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                           RTC_FORMAT_FLOAT4,
                                           4 * sizeof(float), s->sphere_count);
        memcpy(v, s->spheres, s->sphere_count * 4 * sizeof(float));
        rtcCommitGeometry(g);
        rtcAttachGeometry(es, g);
        rtcReleaseGeometry(g);
    }
    for (k = 0; planes_first == 0 && k < s->plane_count; k++) {
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_QUAD);
        rayo_vec3 n = s->plane_normal[k];
        /* The camera's foot on the plane, and the camera's right (else
         * any direction) in the plane. */
        rayo_vec3 foot = rayo_vec3_sub(cam->origin,
                        rayo_vec3_scale(n, rayo_vec3_dot(rayo_vec3_sub(cam->origin, s->plane_point[k]), n)));
        rayo_vec3 u = rayo_vec3_sub(cam->right, rayo_vec3_scale(n, rayo_vec3_dot(cam->right, n)));
        rayo_vec3 w, corner[4];
        float *v =
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                                    RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4);
        unsigned *q =
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0,
                                    RTC_FORMAT_UINT4, 4 * sizeof(unsigned), 1);
        int c;
        if (!(rayo_vec3_dot(u, u) > 1e-12))
            u = rayo_vec3_cross(n, fabs(n.x) < 0.9 ? rayo_vec3_make(1, 0, 0) : rayo_vec3_make(0, 1, 0));
        u = rayo_vec3_normalize(u);
        w = rayo_vec3_cross(n, u);
        u = rayo_vec3_scale(u, PLANE_HALF_SIZE);
        w = rayo_vec3_scale(w, PLANE_HALF_SIZE);
        /* Embree splits a quad v0 v1 v2 v3 along v1-v3, where float
         * rounding of so large triangles lets rays through: that seam is
         * laid along the camera's right through its foot, out of view. */
        corner[0] = rayo_vec3_sub(foot, w);
        corner[1] = rayo_vec3_add(foot, u);
        corner[2] = rayo_vec3_add(foot, w);
        corner[3] = rayo_vec3_sub(foot, u);
        for (c = 0; c < 4; c++) {
            v[3 * c] = (float)corner[c].x;
            v[3 * c + 1] = (float)corner[c].y;
            v[3 * c + 2] = (float)corner[c].z;
            q[c] = (unsigned)c;
        }
        rtcCommitGeometry(g);
        rtcAttachGeometry(es, g);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(es);
    return es;
}


static void write_pbm(const char *path, const scene *s,
                      const unsigned char *mask)
{
    FILE *out = fopen(path, "wb");
    unsigned i, j;
    if (out == NULL) {
        fprintf(stderr, "embree-rays: %s: %s\n", path, strerror(errno));
        exit(1);
    }
    fprintf(out, "P4\n%u %u\n", s->width, s->height);
    for (j = 0; j < s->height; j++) {
        unsigned char byte = 0;
        for (i = 0; i < s->width; i++) {
            if (mask[(size_t)j * s->width + i])
                byte |= (unsigned char)(0x80u >> (i & 7));
            if ((i & 7) == 7 || i + 1 == s->width) {
                fputc(byte, out);
                byte = 0;
            }
        }
    }
    if (fclose(out) != 0) {
        fprintf(stderr, "embree-rays: %s: %s\n", path, strerror(errno));
        exit(1);
    }
}

static void usage(void)
{
    fprintf(stderr, "usage: embree-rays SCENE [--mode occlusion|shadow] "
                    "[--packet 1|16] [--threads N] [--repeat N] "
                    "[--planes bvh|first] [--quality default|high] "
                    "[--pbm FILE]\n");
    exit(2);
}

int main(int argc, char **argv)
{
    const char *path = NULL, *pbm = NULL;
    int threads = 0, repeat = 1, high_quality = 0, r, a;
    struct rusage resources;
    char config[64];
    scene s;
    job jb;
    pass best;
    double start, read_s, build_s, setup_cpu_s, best_s = -1;
    RTCDevice device;
    memset(&jb, 0, sizeof jb);
    jb.packet = 1;
    for (a = 1; a < argc; a++) {
        if (strcmp(argv[a], "--mode") == 0 && a + 1 < argc) {
            a++;
            if (strcmp(argv[a], "occlusion") == 0)
                jb.shadow = 0;
            else if (strcmp(argv[a], "shadow") == 0)
                jb.shadow = 1;
            else
                usage();
        } else if (strcmp(argv[a], "--packet") == 0 && a + 1 < argc) {
            jb.packet = atoi(argv[++a]);
            if (jb.packet != 1 && jb.packet != 16)
                usage();
        } else if (strcmp(argv[a], "--threads") == 0 && a + 1 < argc) {
            threads = atoi(argv[++a]);
            if (threads < 0)
                usage();
        } else if (strcmp(argv[a], "--repeat") == 0 && a + 1 < argc) {
            repeat = atoi(argv[++a]);
            if (repeat < 0)
                usage();
        } else if (strcmp(argv[a], "--planes") == 0 && a + 1 < argc) {
            a++;
            if (strcmp(argv[a], "first") == 0)
                jb.planes_first = 1;
            else if (strcmp(argv[a], "bvh") == 0)
                jb.planes_first = 0;
            else
                usage();
        } else if (strcmp(argv[a], "--quality") == 0 && a + 1 < argc) {
            a++;
            if (strcmp(argv[a], "high") == 0)
                high_quality = 1;
            else if (strcmp(argv[a], "default") != 0)
                usage();
        } else if (strcmp(argv[a], "--pbm") == 0 && a + 1 < argc) {
            pbm = argv[++a];
        } else if (argv[a][0] != '-' && path == NULL) {
            path = argv[a];
        } else {
            usage();
        }
    }
    if (path == NULL)
        usage();
    if (threads > 0)
        snprintf(config, sizeof config, "threads=%d", threads);
    else
        config[0] = '\0';

    setup_cpu_s = process_cpu_now();
    start = wall_now();
    read_scene(path, &s);
    read_s = wall_now() - start;
    device = rtcNewDevice(config);
    if (device == NULL) {
        fprintf(stderr, "embree-rays: rtcNewDevice failed (%d)\n",
                (int)rtcGetDeviceError(NULL));
        return 1;
    }
    rtcSetDeviceErrorFunction(device, embree_error, NULL);
    start = wall_now();
    jb.s = &s;
    jb.cam = make_camera(&s);
    for (a = 0; (size_t)a < s.plane_count; a++) {
        rayo_vec3 n = s.plane_normal[a];
        jb.plane_n[a][0] = (float)n.x;
        jb.plane_n[a][1] = (float)n.y;
        jb.plane_n[a][2] = (float)n.z;
        jb.plane_d[a] = (float)rayo_vec3_dot(n, s.plane_point[a]);
    }
    jb.es = build(device, &s, &jb.cam, jb.planes_first, high_quality);
    build_s = wall_now() - start;
    setup_cpu_s = process_cpu_now() - setup_cpu_s;
    if (pbm != NULL) {
        jb.mask = calloc((size_t)s.width * s.height, 1);
        if (jb.mask == NULL) {
            fprintf(stderr, "embree-rays: out of memory\n");
            return 1;
        }
    }
    memset(&best, 0, sizeof best);
    for (r = 0; r < repeat; r++) {
        pass p;
        double t;
        memset(&p, 0, sizeof p);
        start = cpu_now();
        if (jb.packet == 16)
            trace_packets(&jb, &p);
        else
            trace_single(&jb, &p);
        t = cpu_now() - start;
        if (best_s < 0 || t < best_s)
            best_s = t;
        best = p;
    }
    printf("scene %s\nsize %ux%u\nspheres %lu\ntriangles %lu\nplanes %lu\n",
           path, s.width, s.height, (unsigned long)s.sphere_count,
           (unsigned long)s.triangle_count, (unsigned long)s.plane_count);
    printf("mode %s\npacket %d\nthreads %d\nplanes %s\nquality %s\n",
           jb.shadow ? "shadow" : "occlusion", jb.packet, threads,
           jb.planes_first ? "first" : "bvh",
           high_quality ? "high" : "default");
    printf("setup_cpu_s %.6f\n", setup_cpu_s);
    printf("read_s %.6f\nbuild_s %.6f\nsetup_s %.6f\n", read_s, build_s,
           read_s + build_s);
    if (best_s < 0)
        best_s = 0;
    printf("rays %llu\nrays_s %.6f\nns_per_ray %.3f\n", best.rays, best_s,
           best.rays ? best_s * 1e9 / (double)best.rays : 0.0);
    printf("hits %llu\nlit %llu\n", best.hits, best.lit);
    if (getrusage(RUSAGE_SELF, &resources) == 0)
        printf("peak_rss_kib %ld\n", (long)resources.ru_maxrss);
    if (pbm != NULL)
        write_pbm(pbm, &s, jb.mask);
    free(jb.mask);
    rtcReleaseScene(jb.es);
    rtcReleaseDevice(device);
    free(s.spheres);
    free(s.corners);
    return 0;
}
