/*
 * zlib.h - the compression constants the PNG writers name, for the
 * page's libpng (png_shim.c), which stores rows uncompressed: levels and
 * strategies are accepted and ignored.
 */
#ifndef RAYO_WEB_ZLIB_H
#define RAYO_WEB_ZLIB_H

#define Z_BEST_SPEED 1
#define Z_DEFAULT_COMPRESSION (-1)
#define Z_FILTERED 1
#define Z_HUFFMAN_ONLY 2
#define Z_RLE 3
#define Z_DEFAULT_STRATEGY 0

#endif
