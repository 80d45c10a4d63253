/*
 * scene_file_parser.h - the parser of scene files, shared by its files:
 * the statements (scene_file_settings.c: the camera and the render
 * settings; scene_file_objects.c: lights, materials and shapes;
 * scene_file_mesh.c: meshes), the values they read and the messages
 * that say what was found (scene_file_values.c), and the reader that
 * hands them the lines in file order (scene_file.c).  Private to
 * src/scenefile/; the scene is reached through scene.h alone.
 *
 * Every function reading a statement's words fails with the message,
 * and the "FILE:LINE:COL:" of the word, that the caller returns as is.
 */
#ifndef RAYO_SCENE_FILE_PARSER_H
#define RAYO_SCENE_FILE_PARSER_H

#include "rayo/scene_file.h"

#include "scene_file_split.h"
#include "scene_lexer.h"

/* Spheres added at once: enough that a batch costs little per sphere,
 * few enough that the batch stays in the first-level cache. */
#define SPHERE_BATCH 256

/* A material's name, as its 'material' line gave it. */
typedef struct material_name {
    char text[RAYO_SCENE_MAX_NAME + 1];
    size_t length;
    unsigned id;
    unsigned long line;
} material_name;

/* What the parser keeps from line to line and window to window. */
typedef struct parser {
    scene_lexer lx;
    rayo_scene_file *file;
    material_name *names;
    size_t name_count, name_capacity;
    size_t *slots; /* hash table of names: position + 1, 0 when empty */
    size_t slot_capacity; /* a power of two, at least twice name_count */
    unsigned long camera_line, shade_line, samples_line, depth_line;
    unsigned long ambient_line, background_line;
    unsigned long base; /* lines before the window the lexer reads */
    unsigned parts;     /* threads a long window is read on */
    split_set split;    /* its parts, kept for the next window */
    /* Spheres read ahead, consecutive lines of a part, waiting to be
       added together (rayo_scene_add_spheres). */
    rayo_sphere batch[SPHERE_BATCH];
    unsigned batch_material[SPHERE_BATCH];
    size_t batch_count;
} parser;

/* Room for a word shown in a message (scene_word_show). */
#define WORD_SHOW 48


/* ---- values (scene_file_values.c) ------------------------------------ */

/* The word in quotes, printable, for messages. */
const char *scene_quoted(const scene_word *word, char *buffer, size_t size);

/* "found 'word'" (have) or "found the end of the line" into buffer, in
 * the error's language. */
const char *scene_found(const parser *p, const scene_word *word, int have,
                        char *buffer, size_t size);

/* Reads a word that must be there; what names the value expected. */
rayo_status scene_need_word(parser *p, scene_word *word, const char *what);

/* One number; what names it ("the sphere's radius"); *column (may be
 * NULL) gets its column. */
rayo_status scene_need_number(parser *p, const char *what, double *value,
                              size_t *column);

/* Three numbers: the x, y and z of what ("the sphere's centre"). */
rayo_status scene_need_vector(parser *p, const char *what, rayo_vec3 *v,
                              size_t *column);

/* A vector that must not be zero (a direction or a normal). */
rayo_status scene_need_direction(parser *p, const char *what, rayo_vec3 *v);

/* A number in [min, max]. */
rayo_status scene_need_ranged(parser *p, const char *what, double min,
                              double max, double *value);

/* A whole number in [min, max]. */
rayo_status scene_need_count(parser *p, const char *what, unsigned long min,
                             unsigned long max, unsigned long *value);

/* A colour: one number (a gray, copied to all three channels) or three,
 * each in [0, max]. */
rayo_status scene_need_color(parser *p, const char *what, double max,
                             rayo_vec3 *color);

/* The end of the line; options, when not NULL, lists what else the
 * statement would have taken there. */
rayo_status scene_need_end(parser *p, const char *statement,
                           const char *options);

/* A statement that may appear once: fails on the second; *line is where
 * the first was (0: none yet). */
rayo_status scene_once(parser *p, unsigned long *line, const char *keyword);

/* Re-issues a scene error at the statement's first column. */
rayo_status scene_failed(parser *p, const rayo_error *inner);

/* ---- statements: each reads the rest of its line ---------------------- */

/* scene_file_settings.c */
rayo_status scene_parse_camera(parser *p);
rayo_status scene_parse_shade(parser *p);
rayo_status scene_parse_samples(parser *p);
rayo_status scene_parse_depth(parser *p);
rayo_status scene_parse_background(parser *p);
rayo_status scene_parse_ambient(parser *p);

/* scene_file_objects.c */
rayo_status scene_parse_light(parser *p);
rayo_status scene_parse_material(parser *p);
rayo_status scene_parse_sphere(parser *p);
rayo_status scene_parse_plane(parser *p);
rayo_status scene_parse_triangle(parser *p);

/* scene_file_mesh.c */
rayo_status scene_parse_mesh(parser *p);

/* The optional "material NAME" at the end of an object's line: *id, or
 * material 0 when the line ends first.  (scene_file_objects.c) */
rayo_status scene_object_material(parser *p, const char *statement,
                                  unsigned *id);

/* The material defined with that name, or NULL.  (scene_file_objects.c) */
material_name *scene_find_name(const parser *p, const char *text,
                               size_t length);

#endif
