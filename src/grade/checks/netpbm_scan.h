/*
 * netpbm_scan.h - what the strict checkers of plain PBM (pbm_check.c)
 * and plain PGM and PPM (pnm_check.c) share: a cursor over the output
 * that remembers the first failure to record a finding, positions as
 * line and column, quoting untrusted bytes, the magic number and the
 * dimensions, the pixel-count verdict and the line-length note.
 *
 * Private to src/grade: the public entry points are in pbm_check.h.
 * Nothing here knows the raster of a particular format.
 */
#ifndef RAYO_NETPBM_SCAN_H
#define RAYO_NETPBM_SCAN_H

#include <stddef.h>
#include <stdint.h>

#include "rayo/grade.h"
#include "rayo/image.h"
#include "rayo/status.h"

#include "../grade_impl.h"

typedef struct netpbm_scan {
    const unsigned char *data;
    size_t size, pos;
    rayo_grade_item *item;
    rayo_error *err;
    rayo_status status; /* the first failure to record a line */
} netpbm_scan;

/* The plain format an exercise asks for. */
typedef struct netpbm_kind {
    char magic;          /* '1', '2' or '3' */
    const char *name;    /* "PBM", "PGM", "PPM" */
    const char *samples; /* what its raster is made of: "digits" */
    const char *file;    /* the course's file name: "imagen.pbm" */
    unsigned channels;   /* 1 or 3 (1 for PBM's bits too) */
} netpbm_kind;

/* What the magic number turned out to be. */
typedef enum netpbm_magic {
    NETPBM_MAGIC_REFUSED, /* not Netpbm at all; said so */
    NETPBM_MAGIC_WANTED,  /* the kind asked for (perhaps lowercase; said) */
    NETPBM_MAGIC_OTHER    /* another Netpbm magic; nothing said yet */
} netpbm_magic;

/* Marks a whole sentence for xgettext; grade_fail and grade_say look it
   up in err's language. */
#ifndef N_
#define N_(text) text
#endif

#define NETPBM_FAIL(s, ...)                                                  \
    do {                                                                     \
        if ((s)->status == RAYO_OK)                                          \
            (s)->status = grade_fail((s)->item, (s)->err, __VA_ARGS__);      \
    } while (0)

#define NETPBM_SAY(s, ...)                                                   \
    do {                                                                     \
        if ((s)->status == RAYO_OK)                                          \
            (s)->status = grade_say((s)->item, (s)->err, __VA_ARGS__);       \
    } while (0)

static inline int netpbm_is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
           c == '\f';
}

static inline int netpbm_is_digit(int c)
{
    return c >= '0' && c <= '9';
}

static inline int netpbm_peek(const netpbm_scan *s)
{
    return s->pos < s->size ? s->data[s->pos] : -1;
}

/* The kind for magic '1', '2' or '3'; NULL for anything else. */
const netpbm_kind *netpbm_kind_of(char magic);

/* Line and column (from 1) of a byte offset. */
void netpbm_where(const netpbm_scan *s, size_t offset, unsigned long *line,
                  unsigned long *column);

/* Up to length (at most 16) bytes from offset, escaped to be printable,
   for quoting in a message; room is at least 80. */
void netpbm_excerpt(const netpbm_scan *s, size_t offset, size_t length,
                    char *out, size_t room);

/* Whitespace and '#' comments, as a header allows. */
void netpbm_skip_header_space(netpbm_scan *s);

/* A decimal number at pos; 0 when there is none.  Saturates at 10^9. */
int netpbm_read_number(netpbm_scan *s, unsigned long *value);

/* "plain PGM (gray)" for a Netpbm magic (P or p, then 1-6); NULL else. */
const char *netpbm_format_name(const unsigned char *magic);

/*
 * Finds the magic number, saying what is wrong with it: whitespace
 * before it, a PNG, text, a lowercase 'p', no whitespace after.  On
 * NETPBM_MAGIC_WANTED pos is just after it; on NETPBM_MAGIC_OTHER pos is
 * at it and the caller decides (netpbm_refuse_other says the usual).
 */
netpbm_magic netpbm_check_magic(netpbm_scan *s, const netpbm_kind *kind);

/* "the magic number is 'P5', raw PGM ...; the exercise asks for ...". */
void netpbm_refuse_other(netpbm_scan *s, const netpbm_kind *kind);

/* The header's numbers, each named in a whole sentence of its own. */
typedef enum netpbm_field {
    NETPBM_FIELD_WIDTH,  /* after the magic number 'P<magic>' */
    NETPBM_FIELD_HEIGHT, /* after the width */
    NETPBM_FIELD_MAXVAL  /* after the height */
} netpbm_field;

/* Expects a number after header space; says what is there instead.
   magic is the kind's, for the width's sentence. */
int netpbm_expect_number(netpbm_scan *s, netpbm_field field, int magic,
                         unsigned long *value);

/* Width and height, checked against the exercise's; 1 when both could
   be read and an image of that size can be made. */
int netpbm_check_dimensions(netpbm_scan *s, const netpbm_kind *kind,
                            uint32_t want_w, uint32_t want_h,
                            unsigned long *w, unsigned long *h);

/* The verdict on how many samples the raster held, in pixels and rows. */
void netpbm_say_count(netpbm_scan *s, const netpbm_kind *kind,
                      unsigned long w, unsigned long h,
                      unsigned long long samples);

/* A note (not a warning) when lines exceed Netpbm's 70 characters. */
void netpbm_note_line_lengths(netpbm_scan *s);

/* The raster checkers (pbm_check.c, pnm_check.c), from the magic on;
   image is zeroed and item's result is pass when they start. */
void netpbm_check_p1(netpbm_scan *s, uint32_t width, uint32_t height,
                     rayo_image *image);
void netpbm_check_p2_p3(netpbm_scan *s, const netpbm_kind *kind,
                        uint32_t width, uint32_t height, rayo_image *image);

#endif
