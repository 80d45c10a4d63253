/*
 * scene_file_split.h - reading a large scene file's sphere lines on
 * several threads, ahead of the parser (scene_file.c), which then takes
 * the file's statements in order.  Private to the library.
 *
 * The text is cut into parts at line ends, one a thread.  Each part's
 * lines with words become records, in order: a sphere line that reads
 * cleanly (four numbers within the limits, a positive radius, nothing or
 * "material NAME" after) carries its values; any other line (every other
 * statement, and a sphere line with anything wrong in it) is only
 * pointed at, for the parser to read as it always does.  A part stops at
 * a line the lexer refuses (too long, a NUL byte): that line is its last
 * record.  Nothing here reports an error; the parser, reading the lines
 * pointed at, says exactly what it says reading the file alone.
 */
#ifndef RAYO_SCENE_FILE_SPLIT_H
#define RAYO_SCENE_FILE_SPLIT_H

#include <stddef.h>
#include <stdint.h>

/* One line with words on it (56 bytes: a file has many). */
typedef struct split_line {
    double center[3], radius; /* a clean sphere line's values */
    size_t offset;            /* where the line starts in the text */
    uint32_t line;            /* its number within its part, from 1 */
    uint32_t sphere;          /* 1: a clean sphere line */
    uint32_t material_at;     /* its material's name: from the line's */
    uint32_t material_length; /* start, so long; 0: no material */
} split_line;

typedef struct split_part {
    split_line *lines;
    size_t count, capacity;
    unsigned long line_count; /* lines in the part (for the next one's
                                 numbers) */
    int failed;               /* out of memory: read the file alone */
} split_part;

/* Files at least this long (and at most RAYO_SCENE_MAX_BYTES, so line
 * numbers fit 32 bits) are split, when threads > 1. */
#define SCENE_SPLIT_MIN_BYTES (1ul << 20)

/* The parser splits a file this much at a time (each piece cut at a line
 * end), so the records of a 256 MiB file of short lines never all exist
 * at once: at most about 60 MB of them. */
#define SCENE_SPLIT_WINDOW (16ul << 20)

/*
 * Cuts text[from, length) (from at a line's start) into parts (at most
 * `parts`, each ending after a newline but the last) and reads them on
 * as many threads; *out gets the array and *count its length.  Line
 * numbers count from the first line at from.  0 when out of memory
 * (nothing to free then).
 */
int scene_split_read(const char *name, const char *text, size_t from,
                     size_t length, unsigned parts, split_part **out,
                     size_t *count);

void scene_split_free(split_part *parts, size_t count);

#endif
