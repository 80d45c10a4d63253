/*
 * scene_file_impl.h - reading a scene file a window at a time, for the
 * loader (scene_file_load.c) and for texts in memory (scene_file.c).
 * Private to the library.
 *
 * Why windows: a page of memory costs a good deal the first time it is
 * touched (docs/performance.md, "Setup"), and a large file's text and
 * records would be many pages.  Read a window at a time into one
 * buffer, with the records' arrays kept from window to window, the file
 * costs 1 MiB of each instead.  The parser keeps its state (the material
 * names, the line numbers, the statements seen once) between windows, so
 * the scene and the first error are those of the whole text read at
 * once.  The hierarchy is built after the text is freed
 * (scene_file_read_text, then scene_file_prepare), so its arrays can
 * take the text's memory.
 */
#ifndef RAYO_SCENE_FILE_IMPL_H
#define RAYO_SCENE_FILE_IMPL_H

#include "rayo/scene_file.h"

/* A window's size: whole lines of about this many bytes.  Larger than a
 * line may be (RAYO_SCENE_MAX_LINE), so a window without a newline holds
 * a line the lexer refuses as too long, as it would in the whole text. */
#define SCENE_WINDOW (1ul << 20)

typedef struct scene_reader scene_reader;

/* Starts reading a scene into *file (its defaults set and its scene
 * made; prepared later by scene_file_prepare); long windows are read on
 * `threads` threads (0: one per processor). */
rayo_status scene_reader_new(scene_reader **reader, rayo_scene_file *file,
                             const char *name, unsigned threads,
                             rayo_error *err);

/* The file's next lines: text[0, length), which ends just after a
 * newline, or is the file's last window, or is a window without a
 * newline (SCENE_WINDOW bytes of one line).  The text may be freed or
 * overwritten once this returns. */
rayo_status scene_reader_take(scene_reader *reader, const char *text,
                              size_t length);

/* Frees the reader and returns status; when status is not RAYO_OK, the
 * file's scene is freed too. */
rayo_status scene_reader_end(scene_reader *reader, rayo_status status);

/* rayo_scene_file_parse_threads without rayo_scene_prepare_threads. */
rayo_status scene_file_read_text(rayo_scene_file *file, const char *name,
                                 const char *text, size_t length,
                                 unsigned threads, rayo_error *err);

/* rayo_scene_prepare_threads on the file's scene; on failure the file
 * is freed, as rayo_scene_file_parse_threads leaves it. */
rayo_status scene_file_prepare(rayo_scene_file *file, unsigned threads,
                               rayo_error *err);

#endif
