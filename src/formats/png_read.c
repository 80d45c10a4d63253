/*
 * png_read.c - reading PNG with libpng into a rayo_image.
 *
 * libpng does the decoding (every colour type and bit depth, palettes,
 * interlacing); this file chooses libpng's transformations so that the
 * result lands in one of rayo's three layouts (see reader.h for the
 * table), composites alpha over white, and turns libpng's longjmp errors
 * into one rayo_error naming the file and the byte where reading stopped.
 *
 * Hostile files: the IHDR's size is checked against limits.h (libpng's
 * user limits, then rayo_image_info_check) before the image is allocated;
 * ancillary chunks are capped in size; a CRC error in any chunk is an
 * error, and so is a stream that ends before IEND.  Not a writer
 * (png_write.c) and not a colour manager: gamma and ICC chunks are
 * ignored.
 */
#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/limits.h"
#include "reader_impl.h"

/* Largest ancillary chunk libpng may allocate (text, ICC profiles). */
#define PNG_CHUNK_MALLOC_MAX (8u * 1024u * 1024u)

typedef struct png_reader {
    rayo_source *src;
    rayo_image *image;
    png_structp png;
    png_infop info;
    rayo_error error;       /* set before every longjmp */
    char warning[128];      /* libpng's last warning: the reason behind
                               "Invalid IHDR data" */
    int alpha;              /* rows carry an alpha sample to composite */
    unsigned in_channels;   /* samples per pixel in libpng's rows */
    size_t in_row_bytes;    /* libpng's row size after transformations */
    unsigned char *scratch; /* rows with alpha, before compositing */
} png_reader;

static void on_png_error(png_structp png, png_const_charp message)
{
    png_reader *r = png_get_error_ptr(png);
    if (r->error.status == RAYO_OK) {
        int limit = strstr(r->warning, "exceeds user limit") != NULL;
        rayo_error_set(&r->error, limit ? RAYO_ERR_LIMIT : RAYO_ERR_FORMAT,
                       "%s: byte %llu: found %s%s%s%s; expected %s",
                       r->src->name,
                       (unsigned long long)rayo_source_offset(r->src),
                       message, r->warning[0] ? " (" : "", r->warning,
                       r->warning[0] ? ")" : "",
                       limit ? "at most 65536 pixels each way"
                             : "a well-formed PNG stream");
    }
    png_longjmp(png, 1);
}

static void on_png_warning(png_structp png, png_const_charp message)
{
    png_reader *r = png_get_error_ptr(png);
    snprintf(r->warning, sizeof r->warning, "%s", message);
}

static void on_png_read(png_structp png, png_bytep data, size_t length)
{
    png_reader *r = png_get_io_ptr(png);
    size_t got;
    rayo_source_read(r->src, data, length, &got);
    if (got == length)
        return;
    rayo_source_end_error(r->src, "more PNG data (the file is cut short "
                                  "or has no IEND chunk)",
                          &r->error);
    png_error(png, "truncated");
}

/* Sets up libpng's transformations; fills info with rayo's layout. */
static void choose_layout(png_reader *r, rayo_image_info *info)
{
    png_structp png = r->png;
    int depth = png_get_bit_depth(png, r->info);
    int type = png_get_color_type(png, r->info);
    int trns = png_get_valid(png, r->info, PNG_INFO_tRNS) != 0;
    info->width = png_get_image_width(png, r->info);
    info->height = png_get_image_height(png, r->info);
    info->channels = (type & PNG_COLOR_MASK_COLOR) ? 3 : 1;
    info->sample = depth == 16 ? RAYO_SAMPLE_U16 : RAYO_SAMPLE_U8;
    info->maxval = depth == 16 ? 65535 : 255;
    r->alpha = trns || (type & PNG_COLOR_MASK_ALPHA);
    if (type == PNG_COLOR_TYPE_PALETTE)
        png_set_palette_to_rgb(png);
    if (type == PNG_COLOR_TYPE_GRAY && depth < 8 && !trns) {
        if (depth == 1) {
            png_set_invert_mono(png);
            info->sample = RAYO_SAMPLE_BIT;
            info->maxval = 1;
        } else {
            png_set_packing(png);
            info->maxval = (1u << depth) - 1;
        }
    } else if (type == PNG_COLOR_TYPE_GRAY && depth < 8) {
        png_set_expand_gray_1_2_4_to_8(png);
    }
    if (trns)
        png_set_tRNS_to_alpha(png);
    r->in_channels = info->channels + (r->alpha ? 1u : 0u);
}

/* Composites one row of (samples..., alpha) pixels over white. */
static void composite_row(const png_reader *r, const unsigned char *in,
                          unsigned char *out)
{
    const rayo_image_info *info = &r->image->info;
    uint64_t m = info->maxval;
    uint32_t x;
    unsigned c;
    for (x = 0; x < info->width; x++) {
        const unsigned char *p = in + (size_t)x * r->in_channels *
                                          (m > 255 ? 2 : 1);
        uint64_t a = m > 255 ? (uint64_t)((p[2 * info->channels] << 8) |
                                          p[2 * info->channels + 1])
                             : p[info->channels];
        for (c = 0; c < info->channels; c++) {
            uint64_t v = m > 255 ? (uint64_t)((p[2 * c] << 8) | p[2 * c + 1])
                                 : p[c];
            uint64_t mixed = (v * a + m * (m - a) + m / 2) / m;
            size_t index = (size_t)x * info->channels + c;
            if (m > 255) {
                uint16_t s = (uint16_t)mixed;
                memcpy(out + 2 * index, &s, sizeof s);
            } else {
                out[index] = (unsigned char)mixed;
            }
        }
    }
}

/* Big-endian 16-bit samples (libpng's order) to native, in place. */
static void native_row16(unsigned char *row, size_t samples)
{
    size_t i;
    for (i = 0; i < samples; i++) {
        uint16_t v = (uint16_t)((row[2 * i] << 8) | row[2 * i + 1]);
        memcpy(row + 2 * i, &v, sizeof v);
    }
}

static rayo_status allocate(png_reader *r, const rayo_image_info *info,
                            int passes)
{
    size_t rows = passes > 1 ? info->height : 1;
    size_t sample_bytes = info->sample == RAYO_SAMPLE_U16 ? 2 : 1;
    rayo_status status = rayo_image_info_check(info, NULL);
    if (status != RAYO_OK)
        return rayo_error_set(&r->error, status,
                              "%s: byte 16: found a %lux%lu image in the PNG "
                              "IHDR; expected at most %u pixels each way and "
                              "%lu (2^30) in all",
                              r->src->name, (unsigned long)info->width,
                              (unsigned long)info->height,
                              RAYO_MAX_DIMENSION, RAYO_MAX_PIXELS);
    if (r->in_row_bytes != (info->sample == RAYO_SAMPLE_BIT
                                ? ((size_t)info->width + 7) / 8
                                : (size_t)info->width * r->in_channels *
                                      sample_bytes))
        return rayo_error_set(&r->error, RAYO_ERR_FORMAT,
                              "%s: byte 16: found a PNG layout libpng "
                              "cannot give as %u samples a pixel; expected "
                              "a standard colour type and depth",
                              r->src->name, r->in_channels);
    status = rayo_image_create(r->image, info, NULL);
    if (status == RAYO_OK && r->alpha) {
        if (r->in_row_bytes > SIZE_MAX / rows)
            status = RAYO_ERR_NOMEM;
        else if ((r->scratch = malloc(r->in_row_bytes * rows)) == NULL)
            status = RAYO_ERR_NOMEM;
    }
    if (status != RAYO_OK)
        return rayo_error_set(&r->error, status,
                              "%s: out of memory for a %lux%lu image",
                              r->src->name, (unsigned long)info->width,
                              (unsigned long)info->height);
    return RAYO_OK;
}

/*
 * Deflate cannot shrink data more than 1032:1, so a file (or memory) with
 * fewer bytes left than the raster needs over 1032 is lying about its
 * size; refusing it here spares allocating for it.  Unknown sizes (pipes)
 * are found out while reading.
 */
static rayo_status check_room(png_reader *r, const rayo_image_info *info)
{
    uint64_t remaining, bits, raw;
    if (!rayo_source_remaining(r->src, &remaining))
        return RAYO_OK;
    bits = (uint64_t)info->width * png_get_channels(r->png, r->info) *
           png_get_bit_depth(r->png, r->info);
    raw = (uint64_t)info->height * (1 + (bits + 7) / 8);
    if (remaining * 1032 + 4096 >= raw)
        return RAYO_OK;
    return rayo_error_set(&r->error, RAYO_ERR_FORMAT,
                          "%s: byte %llu: found %llu bytes after the header; "
                          "expected at least %llu for the compressed data of "
                          "a %lux%lu PNG",
                          r->src->name,
                          (unsigned long long)rayo_source_offset(r->src),
                          (unsigned long long)remaining,
                          (unsigned long long)((raw - 4096) / 1032),
                          (unsigned long)info->width,
                          (unsigned long)info->height);
}

static unsigned char *row_target(const png_reader *r, uint32_t y, int passes)
{
    if (!r->alpha)
        return rayo_image_row(r->image, y);
    return r->scratch + (passes > 1 ? (size_t)y * r->in_row_bytes : 0);
}

/* After all passes (or each row, when not interlaced): rayo's layout. */
static void finish_row(const png_reader *r, uint32_t y, int passes)
{
    const rayo_image_info *info = &r->image->info;
    unsigned char *row = rayo_image_row(r->image, y);
    if (r->alpha)
        composite_row(r, row_target(r, y, passes), row);
    else if (info->sample == RAYO_SAMPLE_U16)
        native_row16(row, (size_t)info->width * info->channels);
    else if (info->sample == RAYO_SAMPLE_BIT && (info->width & 7))
        row[info->width >> 3] &=
            (unsigned char)(0xFFu << (8 - (info->width & 7)));
}

static void read_rows(png_reader *r, int passes)
{
    uint32_t height = r->image->info.height, y;
    int pass;
    for (pass = 0; pass < passes; pass++) {
        for (y = 0; y < height; y++) {
            png_read_row(r->png, row_target(r, y, passes), NULL);
            if (passes == 1)
                finish_row(r, y, passes);
        }
    }
    if (passes > 1)
        for (y = 0; y < height; y++)
            finish_row(r, y, passes);
}

/* Everything that may longjmp; all state lives in *r. */
static rayo_status read_with_libpng(png_reader *r)
{
    rayo_image_info info;
    int passes;
    if (setjmp(png_jmpbuf(r->png)))
        return r->error.status;
    png_set_read_fn(r->png, r, on_png_read);
    png_set_sig_bytes(r->png, 8);
    png_set_user_limits(r->png, RAYO_MAX_DIMENSION, RAYO_MAX_DIMENSION);
    png_set_chunk_malloc_max(r->png, PNG_CHUNK_MALLOC_MAX);
    png_set_crc_action(r->png, PNG_CRC_ERROR_QUIT, PNG_CRC_ERROR_QUIT);
    png_read_info(r->png, r->info);
    choose_layout(r, &info);
    /* Before png_read_update_info: the file's channels and depth. */
    if (rayo_image_info_check(&info, NULL) == RAYO_OK &&
        check_room(r, &info) != RAYO_OK)
        return r->error.status;
    passes = png_set_interlace_handling(r->png);
    png_read_update_info(r->png, r->info);
    r->in_row_bytes = png_get_rowbytes(r->png, r->info);
    if (allocate(r, &info, passes) != RAYO_OK)
        return r->error.status;
    read_rows(r, passes);
    png_read_end(r->png, NULL);
    return RAYO_OK;
}

rayo_status rayo_png_read(rayo_source *src, rayo_image *image,
                          rayo_error *err)
{
    png_reader r;
    rayo_status status;
    memset(&r, 0, sizeof r);
    r.src = src;
    r.image = image;
    r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &r, on_png_error,
                                   on_png_warning);
    if (r.png != NULL)
        r.info = png_create_info_struct(r.png);
    if (r.png == NULL || r.info == NULL) {
        png_destroy_read_struct(&r.png, &r.info, NULL);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                              src->name);
    }
    status = read_with_libpng(&r);
    png_destroy_read_struct(&r.png, &r.info, NULL);
    free(r.scratch);
    if (status != RAYO_OK) {
        rayo_image_free(image);
        if (err != NULL)
            *err = r.error;
    }
    return status;
}
