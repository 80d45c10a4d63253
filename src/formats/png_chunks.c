/*
 * png_chunks.c - following a PNG's chunks as its bytes go by, and reading
 * the rest of the file up to IEND without inflating it (see png_chunks.h
 * for why).
 *
 * A chunk is a 4-byte big-endian length, a 4-byte type, the data and a
 * CRC-32 of type and data.  The CRC is computed here from a table made
 * for each reader (1 KiB, no shared state), rather than asking for zlib,
 * which libpng links but rayo does not.
 */
#include "png_chunks.h"

#include <string.h>

#define PNG_MAX_CHUNK_LENGTH 0x7fffffffu

void rayo_png_chunks_init(rayo_png_chunks *c)
{
    uint32_t n, k, v;
    memset(c, 0, sizeof *c);
    for (n = 0; n < 256; n++) {
        v = n;
        for (k = 0; k < 8; k++)
            v = (v & 1) ? 0xedb88320u ^ (v >> 1) : v >> 1;
        c->table[n] = v;
    }
}

static uint32_t crc_update(const rayo_png_chunks *c, uint32_t crc,
                           const unsigned char *data, size_t size)
{
    size_t i;
    for (i = 0; i < size; i++)
        crc = c->table[(crc ^ data[i]) & 0xffu] ^ (crc >> 8);
    return crc;
}

static uint32_t be32(const unsigned char *p)
{
    return ((uint32_t)p[0] << 24) | ((uint32_t)p[1] << 16) |
           ((uint32_t)p[2] << 8) | p[3];
}

/* Bytes from the cursor to the end of the current part (header, data or
   CRC). */
static uint64_t part_left(const rayo_png_chunks *c)
{
    if (c->at < 8)
        return 8 - c->at;
    if (c->at < 8 + (uint64_t)c->length)
        return 8 + (uint64_t)c->length - c->at;
    return 12 + (uint64_t)c->length - c->at;
}

enum { SAW_PART, SAW_HEADER, SAW_CHUNK };

/* Takes size <= part_left bytes; says whether they ended a header or a
   chunk (then at is 0 again and tail holds the chunk's CRC). */
static int take(rayo_png_chunks *c, const unsigned char *data, size_t size)
{
    if (c->at < 8) {
        memcpy(c->head + c->at, data, size);
        c->at += size;
        if (c->at < 8)
            return SAW_PART;
        c->length = be32(c->head);
        c->crc = crc_update(c, 0xffffffffu, c->head + 4, 4);
        return SAW_HEADER;
    }
    if (c->at < 8 + (uint64_t)c->length) {
        c->crc = crc_update(c, c->crc, data, size);
        c->at += size;
        return SAW_PART;
    }
    memcpy(c->tail + (c->at - 8 - c->length), data, size);
    c->at += size;
    if (c->at < 12 + (uint64_t)c->length)
        return SAW_PART;
    c->at = 0;
    return SAW_CHUNK;
}

void rayo_png_chunks_see(rayo_png_chunks *c, const unsigned char *data,
                         size_t size)
{
    while (size > 0) {
        uint64_t left = part_left(c);
        size_t n = left < size ? (size_t)left : size;
        take(c, data, n);
        data += n;
        size -= n;
    }
}

static int is_letter(unsigned char b)
{
    return (b >= 'A' && b <= 'Z') || (b >= 'a' && b <= 'z');
}

/* A chunk's header, once read: may the rest of the file go on so? */
static rayo_status check_header(rayo_png_chunks *c, const rayo_source *src,
                                rayo_error *err)
{
    const unsigned char *type = c->head + 4;
    unsigned long long at = (unsigned long long)rayo_source_offset(src) - 8;
    if (!is_letter(type[0]) || !is_letter(type[1]) || !is_letter(type[2]) ||
        !is_letter(type[3]))
        return rayo_error_set(err, RAYO_ERR_FORMAT,
                              "%s: byte %llu: found a chunk type of bytes "
                              "%02x %02x %02x %02x; expected four letters",
                              src->name, at, type[0], type[1], type[2],
                              type[3]);
    if (c->length > PNG_MAX_CHUNK_LENGTH)
        return rayo_error_set(err, RAYO_ERR_FORMAT,
                              "%s: byte %llu: found a %.4s chunk of %lu "
                              "bytes; expected at most 2^31-1",
                              src->name, at, (const char *)type,
                              (unsigned long)c->length);
    if (memcmp(type, "IDAT", 4) == 0 || memcmp(type, "IEND", 4) == 0 ||
        (type[0] & 0x20) != 0)
        return RAYO_OK;
    return rayo_error_set(err, RAYO_ERR_FORMAT,
                          "%s: byte %llu: found a %.4s chunk after the "
                          "image data; expected IEND (critical chunks "
                          "other than IDAT come before it)",
                          src->name, at, (const char *)type);
}

rayo_status rayo_png_chunks_finish(rayo_png_chunks *c, rayo_source *src,
                                   rayo_error *err)
{
    unsigned char buffer[16384];
    for (;;) {
        uint64_t left = part_left(c);
        size_t want = left < sizeof buffer ? (size_t)left : sizeof buffer;
        size_t got;
        int saw;
        rayo_status status;
        rayo_source_read(src, buffer, want, &got);
        if (got < want)
            return rayo_source_end_error(src,
                                         "more PNG data (the file is cut "
                                         "short or has no IEND chunk)",
                                         err);
        saw = take(c, buffer, got);
        if (saw == SAW_HEADER &&
            (status = check_header(c, src, err)) != RAYO_OK)
            return status;
        if (saw != SAW_CHUNK)
            continue;
        if ((c->crc ^ 0xffffffffu) != be32(c->tail))
            return rayo_error_set(err, RAYO_ERR_FORMAT,
                                  "%s: byte %llu: found %.4s: CRC error; "
                                  "expected a well-formed PNG stream",
                                  src->name,
                                  (unsigned long long)rayo_source_offset(src),
                                  (const char *)(c->head + 4));
        if (memcmp(c->head + 4, "IEND", 4) == 0)
            return RAYO_OK;
    }
}
