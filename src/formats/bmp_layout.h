/*
 * bmp_layout.h - the BMP facts bmp_read.c and bmp_write.c share: the
 * headers' sizes, the stored row's padding, little-endian fields.  Not a
 * public header; docs/formats.md describes the format.
 */
#ifndef RAYO_BMP_LAYOUT_H
#define RAYO_BMP_LAYOUT_H

#include <stddef.h>
#include <stdint.h>

/* The file header and a BITMAPINFOHEADER: where a 24-bit raster starts. */
#define RAYO_BMP_FILE_HEADER 14u
#define RAYO_BMP_INFO_HEADER 40u
#define RAYO_BMP_HEADERS (RAYO_BMP_FILE_HEADER + RAYO_BMP_INFO_HEADER)

/* Bytes of a stored row of width pixels of bits each: padded to 4. */
static inline size_t rayo_bmp_stride(uint32_t width, unsigned bits)
{
    return (size_t)(((uint64_t)width * bits + 31u) / 32u * 4u);
}

static inline void rayo_bmp_put16(unsigned char *p, uint16_t v)
{
    p[0] = (unsigned char)(v & 0xff);
    p[1] = (unsigned char)(v >> 8);
}

static inline void rayo_bmp_put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v & 0xff);
    p[1] = (unsigned char)((v >> 8) & 0xff);
    p[2] = (unsigned char)((v >> 16) & 0xff);
    p[3] = (unsigned char)(v >> 24);
}

static inline uint16_t rayo_bmp_get16(const unsigned char *p)
{
    return (uint16_t)(p[0] | (p[1] << 8));
}

static inline uint32_t rayo_bmp_get32(const unsigned char *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) |
           ((uint32_t)p[3] << 24);
}

#endif
