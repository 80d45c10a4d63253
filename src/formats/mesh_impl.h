/*
 * mesh_impl.h - what the mesh readers share behind mesh.h: mesh_read.c
 * recognises the format and owns the growing triangle list and the text
 * cursor; mesh_stl.c reads STL, mesh_obj.c OBJ.  Not a public header.
 */
#ifndef RAYO_MESH_IMPL_H
#define RAYO_MESH_IMPL_H

#include "rayo/mesh.h"

#include "read_source.h"

/* The mesh being read: triangles appended, memory grown as they come. */
typedef struct mesh_builder {
    rayo_mesh *mesh;
    size_t capacity;
    int with_normals;
} mesh_builder;

/*
 * Room for at least more triangles after the last (a binary STL's count,
 * already checked against the file's size).  RAYO_ERR_LIMIT past
 * RAYO_MAX_OBJECTS in all; RAYO_ERR_NOMEM.
 */
rayo_status mesh_reserve(mesh_builder *b, size_t more, const char *name,
                         rayo_error *err);

/* Appends a triangle (9 floats) and its normal (3, or NULL). */
rayo_status mesh_push(mesh_builder *b, const float corners[9],
                      const float normal[3], const char *name,
                      rayo_error *err);

/* Text, from bytes already read (the head) and then the source; counts
   lines from 1. */
typedef struct mesh_text {
    rayo_source *src;
    const unsigned char *head;
    size_t head_size, head_next;
    uint64_t line;
} mesh_text;

/* The next byte, or -1 at the end (or a failed read: src->read_errno). */
int mesh_text_getc(mesh_text *t);

/*
 * The next word (a run of bytes other than whitespace) into word, at most
 * size - 1 bytes and NUL-terminated; *line is its line.  0 at the end.
 * A word that does not fit is cut (its length says so: size - 1).
 */
size_t mesh_text_word(mesh_text *t, char *word, size_t size, uint64_t *line);

/*
 * The next line, without its end, into line (NUL-terminated); 0 at the
 * end of the text, 1 for a line, -1 when it is longer than size - 1.
 */
int mesh_text_line(mesh_text *t, char *line, size_t size);

/* A finite decimal number (the scene file's rules, decimal.h) as float:
   1, or 0 when word is not one or is out of float's range. */
int mesh_number(const char *word, float *value);

rayo_status rayo_mesh_read_stl_binary(rayo_source *src,
                                      const unsigned char head[84],
                                      mesh_builder *b,
                                      rayo_mesh_report *report,
                                      rayo_error *err);
rayo_status rayo_mesh_read_stl_ascii(mesh_text *t, mesh_builder *b,
                                     rayo_mesh_report *report,
                                     rayo_error *err);
rayo_status rayo_mesh_read_obj(mesh_text *t, mesh_builder *b,
                               rayo_mesh_report *report, rayo_error *err);

#endif
