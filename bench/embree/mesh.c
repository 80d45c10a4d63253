/*
 * mesh.c - the Embree program's meshes: the binary STL a scene's `mesh
 * FILE` line names, read into one array of corners, and handed to Embree
 * as an RTC_GEOMETRY_TYPE_TRIANGLE geometry that shares that array (no
 * copy) with an index buffer 0, 1, 2, ... (the STL's triangle soup as it
 * is, three corners a triangle, as rayo keeps it).  Its own reader, not
 * rayo's (the program links no rayo): 84 bytes of header and count, then
 * the 50-byte records read in large blocks (their floats copied as they
 * are: a little-endian machine's, like the file's), the count checked
 * against the file's size; ASCII STL and OBJ are refused (the bench
 * writes binary).
 */
#define _POSIX_C_SOURCE 200809L

#include "mesh.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define RECORDS_PER_READ 16384

static void die_io(const char *path)
{
    fprintf(stderr, "embree-rays: %s: %s\n", path, strerror(errno));
    exit(1);
}

static void die_input(const char *path, const char *what)
{
    fprintf(stderr, "embree-rays: %s: %s\n", path, what);
    exit(2);
}

static uint32_t u32_at(const unsigned char *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) |
           ((uint32_t)p[3] << 24);
}

void read_mesh(const char *path, scene *s)
{
    FILE *in = fopen(path, "rb");
    unsigned char head[84], *block;
    uint32_t count, done = 0;
    long size = -1;
    float *grown;
    size_t total;
    if (in == NULL)
        die_io(path);
    if (fread(head, 1, sizeof head, in) != sizeof head)
        die_input(path, "expected a binary STL (84 bytes of header and "
                        "count, then 50 a triangle)");
    count = u32_at(head + 80);
    if (fseek(in, 0, SEEK_END) != 0 || (size = ftell(in)) < 0 ||
        fseek(in, 84, SEEK_SET) != 0)
        die_io(path);
    if ((uint64_t)size != 84 + (uint64_t)count * 50)
        die_input(path, "expected a binary STL of 84 + 50 x its count "
                        "bytes (this program reads no ASCII STL or OBJ)");
    total = s->triangle_count + count;
    /* Embree reads a float3 vertex buffer 16 bytes at a time: one float
     * more at the end. */
    grown = realloc(s->corners, (total * 9 + 1) * sizeof *grown);
    block = malloc((size_t)RECORDS_PER_READ * 50);
    if (grown == NULL || block == NULL) {
        fprintf(stderr, "embree-rays: out of memory\n");
        exit(1);
    }
    s->corners = grown;
    while (done < count) {
        uint32_t n = count - done < RECORDS_PER_READ ? count - done
                                                     : RECORDS_PER_READ, k;
        float *to = s->corners + (s->triangle_count + done) * 9;
        if (fread(block, 50, n, in) != n) {
            if (ferror(in))
                die_io(path);
            die_input(path, "the file ended before its last triangle");
        }
        for (k = 0; k < n; k++)
            memcpy(to + 9 * (size_t)k, block + 50 * (size_t)k + 12,
                   9 * sizeof(float));
        done += n;
    }
    s->corners[total * 9] = 0;
    s->triangle_count = total;
    free(block);
    fclose(in);
}

void attach_meshes(RTCDevice device, RTCScene es, const scene *s)
{
    RTCGeometry g;
    unsigned *index;
    size_t i;
    if (s->triangle_count == 0)
        return;
    g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0,
                               RTC_FORMAT_FLOAT3, s->corners, 0,
                               3 * sizeof(float), 3 * s->triangle_count);
    index = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0,
                                    RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                    s->triangle_count);
    for (i = 0; i < 3 * s->triangle_count; i++)
        index[i] = (unsigned)i;
    rtcCommitGeometry(g);
    rtcAttachGeometry(es, g);
    rtcReleaseGeometry(g);
}
