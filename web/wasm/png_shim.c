/*
 * png_shim.c - libpng's writing calls (include/png.h) for the page's
 * WebAssembly build: PNG files with their rows stored, not compressed.
 *
 * The image data is one zlib stream of "stored" deflate blocks, a block
 * per row (a row of rayo's is at most 4096 x 3 x 2 + 1 bytes, under a
 * block's 65535), each in an IDAT chunk of its own, so rows are written
 * as they come and memory holds none.  A 640 x 480 difference picture
 * is 77 KB at 2 bits a pixel: it is shown at once and never stored, so
 * compression would buy nothing.  Valid PNG (any decoder reads it);
 * levels, strategies and filters are accepted and ignored.
 */
#include <png.h>

#include <stdlib.h>
#include <string.h>

struct png_struct_def {
    void *error_ptr, *io_ptr;
    png_error_ptr error_fn;
    png_rw_ptr write_fn;
    uint32_t width, height;
    int depth, color, invert, palette_count;
    png_color palette[256];
    size_t row_bytes;
    uint32_t adler_a, adler_b;
    unsigned char *row; /* row_bytes + 1: the filter byte and the row */
};

struct png_info_def {
    int unused;
};

static uint32_t crc_table[256];

static void crc_init(void)
{
    uint32_t n, c, k;
    if (crc_table[1] != 0)
        return;
    for (n = 0; n < 256; n++) {
        for (c = n, k = 0; k < 8; k++)
            c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        crc_table[n] = c;
    }
}

static uint32_t crc_add(uint32_t crc, const unsigned char *p, size_t n)
{
    while (n--)
        crc = crc_table[(crc ^ *p++) & 0xFFu] ^ (crc >> 8);
    return crc;
}

static void put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

static void emit(png_structp png, const void *data, size_t n)
{
    png->write_fn(png, (png_bytep)(uintptr_t)data, n);
}

/* A chunk whose data is head (hn bytes) then body (bn bytes). */
static void chunk(png_structp png, const char *type, const unsigned char *head,
                  size_t hn, const unsigned char *body, size_t bn)
{
    unsigned char b[8];
    uint32_t crc = 0xFFFFFFFFu;
    put32(b, (uint32_t)(hn + bn));
    memcpy(b + 4, type, 4);
    emit(png, b, 8);
    crc = crc_add(crc, b + 4, 4);
    if (hn) {
        emit(png, head, hn);
        crc = crc_add(crc, head, hn);
    }
    if (bn) {
        emit(png, body, bn);
        crc = crc_add(crc, body, bn);
    }
    put32(b, crc ^ 0xFFFFFFFFu);
    emit(png, b, 4);
}

png_structp png_create_write_struct(png_const_charp version, void *error_ptr,
                                    png_error_ptr error_fn,
                                    png_error_ptr warning_fn)
{
    png_structp png = calloc(1, sizeof *png);
    (void)version, (void)warning_fn;
    crc_init();
    if (png != NULL) {
        png->error_ptr = error_ptr;
        png->error_fn = error_fn;
    }
    return png;
}

png_infop png_create_info_struct(png_const_structp png)
{
    (void)png;
    return calloc(1, sizeof(png_info));
}

void png_destroy_write_struct(png_structpp png, png_infopp info)
{
    if (png != NULL && *png != NULL) {
        free((*png)->row);
        free(*png);
        *png = NULL;
    }
    if (info != NULL && *info != NULL) {
        free(*info);
        *info = NULL;
    }
}

void *png_get_error_ptr(png_const_structp png) { return png->error_ptr; }
void *png_get_io_ptr(png_const_structp png) { return png->io_ptr; }

void png_set_write_fn(png_structp png, void *io_ptr, png_rw_ptr write_fn,
                      png_flush_ptr flush_fn)
{
    (void)flush_fn;
    png->io_ptr = io_ptr;
    png->write_fn = write_fn;
}

void png_set_compression_level(png_structp png, int level)
{
    (void)png, (void)level;
}

void png_set_compression_strategy(png_structp png, int strategy)
{
    (void)png, (void)strategy;
}

void png_set_filter(png_structp png, int method, int filters)
{
    (void)png, (void)method, (void)filters;
}

void png_set_IHDR(png_const_structp png, png_infop info, uint32_t width,
                  uint32_t height, int depth, int color, int interlace,
                  int compression, int filter)
{
    png_structp p = (png_structp)(uintptr_t)png;
    unsigned channels = color == PNG_COLOR_TYPE_RGB ? 3u : 1u;
    (void)info, (void)interlace, (void)compression, (void)filter;
    p->width = width;
    p->height = height;
    p->depth = depth;
    p->color = color;
    p->row_bytes = ((size_t)width * channels * (unsigned)depth + 7) / 8;
}

void png_set_PLTE(png_structp png, png_infop info, const png_color *palette,
                  int count)
{
    (void)info;
    if (count > 256)
        count = 256;
    memcpy(png->palette, palette, (size_t)count * sizeof *palette);
    png->palette_count = count;
}

void png_set_invert_mono(png_structp png) { png->invert = 1; }

void png_write_info(png_structp png, png_infop info)
{
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G',
                                               '\r', '\n', 0x1A, '\n'};
    static const unsigned char zlib_header[2] = {0x78, 0x01};
    unsigned char ihdr[13], plte[768];
    int i;
    (void)info;
    png->row = malloc(png->row_bytes + 1);
    if (png->row == NULL || png->row_bytes + 1 > 65535u)
        png_error(png, png->row == NULL ? "out of memory" : "row too long");
    emit(png, signature, 8);
    put32(ihdr, png->width);
    put32(ihdr + 4, png->height);
    ihdr[8] = (unsigned char)png->depth;
    ihdr[9] = (unsigned char)png->color;
    ihdr[10] = ihdr[11] = ihdr[12] = 0;
    chunk(png, "IHDR", ihdr, 13, NULL, 0);
    if (png->palette_count > 0) {
        for (i = 0; i < png->palette_count; i++) {
            plte[3 * i] = png->palette[i].red;
            plte[3 * i + 1] = png->palette[i].green;
            plte[3 * i + 2] = png->palette[i].blue;
        }
        chunk(png, "PLTE", plte, 3 * (size_t)png->palette_count, NULL, 0);
    }
    chunk(png, "IDAT", zlib_header, 2, NULL, 0);
    png->adler_a = 1;
    png->adler_b = 0;
}

void png_write_row(png_structp png, png_const_bytep row)
{
    size_t n = png->row_bytes + 1, i;
    unsigned char block[5];
    png->row[0] = 0; /* filter: none */
    memcpy(png->row + 1, row, png->row_bytes);
    if (png->invert)
        for (i = 1; i < n; i++)
            png->row[i] = (unsigned char)~png->row[i];
    for (i = 0; i < n; i++) {
        png->adler_a = (png->adler_a + png->row[i]) % 65521u;
        png->adler_b = (png->adler_b + png->adler_a) % 65521u;
    }
    block[0] = 0; /* not the last block; stored */
    block[1] = (unsigned char)(n & 0xFFu);
    block[2] = (unsigned char)(n >> 8);
    block[3] = (unsigned char)(~n & 0xFFu);
    block[4] = (unsigned char)((~n >> 8) & 0xFFu);
    chunk(png, "IDAT", block, 5, png->row, n);
}

void png_write_end(png_structp png, png_infop info)
{
    unsigned char tail[9] = {1, 0, 0, 0xFF, 0xFF}; /* last block, empty */
    (void)info;
    put32(tail + 5, png->adler_b << 16 | png->adler_a);
    chunk(png, "IDAT", tail, 9, NULL, 0);
    chunk(png, "IEND", NULL, 0, NULL, 0);
}

_Noreturn void png_error(png_const_structp png, png_const_charp message)
{
    if (png->error_fn != NULL)
        png->error_fn((png_structp)(uintptr_t)png, message);
    __builtin_trap();
}

_Noreturn void png_longjmp(png_const_structp png, int value)
{
    (void)png, (void)value;
    __builtin_trap();
}

_Noreturn void longjmp(jmp_buf env, int value)
{
    (void)env, (void)value;
    __builtin_trap();
}
