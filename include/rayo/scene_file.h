/*
 * scene_file.h - reading scene files (docs/scene-format.md): text in,
 * a camera description, a prepared scene and render settings out.
 *
 * A scene file is lines of words: a keyword (camera, shade, samples,
 * depth, background, ambient, light, material, sphere, plane, triangle,
 * mesh) and its values; '#' starts a comment.  Every failure is one line of the
 * form "FILE:LINE:COL: what was found; what was expected", with the status
 * RAYO_ERR_FORMAT (a word where a number should be, an unknown keyword),
 * RAYO_ERR_INVALID (a negative radius, a zero-length direction, two
 * cameras) or RAYO_ERR_LIMIT (absurd sizes, too many objects, a line or a
 * file too long); RAYO_ERR_IO when the file cannot be read.  The parser
 * never prints; it knows nothing of rendering beyond the settings it
 * hands back.
 */
#ifndef RAYO_SCENE_FILE_H
#define RAYO_SCENE_FILE_H

#include <stddef.h>

#include "rayo/camera_spec.h"
#include "rayo/export.h"
#include "rayo/render.h"
#include "rayo/scene.h"
#include "rayo/status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Longest line, in bytes (newline excluded). */
#define RAYO_SCENE_MAX_LINE 4096u
/* Largest scene file, in bytes (256 MiB). */
#define RAYO_SCENE_MAX_BYTES (256ul << 20)
/* Largest magnitude of any number in a scene file. */
#define RAYO_SCENE_MAX_NUMBER 1e12
/* Longest material name, in bytes. */
#define RAYO_SCENE_MAX_NAME 64u

typedef struct rayo_scene_file {
    rayo_scene *scene;        /* owned; prepared, ready to render */
    rayo_camera_spec camera;  /* rayo_camera_spec_init's unless given */
    int camera_given;         /* 1 when the file has a camera line */
    rayo_shade_mode shade;    /* RAYO_SHADE_PHONG unless a shade line */
    int shade_given;
    unsigned samples;         /* 1 unless a samples line */
    unsigned depth;           /* 5 unless a depth line */
    rayo_tp1_reading tp1;     /* the shade course-tp1 line's readings */
    /* What the mesh lines did: triangles added, triangles left out
       (corners on one line once placed), OBJ statements not used (vn,
       vt, g, ...); for the command's warnings. */
    unsigned long long mesh_triangles, mesh_left_out, mesh_ignored;
} rayo_scene_file;

/*
 * Parses length bytes of text; name is the file name used in messages.
 * On failure *file holds nothing to free.
 */
RAYO_API rayo_status rayo_scene_file_parse(rayo_scene_file *file,
                                           const char *name, const char *text,
                                           size_t length, rayo_error *err);

/*
 * Reads and parses the file at path (at most RAYO_SCENE_MAX_BYTES);
 * "-" is standard input, called "standard input" in messages.
 * RAYO_ERR_IO, naming the path and the system's reason, when it cannot
 * be read.
 */
RAYO_API rayo_status rayo_scene_file_load(rayo_scene_file *file,
                                          const char *path, rayo_error *err);

/*
 * The same two, reading and preparing on at most threads threads (0: one
 * per CPU, as the two above; 1: the caller's alone).  The scene is the
 * same for any number: the command passes its --threads.
 */
RAYO_API rayo_status rayo_scene_file_parse_threads(
    rayo_scene_file *file, const char *name, const char *text, size_t length,
    unsigned threads, rayo_error *err);
RAYO_API rayo_status rayo_scene_file_load_threads(rayo_scene_file *file,
                                                  const char *path,
                                                  unsigned threads,
                                                  rayo_error *err);

/* Frees the scene; safe on a zeroed or failed rayo_scene_file. */
RAYO_API void rayo_scene_file_free(rayo_scene_file *file);

#ifdef __cplusplus
}
#endif

#endif
