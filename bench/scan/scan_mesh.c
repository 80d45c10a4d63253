/*
 * scan_mesh.c - writes the benchmark's triangle mesh, a stand-in for a
 * scanned object, as a binary STL, and a scene file framing it on a floor
 * under one point light (`make bench`, bench/meshes.c).
 *
 * The mesh is an octahedron whose eight faces are each cut into n x n
 * triangles (8 n^2 in all, n the nearest to the count asked for), every
 * corner pushed out onto the unit sphere and then along its direction by
 * a few octaves of smooth value noise: a lumpy closed surface of
 * well-shaped triangles of every orientation, like a scan's.  A corner is
 * computed only from its integer lattice point, so the faces that share
 * an edge share its corners bit for bit: the mesh is watertight.  Only
 * + - * / and sqrt, which IEEE-754 rounds exactly, so every machine
 * writes the same bytes.  Not a mesh reader, and not part of rayo.
 *
 *   scan-mesh TRIANGLES STL SCENE
 */
#define _POSIX_C_SOURCE 200809L

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define OCTAVES 5
#define AMPLITUDE 0.14
#define BASE_FREQUENCY 1.7
#define RECORDS_PER_WRITE 8192

static uint64_t mix(uint64_t x)
{
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    x ^= x >> 31;
    return x;
}

/* A value in [-1, 1) for a lattice point of the noise. */
static double lattice(long x, long y, long z)
{
    uint64_t h = mix((uint64_t)x * 0x9e3779b97f4a7c15ULL ^
                     mix((uint64_t)y * 0xc2b2ae3d27d4eb4fULL ^
                         mix((uint64_t)z + 0x165667b19e3779f9ULL)));
    return (double)(h >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

static double fade(double t)
{
    return t * t * t * (t * (t * 6 - 15) + 10);
}

/* Value noise: the lattice values blended with a C2 fade. */
static double noise(double x, double y, double z)
{
    double fx = floor(x), fy = floor(y), fz = floor(z);
    long ix = (long)fx, iy = (long)fy, iz = (long)fz;
    double u = fade(x - fx), v = fade(y - fy), w = fade(z - fz);
    double c[2][2];
    int a, b;
    for (a = 0; a < 2; a++)
        for (b = 0; b < 2; b++) {
            double lo = lattice(ix, iy + a, iz + b);
            double hi = lattice(ix + 1, iy + a, iz + b);
            c[a][b] = lo + u * (hi - lo);
        }
    c[0][0] += v * (c[1][0] - c[0][0]);
    c[0][1] += v * (c[1][1] - c[0][1]);
    return c[0][0] + w * (c[0][1] - c[0][0]);
}

/* The corner of lattice point (a, b, c), |a| + |b| + |c| = n. */
static void corner(long a, long b, long c, float out[3])
{
    double x = (double)a, y = (double)b, z = (double)c;
    double len = sqrt(x * x + y * y + z * z), r = 1.0;
    double f = BASE_FREQUENCY, amp = AMPLITUDE;
    int o;
    x /= len;
    y /= len;
    z /= len;
    for (o = 0; o < OCTAVES; o++) {
        r += amp * noise(x * f + 17.0, y * f + 31.0, z * f + 47.0);
        f *= 2.0;
        amp *= 0.5;
    }
    out[0] = (float)(x * r);
    out[1] = (float)(y * r);
    out[2] = (float)(z * r);
}

static void put_float(unsigned char *p, float value)
{
    uint32_t bits;
    memcpy(&bits, &value, sizeof bits);
    p[0] = (unsigned char)bits;
    p[1] = (unsigned char)(bits >> 8);
    p[2] = (unsigned char)(bits >> 16);
    p[3] = (unsigned char)(bits >> 24);
}

typedef struct writer {
    FILE *out;
    const char *path;
    unsigned char *buffer;
    size_t used;
    float min_y;
} writer;

static void fail_io(const char *path)
{
    fprintf(stderr, "scan-mesh: %s: %s\n", path, strerror(errno));
    exit(1);
}

static void flush(writer *w)
{
    if (w->used > 0 && fwrite(w->buffer, 50, w->used, w->out) != w->used)
        fail_io(w->path);
    w->used = 0;
}

/* One record: the facet normal from the corners, then the corners. */
static void facet(writer *w, const float *p, const float *q, const float *r)
{
    unsigned char *rec = w->buffer + 50 * w->used;
    double e1[3], e2[3], n[3], len;
    int k;
    for (k = 0; k < 3; k++) {
        e1[k] = (double)q[k] - p[k];
        e2[k] = (double)r[k] - p[k];
    }
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (k = 0; k < 3; k++) {
        put_float(rec + 4 * k, (float)(len > 0 ? n[k] / len : 0));
        put_float(rec + 12 + 4 * k, p[k]);
        put_float(rec + 24 + 4 * k, q[k]);
        put_float(rec + 36 + 4 * k, r[k]);
    }
    rec[48] = rec[49] = 0;
    for (k = 0; k < 3; k++) {
        const float *v = k == 0 ? p : k == 1 ? q : r;
        if (v[1] < w->min_y)
            w->min_y = v[1];
    }
    if (++w->used == RECORDS_PER_WRITE)
        flush(w);
}

/* Face (sx, sy, sz) of the octahedron: its n x n triangles, facing out. */
static void face(writer *w, long n, int sx, int sy, int sz, float *grid)
{
    long i, j;
    int flip = sx * sy * sz < 0;
#define AT(i, j) (grid + 3 * ((size_t)(i) * (size_t)(n + 1) + (size_t)(j)))
    for (i = 0; i <= n; i++)
        for (j = 0; j + i <= n; j++)
            corner(sx * i, sy * j, sz * (n - i - j), AT(i, j));
    for (i = 0; i < n; i++)
        for (j = 0; i + j < n; j++) {
            const float *a = AT(i, j), *b = AT(i + 1, j), *c = AT(i, j + 1);
            facet(w, a, flip ? c : b, flip ? b : c);
            if (i + j + 2 <= n) {
                const float *d = AT(i + 1, j + 1);
                facet(w, b, flip ? c : d, flip ? d : c);
            }
        }
#undef AT
}

static FILE *open_temporary(const char *path, char *temp, size_t size)
{
    FILE *out;
    snprintf(temp, size, "%s.part", path);
    out = fopen(temp, "wb");
    if (out == NULL)
        fail_io(temp);
    return out;
}

static void finish(FILE *out, const char *temp, const char *path)
{
    if (fflush(out) != 0 || ferror(out) || fclose(out) != 0)
        fail_io(temp);
    if (rename(temp, path) != 0)
        fail_io(path);
}

/* The file part of path (the scene names the mesh beside it). */
static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash != NULL ? slash + 1 : path;
}

int main(int argc, char **argv)
{
    static const int signs[8][3] = {{1, 1, 1},   {-1, 1, 1}, {1, -1, 1},
                                    {1, 1, -1},  {-1, -1, 1}, {-1, 1, -1},
                                    {1, -1, -1}, {-1, -1, -1}};
    char temp[4096], *end;
    unsigned char header[84];
    unsigned long asked;
    long n;
    uint32_t count;
    writer w;
    float *grid;
    FILE *scene;
    int f;
    if (argc != 4) {
        fprintf(stderr, "usage: scan-mesh TRIANGLES STL SCENE\n");
        return 2;
    }
    errno = 0;
    asked = strtoul(argv[1], &end, 10);
    if (*end != '\0' || errno != 0 || asked < 8 || asked > 16000000) {
        fprintf(stderr, "scan-mesh: '%.40s': expected a count of triangles "
                        "from 8 to 16000000\n", argv[1]);
        return 2;
    }
    n = (long)floor(sqrt((double)asked / 8.0) + 0.5);
    count = (uint32_t)(8 * n * n);
    grid = malloc(3 * sizeof *grid * (size_t)(n + 1) * (size_t)(n + 1));
    w.buffer = malloc(50 * RECORDS_PER_WRITE);
    if (grid == NULL || w.buffer == NULL) {
        fprintf(stderr, "scan-mesh: out of memory\n");
        return 1;
    }
    w.path = temp;
    w.used = 0;
    w.min_y = INFINITY;
    w.out = open_temporary(argv[2], temp, sizeof temp);
    memset(header, 0, sizeof header);
    snprintf((char *)header, 80, "rayo bench/scan: %lu triangles",
             (unsigned long)count);
    header[80] = (unsigned char)count;
    header[81] = (unsigned char)(count >> 8);
    header[82] = (unsigned char)(count >> 16);
    header[83] = (unsigned char)(count >> 24);
    if (fwrite(header, 1, sizeof header, w.out) != sizeof header)
        fail_io(temp);
    for (f = 0; f < 8; f++)
        face(&w, n, signs[f][0], signs[f][1], signs[f][2], grid);
    flush(&w);
    finish(w.out, temp, argv[2]);

    scene = open_temporary(argv[3], temp, sizeof temp);
    fprintf(scene,
            "# A scan-like mesh of %lu triangles on a floor "
            "(bench/scan/scan_mesh.c)\n"
            "shade phong\n"
            "camera size 1920 1080 fov 60 origin 0 0.8 -4.2 look-at 0 -0.2 0 "
            "up 0 1 0\n"
            "background 0.5 0.7 1\nambient 0.1\n"
            "light point -4 6 -5 color 1 1 1\n"
            "material ground color 0.6 ka 0.1 kd 0.8 ks 0\n"
            "material scan color 0.8 0.7 0.6 ka 0.1 kd 0.8 ks 0.3 "
            "shininess 24\n"
            "plane 0 %.9g 0  0 1 0 material ground\n"
            "mesh %s material scan\n",
            (unsigned long)count, (double)w.min_y, base_name(argv[2]));
    finish(scene, temp, argv[3]);
    free(grid);
    free(w.buffer);
    return 0;
}
