/*
 * t_mesh.c - the mesh readers (mesh.h) and meshes placed in a scene
 * (rayo_scene_add_mesh), on files built here byte by byte: binary STL as
 * the course's statement lays it out, ASCII STL and OBJ as text; what
 * each must yield is written out by hand, and every hostile file is
 * refused with the line or byte it names.
 */
#define _POSIX_C_SOURCE 200809L

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "rayo/limits.h"
#include "rayo/mesh.h"
#include "rayo/scene.h"
#include "tap.h"

/* A binary STL of count records (the count field says `claimed`). */
typedef struct stl_file {
    unsigned char *bytes;
    size_t size;
} stl_file;

static void put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)v;
    p[1] = (unsigned char)(v >> 8);
    p[2] = (unsigned char)(v >> 16);
    p[3] = (unsigned char)(v >> 24);
}

static void put_float(unsigned char *p, float f)
{
    uint32_t bits;
    memcpy(&bits, &f, sizeof bits);
    put32(p, bits);
}

/* Triangle i: corners (i, 0, 5), (i + 1, 0, 5), (i, 1, 5); normal
   (0, 0, -1), or (0, 0, 0) for odd i. */
static stl_file binary_stl(uint32_t count, uint32_t claimed)
{
    stl_file f;
    uint32_t i;
    f.size = 84 + (size_t)count * 50;
    f.bytes = calloc(f.size, 1);
    memcpy(f.bytes, "solid but binary all the same", 29);
    put32(f.bytes + 80, claimed);
    for (i = 0; i < count; i++) {
        unsigned char *r = f.bytes + 84 + (size_t)i * 50;
        float c[9];
        int k;
        c[0] = (float)i, c[1] = 0, c[2] = 5;
        c[3] = (float)i + 1, c[4] = 0, c[5] = 5;
        c[6] = (float)i, c[7] = 1, c[8] = 5;
        put_float(r + 8, i % 2 ? 0.0f : -1.0f);
        for (k = 0; k < 9; k++)
            put_float(r + 12 + 4 * k, c[k]);
    }
    return f;
}

static void test_binary(void)
{
    stl_file f = binary_stl(3, 3);
    rayo_mesh mesh;
    rayo_mesh_report report;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    status = rayo_mesh_read_memory(f.bytes, f.size, "t.stl", &mesh, &report,
                                   &err);
    is_int(status, RAYO_OK, "binary STL read (its header begins 'solid')");
    is_int(report.format, RAYO_MESH_STL_BINARY, "  as binary: its size fits");
    is_int((int)mesh.count, 3, "  three triangles");
    ok(mesh.corners[9 * 2 + 0] == 2 && mesh.corners[9 * 2 + 3] == 3 &&
           mesh.corners[9 * 2 + 7] == 1 && mesh.corners[9 * 2 + 8] == 5,
       "  the third's corners");
    ok(mesh.normals[2] == -1 && mesh.normals[3 + 2] == 0,
       "  the file's normals");
    is_int((int)report.zero_normals, 1, "  one zero normal counted");
    rayo_mesh_free(&mesh);
    ok(mesh.count == 0 && mesh.corners == NULL, "freed mesh is zeroed");

    /* A count larger than the file. */
    put32(f.bytes + 80, 4);
    status = rayo_mesh_read_memory(f.bytes, f.size, "t.stl", &mesh, NULL,
                                   &err);
    is_int(status, RAYO_ERR_FORMAT, "a count the file cannot hold: refused");
    is_string(err.message,
              "t.stl: byte 80: found a count of 4 triangles, which need 84 "
              "+ 50 x 4 = 284 bytes; expected at most 3 triangles (the file "
              "has 234 bytes)",
              "  naming the count, the bytes it needs and the file's");
    ok(mesh.count == 0 && mesh.corners == NULL, "  the mesh left zeroed");
    /* A billion faces: over the limit before any allocation. */
    put32(f.bytes + 80, 1000000000u);
    status = rayo_mesh_read_memory(f.bytes, f.size, "t.stl", &mesh, NULL,
                                   &err);
    is_int(status, RAYO_ERR_LIMIT, "a billion faces: over the limit");
    is_string(err.message,
              "t.stl: byte 80: found a count of 1000000000 triangles; "
              "expected at most 16777216 (2^24, the objects of a scene)",
              "  the limit named");
    /* A NaN corner. */
    put32(f.bytes + 80, 3);
    put_float(f.bytes + 84 + 50 + 12 + 4 * 4, NAN);
    status = rayo_mesh_read_memory(f.bytes, f.size, "t.stl", &mesh, NULL,
                                   &err);
    is_int(status, RAYO_ERR_FORMAT, "a NaN corner: refused");
    is_string(err.message,
              "t.stl: byte 162: found nan as coordinate 2 of triangle 2's "
              "corner 2; expected a finite number",
              "  the byte, the triangle and the corner");
    free(f.bytes);
    /* A record cut short, read from a pipe-like source is covered by the
       size check above; a file one byte short of its last record: */
    f = binary_stl(2, 2);
    f.size -= 1;
    status = rayo_mesh_read_memory(f.bytes, f.size, "t.stl", &mesh, NULL,
                                   &err);
    is_int(status, RAYO_ERR_FORMAT, "a truncated record: refused");
    free(f.bytes);
}

/* f written to path, a new file made from it first when it ends in
   XXXXXX (mkstemp); 0 on failure. */
static int write_file(const stl_file *f, char *path)
{
    size_t n = strlen(path);
    int fd = n >= 6 && strcmp(path + n - 6, "XXXXXX") == 0 ? mkstemp(path)
                                                           : -1;
    FILE *out = fd >= 0 ? fdopen(fd, "wb") : fopen(path, "wb");
    int written;
    if (out == NULL)
        return 0;
    written = fwrite(f->bytes, 1, f->size, out) == f->size;
    return fclose(out) == 0 && written;
}

/* f written to path and read back: refused with "PATH: " message. */
static void refused_at(const stl_file *f, char *path, const char *message,
                       const char *what)
{
    char expected[256];
    rayo_mesh mesh;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    snprintf(expected, sizeof expected, "%s: %s", path, message);
    ok(write_file(f, path), "the file written");
    is_int(rayo_mesh_read_file(path, &mesh, NULL, &err), RAYO_ERR_FORMAT,
           "%s", what);
    is_string(err.message, expected, "  the byte, the triangle, the corner");
}

/* A file is read in 64 KiB windows: record 1310 (bytes 65534 to 65583)
   is cut by the first window's end, the rest are decoded in place. */
static void test_binary_windows(void)
{
    stl_file f = binary_stl(3000, 3000);
    char path[] = "/tmp/rayo-t-mesh.XXXXXX";
    rayo_mesh mesh;
    rayo_mesh_report report;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    int fine;
    size_t i;
    ok(write_file(&f, path), "a 150,084-byte binary STL written");
    is_int(rayo_mesh_read_file(path, &mesh, &report, &err), RAYO_OK,
           "read from the file, window by window");
    is_int((int)mesh.count, 3000, "  all 3000 triangles");
    for (i = 0, fine = 1; i < mesh.count; i++)
        fine &= mesh.corners[9 * i] == (float)i &&
                mesh.corners[9 * i + 3] == (float)i + 1 &&
                mesh.corners[9 * i + 7] == 1 && mesh.corners[9 * i + 8] == 5 &&
                mesh.normals[3 * i + 2] == (i % 2 ? 0.0f : -1.0f);
    ok(fine, "  each one's corners and normal, the cut record's too");
    is_int((int)report.zero_normals, 1500, "  1500 zero normals counted");
    rayo_mesh_free(&mesh);

    /* Not finite: in the cut record, and in one decoded in place. */
    put_float(f.bytes + 84 + 1309 * 50 + 12 + 4 * 4, NAN);
    refused_at(&f, path,
               "byte 65562: found nan as coordinate 2 of triangle 1310's "
               "corner 2; expected a finite number",
               "a NaN in the cut record: refused at byte 84 + 1309 x 50 + 28");
    put_float(f.bytes + 84 + 1309 * 50 + 12 + 4 * 4, 0);
    put_float(f.bytes + 84 + 2000 * 50 + 12 + 4 * 8, INFINITY);
    refused_at(&f, path,
               "byte 100128: found an infinity as coordinate 3 of triangle "
               "2001's corner 3; expected a finite number",
               "an infinity in triangle 2001: refused at byte 84 + 2000 x 50 "
               "+ 44");
    unlink(path);
    free(f.bytes);
}

static rayo_status read_text(const char *text, rayo_mesh *mesh,
                             rayo_mesh_report *report, rayo_error *err)
{
    return rayo_mesh_read_memory(text, strlen(text), "t.txt", mesh, report,
                                 err);
}

static void test_ascii(void)
{
    rayo_mesh mesh;
    rayo_mesh_report report;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    const char *good = "solid thing\n"
                       "  facet normal 0 0 -1\n    outer loop\n"
                       "      vertex 0 0 5\n      vertex 1.5e0 0 5\n"
                       "      vertex 0 -2 5\n    endloop\n  endfacet\n"
                       "endsolid thing\n";
    is_int(read_text(good, &mesh, &report, &err), RAYO_OK, "ASCII STL read");
    is_int(report.format, RAYO_MESH_STL_ASCII, "  as ASCII");
    ok(mesh.count == 1 && mesh.corners[3] == 1.5f && mesh.corners[7] == -2 &&
           mesh.normals[2] == -1,
       "  its corners and normal");
    rayo_mesh_free(&mesh);
    is_int(read_text("solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 "
                     "nan\n",
                     &mesh, &report, &err),
           RAYO_ERR_FORMAT, "a nan vertex: refused");
    is_string(err.message,
              "t.txt:4: found 'nan'; expected a vertex's three finite "
              "numbers",
              "  naming the line");
    is_int(read_text("solid x\n facet normal 0 0 1\n outer loop\n", &mesh,
                     &report, &err),
           RAYO_ERR_FORMAT, "cut short: refused");
    is_string(err.message,
              "t.txt:4: found the end of the file; expected 'vertex'",
              "  at the end");
}

static void test_obj(void)
{
    rayo_mesh mesh;
    rayo_mesh_report report;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    const char *quad = "# a square and a triangle\n"
                       "o square\nv 0 0 5\nv 1 0 5\nv 1 1 5\nv 0 1 5\n"
                       "vn 0 0 -1\nvt 0 0\n"
                       "f 1/1/1 2/1/1 3//1 4\n"
                       "f -4 -3 -1\n";
    is_int(read_text(quad, &mesh, &report, &err), RAYO_OK, "OBJ read");
    is_int(report.format, RAYO_MESH_OBJ, "  as OBJ");
    is_int((int)mesh.count, 3, "  a quad in two triangles and a triangle");
    ok(mesh.normals == NULL, "  no normals");
    /* The quad's fan: (1 2 3), (1 3 4); then (1 2 4). */
    ok(mesh.corners[9 + 3] == 1 && mesh.corners[9 + 4] == 1 &&
           mesh.corners[9 + 6] == 0 && mesh.corners[9 + 7] == 1,
       "  the fan's second triangle is corners 1, 3, 4");
    ok(mesh.corners[18 + 6] == 0 && mesh.corners[18 + 7] == 1,
       "  -1 is the last vertex");
    is_int((int)report.polygons, 1, "  one polygon cut");
    is_int((int)report.ignored, 3, "  three statements not used (o, vn, vt)");
    rayo_mesh_free(&mesh);
    is_int(read_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", &mesh, &report,
                     &err),
           RAYO_ERR_FORMAT, "an index out of range: refused");
    is_string(err.message,
              "t.txt:4: found the vertex index 4; expected 1 to 3 or -1 to "
              "-3 (the vertices so far)",
              "  naming the line and the range");
    is_int(read_text("v 0 0 0\nv 1 0 0\nf 1 2\n", &mesh, &report, &err),
           RAYO_ERR_FORMAT, "a face of two corners: refused");
    is_string(err.message, "t.txt:3: found a face of 2 corners; expected at "
                           "least 3",
              "  naming it");
    is_int(read_text("v 0 0 inf\n", &mesh, &report, &err), RAYO_ERR_FORMAT,
           "an infinite vertex: refused");
    is_int(read_text("\x01\x02 garbage", &mesh, &report, &err),
           RAYO_ERR_FORMAT, "no mesh at all: refused");
}

static void test_scene(void)
{
    stl_file f = binary_stl(2, 2);
    rayo_mesh mesh;
    rayo_scene *scene;
    rayo_mesh_placement placement;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_hit hit;
    rayo_ray ray;
    size_t left_out = 9;
    rayo_mesh_read_memory(f.bytes, f.size, "t.stl", &mesh, NULL, &err);
    free(f.bytes);
    /* Triangle 0 has the file normal (0, 0, -1); give it a tilted one. */
    mesh.normals[0] = 1;
    mesh.normals[2] = -1;
    rayo_scene_create(&scene, &err);
    rayo_mesh_placement_init(&placement);
    placement.scale = 2;
    placement.rotate = rayo_vec3_make(0, 0, 90);
    placement.translate = rayo_vec3_make(0, 0, 1);
    is_int(rayo_scene_add_mesh(scene, &mesh, &placement, 0, &left_out, &err),
           RAYO_OK, "a mesh placed in a scene");
    is_int((int)rayo_scene_object_count(scene), 2, "  two triangles");
    is_int((int)left_out, 0, "  none left out");
    /* Corner (0.25, 0.25, 5) of triangle 0 scaled by 2 is (0.5, 0.5, 10),
       turned 90 degrees about z (x, y) -> (-y, x): (-0.5, 0.5, 10), moved
       to z = 11. */
    ray.origin = rayo_vec3_make(-0.5, 0.5, 0);
    ray.direction = rayo_vec3_make(0, 0, 1);
    ok(rayo_scene_intersect(scene, &ray, 1e-9, INFINITY, &hit) &&
           fabs(hit.t - 11) < 1e-12,
       "  placed where scale, turn and move put it");
    /* Its normal: the file's (1, 0, -1) turned to (0, 1, -1), unit. */
    ok(fabs(hit.normal.x) < 1e-12 &&
           fabs(hit.normal.y - sqrt(0.5)) < 1e-12 &&
           fabs(hit.normal.z + sqrt(0.5)) < 1e-12,
       "  shaded with the file's normal, turned with the mesh");
    rayo_scene_free(scene);
    rayo_scene_create(&scene, &err);
    placement.computed_normals = 1;
    rayo_scene_add_mesh(scene, &mesh, &placement, 0, &left_out, &err);
    ok(rayo_scene_intersect(scene, &ray, 1e-9, INFINITY, &hit) &&
           fabs(hit.normal.x) < 1e-12 && fabs(hit.normal.y) < 1e-12 &&
           hit.normal.z == -1,
       "  normals computed: the corners' normal, facing the ray");
    rayo_scene_free(scene);
    /* A scale that crushes a triangle to a line leaves it out. */
    rayo_scene_create(&scene, &err);
    mesh.corners[7] = 0; /* triangle 0: third corner on the first edge */
    rayo_mesh_placement_init(&placement);
    is_int(rayo_scene_add_mesh(scene, &mesh, &placement, 0, &left_out, &err),
           RAYO_OK, "a degenerate triangle does not stop the mesh");
    is_int((int)left_out, 1, "  it is left out and counted");
    is_int((int)rayo_scene_object_count(scene), 1, "  the other is there");
    placement.scale = -1;
    is_int(rayo_scene_add_mesh(scene, &mesh, &placement, 0, NULL, &err),
           RAYO_ERR_INVALID, "a negative scale: refused");
    rayo_scene_free(scene);
    rayo_mesh_free(&mesh);
}

int main(void)
{
    test_binary();
    test_binary_windows();
    test_ascii();
    test_obj();
    test_scene();
    return tap_done();
}
