/*
 * png.h - the part of libpng's writing interface that rayo's PNG writers
 * (src/formats/png_write.c, src/compare/diff_image.c) call, for the page's
 * WebAssembly build, which has no libpng.  png_shim.c implements it.
 *
 * The page decodes PNG with the browser (createImageBitmap) and saves
 * what it shows with canvas.toBlob; this is only so that the library's
 * difference pictures come out of the library as the command makes them,
 * the same pixels in a PNG the browser can show.  Errors are reported to
 * the error callback, which jumps (png_longjmp): the module traps there,
 * which the page shows as an error.  Writes go to rayo's memory output
 * (rayo_output_open_memory), which fails only when memory does.
 */
#ifndef RAYO_WEB_PNG_H
#define RAYO_WEB_PNG_H

#include <setjmp.h>
#include <stddef.h>
#include <stdint.h>

#define PNG_LIBPNG_VER_STRING "rayo-web"
#define PNG_COLOR_TYPE_GRAY 0
#define PNG_COLOR_TYPE_RGB 2
#define PNG_COLOR_TYPE_PALETTE 3
#define PNG_INTERLACE_NONE 0
#define PNG_COMPRESSION_TYPE_DEFAULT 0
#define PNG_FILTER_TYPE_DEFAULT 0
#define PNG_FILTER_TYPE_BASE 0
#define PNG_FILTER_NONE 0x08

typedef struct png_struct_def png_struct;
typedef png_struct *png_structp;
typedef const png_struct *png_const_structp;
typedef png_structp *png_structpp;
typedef struct png_info_def png_info;
typedef png_info *png_infop;
typedef png_infop *png_infopp;
typedef unsigned char *png_bytep;
typedef const unsigned char *png_const_bytep;
typedef const char *png_const_charp;
typedef struct png_color {
    unsigned char red, green, blue;
} png_color;

typedef void (*png_error_ptr)(png_structp, png_const_charp);
typedef void (*png_rw_ptr)(png_structp, png_bytep, size_t);
typedef void (*png_flush_ptr)(png_structp);

png_structp png_create_write_struct(png_const_charp version, void *error_ptr,
                                    png_error_ptr error_fn,
                                    png_error_ptr warning_fn);
png_infop png_create_info_struct(png_const_structp png);
void png_destroy_write_struct(png_structpp png, png_infopp info);
void *png_get_error_ptr(png_const_structp png);
void *png_get_io_ptr(png_const_structp png);
void png_set_write_fn(png_structp png, void *io_ptr, png_rw_ptr write_fn,
                      png_flush_ptr flush_fn);
void png_set_compression_level(png_structp png, int level);
void png_set_compression_strategy(png_structp png, int strategy);
void png_set_filter(png_structp png, int method, int filters);
void png_set_IHDR(png_const_structp png, png_infop info, uint32_t width,
                  uint32_t height, int depth, int color, int interlace,
                  int compression, int filter);
void png_set_PLTE(png_structp png, png_infop info, const png_color *palette,
                  int count);
void png_write_info(png_structp png, png_infop info);
void png_set_invert_mono(png_structp png);
void png_write_row(png_structp png, png_const_bytep row);
void png_write_end(png_structp png, png_infop info);
_Noreturn void png_error(png_const_structp png, png_const_charp message);
_Noreturn void png_longjmp(png_const_structp png, int value);
#define png_jmpbuf(png) ((void)(png), (int *)0)

#endif
