/*
 * mesh.h - reading triangle meshes: STL (binary, as the course's TP1
 * uses, and ASCII) and Wavefront OBJ.
 *
 * A mesh is a plain list of triangles, three corners each, with the
 * normal an STL file gives every facet (OBJ gives none that rayo uses).
 * The format comes from the content, never from the name (below).
 * Hostile files are refused before memory is asked for what they
 * promise; errors are one line, "FILE: byte N: ..." for binary STL,
 * "FILE:LINE: ..." for text.  What a scene does with a mesh (placement,
 * material, which normals shade it) is scene.h's and scene_file.h's.
 */
#ifndef RAYO_MESH_H
#define RAYO_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/export.h"
#include "rayo/status.h"

/*
 * A binary STL is 84 + 50 n bytes for its count n; a file that is not,
 * and begins with "solid", is ASCII STL; one whose first statement is an
 * OBJ keyword (v, f, o, g, #, ...) is OBJ.  A binary header may begin
 * "solid" too: a NUL byte in the first 84, which text never has, says
 * binary.
 *
 * Refused: a binary STL whose count needs more bytes than the file has, a
 * count past RAYO_MAX_OBJECTS, a coordinate that is not a finite number,
 * an OBJ index out of range, a truncated record.  Memory grows with what
 * the file holds, never with what a header says.
 */

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rayo_mesh_format {
    RAYO_MESH_STL_BINARY,
    RAYO_MESH_STL_ASCII,
    RAYO_MESH_OBJ
} rayo_mesh_format;

typedef struct rayo_mesh {
    size_t count;   /* triangles */
    float *corners; /* 9 floats a triangle: a, b, c (x, y, z each) */
    float *normals; /* 3 floats a triangle as the file gives them (STL),
                       or NULL (OBJ) */
} rayo_mesh;

typedef struct rayo_mesh_report {
    rayo_mesh_format format;
    uint64_t zero_normals;   /* STL facets whose normal is (0, 0, 0) */
    uint64_t trailing_bytes; /* binary STL: bytes after the last record */
    uint64_t polygons;       /* OBJ faces of more than three corners, cut
                                into triangles around their first corner */
    uint64_t ignored;        /* OBJ statements other than v and f (vn, vt,
                                g, o, s, usemtl, mtllib, ...) */
} rayo_mesh_report;

/* "binary STL", "ASCII STL" or "OBJ". */
RAYO_API const char *rayo_mesh_format_name(rayo_mesh_format format);

/*
 * Reads the mesh in path ("-" = standard input) into mesh, freed with
 * rayo_mesh_free.  report may be NULL.  On failure mesh is left zeroed.
 * RAYO_ERR_FORMAT (malformed or lying input), RAYO_ERR_LIMIT (more than
 * RAYO_MAX_OBJECTS triangles), RAYO_ERR_IO, RAYO_ERR_NOMEM.
 */
RAYO_API rayo_status rayo_mesh_read_file(const char *path, rayo_mesh *mesh,
                                         rayo_mesh_report *report,
                                         rayo_error *err);

/* The same from size bytes at data; name is used in messages. */
RAYO_API rayo_status rayo_mesh_read_memory(const void *data, size_t size,
                                           const char *name, rayo_mesh *mesh,
                                           rayo_mesh_report *report,
                                           rayo_error *err);

/* Frees the triangles and zeroes the struct; safe on a zeroed mesh. */
RAYO_API void rayo_mesh_free(rayo_mesh *mesh);

#ifdef __cplusplus
}
#endif

#endif
