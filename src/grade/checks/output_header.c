/*
 * output_header.c - what a program's output says it is, read from its
 * first bytes without decoding anything: Netpbm's magic, width and
 * height (plain or raw, a lowercase magic and "640x480" too, as the
 * strict checker reads them), or PNG's IHDR.
 *
 * The grader asks this before it hands the output to the strict checker
 * or the readers, so that an image whose header promises far more pixels
 * than the exercise's is refused by the size it names instead of being
 * decoded in the grader's own memory.  It is not a validator: a header
 * it reads may still be wrong in every other way, and a header it cannot
 * read is left to the checker, which says what is wrong with it.
 */
#include <string.h>

#include "../grade_impl.h"

/* Numbers past this are kept at it: far past any size a reader takes. */
#define SATURATED ((uint64_t)1 << 40)

typedef struct cursor {
    const unsigned char *data;
    size_t size, pos;
} cursor;

static int is_space(int c)
{
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' ||
           c == '\f';
}

/* Whitespace and '#' comments, as Netpbm's headers allow them. */
static void skip_space(cursor *c)
{
    while (c->pos < c->size) {
        if (is_space(c->data[c->pos]))
            c->pos++;
        else if (c->data[c->pos] == '#')
            while (c->pos < c->size && c->data[c->pos] != '\n')
                c->pos++;
        else
            break;
    }
}

static int read_number(cursor *c, uint64_t *n)
{
    size_t start = c->pos;
    *n = 0;
    while (c->pos < c->size && c->data[c->pos] >= '0' &&
           c->data[c->pos] <= '9') {
        if (*n < SATURATED)
            *n = *n * 10 + (uint64_t)(c->data[c->pos] - '0');
        c->pos++;
    }
    if (*n > SATURATED)
        *n = SATURATED;
    return c->pos > start;
}

static const char *netpbm_name(int digit)
{
    switch (digit) {
    case '1': return "plain PBM";
    case '2': return "plain PGM";
    case '3': return "plain PPM";
    case '4': return "raw PBM";
    case '5': return "raw PGM";
    case '6': return "raw PPM";
    }
    return NULL;
}

static int peek_netpbm(cursor *c, grade_header *h)
{
    uint64_t maxval;
    /* Whitespace before the magic is a mistake the checker names; the
       size behind it still counts. */
    while (c->pos < c->size && c->pos < 4096 && is_space(c->data[c->pos]))
        c->pos++;
    if (c->size - c->pos < 2 ||
        (c->data[c->pos] != 'P' && c->data[c->pos] != 'p') ||
        netpbm_name(c->data[c->pos + 1]) == NULL)
        return 0;
    h->format = netpbm_name(c->data[c->pos + 1]);
    h->depth = c->data[c->pos + 1] == '1' || c->data[c->pos + 1] == '4'
                   ? 1
                   : 0;
    c->pos += 2;
    skip_space(c);
    if (!read_number(c, &h->width))
        return 0;
    if (c->pos < c->size &&
        (c->data[c->pos] == 'x' || c->data[c->pos] == 'X'))
        c->pos++;
    else
        skip_space(c);
    if (!read_number(c, &h->height))
        return 0;
    if (h->depth == 0) {
        skip_space(c);
        h->depth = read_number(c, &maxval) && maxval > 255 ? 16 : 8;
    }
    return 1;
}

static uint64_t big_endian(const unsigned char *p)
{
    return (uint64_t)p[0] << 24 | (uint64_t)p[1] << 16 |
           (uint64_t)p[2] << 8 | (uint64_t)p[3];
}

static int peek_png(const cursor *c, grade_header *h)
{
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G',
                                               '\r', '\n', 0x1a, '\n'};
    const unsigned char *p = c->data;
    if (c->size < 8 + 8 + 10 || memcmp(p, signature, 8) != 0 ||
        memcmp(p + 12, "IHDR", 4) != 0)
        return 0;
    h->format = "PNG";
    h->width = big_endian(p + 16);
    h->height = big_endian(p + 20);
    h->depth = p[24];
    return 1;
}

int grade_header_peek(const void *data, size_t size, grade_header *header)
{
    cursor c;
    memset(header, 0, sizeof *header);
    c.data = data;
    c.size = size;
    c.pos = 0;
    if (data == NULL)
        return 0;
    if (peek_png(&c, header))
        return 1;
    if (peek_netpbm(&c, header))
        return 1;
    memset(header, 0, sizeof *header);
    return 0;
}

uint64_t grade_pixels_allowed(const rayo_grade_exercise *exercise,
                              const rayo_image *reference)
{
    uint64_t most = (uint64_t)exercise->width * exercise->height;
    if (reference != NULL &&
        (uint64_t)reference->info.width * reference->info.height > most)
        most = (uint64_t)reference->info.width * reference->info.height;
    return most * GRADE_SIZE_MARGIN;
}
