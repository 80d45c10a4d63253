/*
 * scene_file_split.h - reading a large scene file's sphere lines on
 * several threads, ahead of the parser (scene_file.c), which then takes
 * the file's statements in order.  Private to the library.
 *
 * The text is one window of the file: whole lines, at most about
 * SCENE_WINDOW bytes of them (scene_file_impl.h).  It is cut into parts
 * at line ends, one a thread.  Each part's lines with words become
 * records, in order: a sphere line that reads cleanly (four numbers
 * within the limits, a positive radius, nothing or "material NAME"
 * after) carries its values, the name as a number in the part's table
 * of the names its lines use; any other line (every other statement,
 * and a sphere line with anything wrong in it) is only pointed at, for
 * the parser to read as it always does.  A part stops at
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
    uint32_t name;            /* its material's name in the part's names;
                                 SPLIT_NO_NAME: none */
} split_line;

#define SPLIT_NO_NAME UINT32_MAX

/* A material name that the part's clean sphere lines use, once each, so
 * that the parser looks each up once a part, not once a line.  `id` is
 * the parser's: filled in (with found = 1) the first time the name is
 * found defined, in file order; a name is never defined twice, so that
 * answer holds for the part's later lines. */
typedef struct split_name {
    const char *text;
    size_t length;
    unsigned id;
    int found;
} split_name;

typedef struct split_part {
    split_line *lines;
    size_t count, capacity;
    split_name *names;        /* the distinct names, in first use */
    size_t name_count, name_capacity;
    uint32_t *slots;          /* hash table of names: position + 1 */
    size_t slot_capacity;     /* a power of two, > 2 name_count */
    unsigned long line_count; /* lines in the part (for the next one's
                                 numbers) */
    int failed;               /* out of memory: the window is read alone */
} split_part;

/* The parts of one window, kept from window to window so that their
 * arrays (and the pages under them) serve every window. */
typedef struct split_set {
    split_part *parts;
    size_t count;
} split_set;

/* A window at least this long is split, when threads > 1. */
#define SCENE_SPLIT_MIN_BYTES (256ul << 10)

/*
 * Cuts text[0, length) (whole lines) into parts (at most `parts`, each
 * ending after a newline but the last) and reads them on as many
 * threads, into set->parts[0, set->count).  Line numbers count from the
 * text's first line.  0 when out of memory (set keeps what it has, for
 * scene_split_free).
 */
int scene_split_read(split_set *set, const char *name, const char *text,
                     size_t length, unsigned parts);

void scene_split_free(split_set *set);

#endif
