/*
 * png_chunks.h - following a PNG's chunks as its bytes go by, so that
 * reading can stop once the image is complete.
 *
 * png_read.c hands every byte libpng reads to rayo_png_chunks_see, which
 * keeps the current chunk's header, position and running CRC.  When the
 * last row has been decoded, rayo_png_chunks_finish reads the rest of the
 * file up to IEND itself: it checks each chunk's CRC, length and type but
 * inflates nothing, so compressed data after the image (a zlib bomb in
 * IDAT) costs the time of reading it, not of inflating it.  Not a PNG
 * parser: libpng reads everything up to the image's last row.  Not a
 * public header.
 */
#ifndef RAYO_PNG_CHUNKS_H
#define RAYO_PNG_CHUNKS_H

#include <stdint.h>

#include "read_source.h"

typedef struct rayo_png_chunks {
    uint32_t table[256];     /* CRC-32 of each byte value (ISO 3309) */
    uint64_t at;             /* bytes of the current chunk seen so far,
                                0 to 12 + length */
    uint32_t length;         /* the current chunk's data length */
    unsigned char head[8];   /* its length and type, as read */
    unsigned char tail[4];   /* its CRC, as read */
    uint32_t crc;            /* running CRC of its type and data */
} rayo_png_chunks;

/* Starts before the first chunk (after the 8-byte signature). */
void rayo_png_chunks_init(rayo_png_chunks *c);

/* Follows size bytes of the stream, in order; nothing is checked. */
void rayo_png_chunks_see(rayo_png_chunks *c, const unsigned char *data,
                         size_t size);

/*
 * Reads src from where the chunks stand up to the end of IEND, leaving
 * the cursor after it.  Each chunk's CRC must match (the current one's
 * too, whose first bytes were seen); IDAT and ancillary chunks are
 * skipped; another critical chunk, a length over 2^31 - 1, a type that is
 * not four letters or the end of the data is RAYO_ERR_FORMAT (RAYO_ERR_IO
 * for a failed read) naming src and the byte.
 */
rayo_status rayo_png_chunks_finish(rayo_png_chunks *c, rayo_source *src,
                                   rayo_error *err);

#endif
