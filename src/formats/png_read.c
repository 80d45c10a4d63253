/*
 * png_read.c - reading PNG with libpng into a rayo_image.
 *
 * libpng does the decoding (every colour type and bit depth, palettes,
 * interlacing); this file chooses libpng's transformations so that each
 * decoded row is in one of rayo's three layouts but for alpha (reader.h),
 * puts the row's pixels in place (compositing alpha over white, spreading
 * an interlaced pass's pixels over their columns), and turns libpng's
 * longjmp errors into one rayo_error naming the file and the byte where
 * reading stopped.  Hostile files cost no more than their image (below).
 * Not a writer (png_write.c) and not a colour manager: gamma and ICC
 * chunks are ignored.  Built with RAYO_NO_PNG_READ (the page, whose
 * browser decodes PNG), a PNG is recognised and refused.
 */
#ifdef RAYO_NO_PNG_READ
#include "reader_impl.h"

rayo_status rayo_png_read(rayo_source *src, rayo_image *image,
                          rayo_error *err)
{
    (void)image;
    return rayo_error_set(err, RAYO_ERR_FORMAT,
                          "%s: a PNG, which this build of rayo does not "
                          "read (it was built without libpng's reader, "
                          "RAYO_NO_PNG_READ)",
                          src->name);
}

#else
#include <png.h>
#include <setjmp.h>
#include <stdlib.h>
#include <string.h>

#include "png_chunks.h"
#include "rayo/limits.h"
#include "reader_impl.h"

/*
 * The image is the only full-size buffer: rows are placed from libpng's
 * row buffer as they are decoded (a user transform, the last of libpng's
 * steps), so an interlaced 16-bit RGBA image needs its 6 bytes a pixel,
 * not 8 more for libpng's layout.
 *
 * Hostile files: the IHDR's size is checked against limits.h (libpng's
 * user limits, then rayo_image_info_check) before the image is allocated;
 * every ancillary chunk but tRNS is skipped unread (libpng's unknown-chunk
 * handling: its CRC is checked, nothing is allocated or inflated for it,
 * whatever length it declares); a CRC error in any chunk is an error, and
 * so is a stream that ends before IEND.  Once the last row is decoded,
 * libpng is stopped: the rest of the file up to IEND is read by
 * png_chunks.c, which checks CRCs but inflates nothing, so a zlib bomb
 * after the image costs no more than reading it.
 */

/*
 * Largest chunk libpng may allocate for: with every ancillary chunk but
 * tRNS skipped it allocates for none (PLTE and tRNS have their own, small
 * bounds); this is the cap should that change.
 */
#define PNG_CHUNK_MALLOC_MAX (8u * 1024u * 1024u)

typedef struct png_reader {
    rayo_source *src;
    rayo_image *image;
    png_structp png;
    png_infop info;
    rayo_error error;       /* set before every longjmp but "complete" */
    char warning[128];      /* libpng's last warning: the reason behind
                               "Invalid IHDR data" */
    int alpha;              /* rows carry an alpha sample to composite */
    int interlaced;         /* Adam7: rows come pass by pass */
    unsigned in_channels;   /* samples per pixel in libpng's rows */
    size_t in_row_bytes;    /* libpng's full row after transformations */
    uint64_t rows_left;     /* rows (of all passes) still to decode */
    int complete;           /* every row is in place: libpng must read no
                               more; the next read longjmps */
    rayo_png_chunks chunks; /* where libpng stands in the chunks */
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

/*
 * libpng's input.  Once the image is complete, libpng would go on to
 * inflate whatever compressed data is left (all of it: libpng checks that
 * the stream ends); it is stopped at its first read instead, and
 * png_chunks.c reads the rest.
 */
static void on_png_read(png_structp png, png_bytep data, size_t length)
{
    png_reader *r = png_get_io_ptr(png);
    size_t got;
    if (r->complete)
        png_longjmp(png, 1);
    rayo_source_read(r->src, data, length, &got);
    rayo_png_chunks_see(&r->chunks, data, got);
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
    r->interlaced = png_get_interlace_type(png, r->info) != PNG_INTERLACE_NONE;
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

/* Bytes in a row of libpng's of this many pixels. */
static size_t in_row_bytes(const png_reader *r, uint32_t pixels)
{
    const rayo_image_info *info = &r->image->info;
    if (info->sample == RAYO_SAMPLE_BIT)
        return ((size_t)pixels + 7) / 8;
    return (size_t)pixels * r->in_channels *
           (info->sample == RAYO_SAMPLE_U16 ? 2u : 1u);
}

/* Composites one pixel of (samples..., alpha) over white into out. */
static void composite_pixel(const png_reader *r, const unsigned char *p,
                            unsigned char *out)
{
    const rayo_image_info *info = &r->image->info;
    uint64_t m = info->maxval;
    uint64_t a = m > 255 ? (uint64_t)((p[2 * info->channels] << 8) |
                                      p[2 * info->channels + 1])
                         : p[info->channels];
    unsigned c;
    for (c = 0; c < info->channels; c++) {
        uint64_t v = m > 255 ? (uint64_t)((p[2 * c] << 8) | p[2 * c + 1])
                             : p[c];
        uint64_t mixed = (v * a + m * (m - a) + m / 2) / m;
        if (m > 255) {
            uint16_t s = (uint16_t)mixed;
            memcpy(out + 2 * c, &s, sizeof s);
        } else {
            out[c] = (unsigned char)mixed;
        }
    }
}

/*
 * Puts count decoded pixels in at columns x0, x0 + dx, ...: composited,
 * 16-bit samples from big-endian (libpng's order) to native, bits as they
 * are.
 */
static void put_pixels(const png_reader *r, const unsigned char *in,
                       unsigned char *out, uint32_t count, uint32_t x0,
                       uint32_t dx)
{
    const rayo_image_info *info = &r->image->info;
    size_t sample = info->sample == RAYO_SAMPLE_U16 ? 2 : 1;
    size_t in_pixel = r->in_channels * sample;
    size_t out_pixel = info->channels * sample;
    uint32_t i;
    unsigned c;
    if (info->sample == RAYO_SAMPLE_BIT && dx == 1) {
        memcpy(out, in, in_row_bytes(r, count));
        if (info->width & 7)
            out[info->width >> 3] &=
                (unsigned char)(0xFFu << (8 - (info->width & 7)));
    } else if (info->sample == RAYO_SAMPLE_BIT) {
        for (i = 0; i < count; i++)
            rayo_bit_set(out, x0 + i * dx, rayo_bit_get(in, i));
    } else if (r->alpha) {
        for (i = 0; i < count; i++)
            composite_pixel(r, in + i * in_pixel,
                            out + (size_t)(x0 + i * dx) * out_pixel);
    } else if (sample == 1 && dx == 1) {
        memcpy(out, in, (size_t)count * in_pixel);
    } else {
        for (i = 0; i < count; i++) {
            const unsigned char *p = in + i * in_pixel;
            unsigned char *q = out + (size_t)(x0 + i * dx) * out_pixel;
            if (sample == 1) {
                memcpy(q, p, out_pixel);
                continue;
            }
            for (c = 0; c < info->channels; c++) {
                uint16_t v = (uint16_t)((p[2 * c] << 8) | p[2 * c + 1]);
                memcpy(q + 2 * c, &v, sizeof v);
            }
        }
    }
}

/*
 * libpng's last step on each decoded row (a user transform): the row, in
 * libpng's buffer, goes to its place in the image.  Rows are read with no
 * row of the caller's (png_read_row(png, NULL, NULL)) and, for interlaced
 * images, without libpng's interlace handling, so a row is one pass's
 * pixels of one image row.
 */
static void place_row(png_structp png, png_row_infop row, png_bytep data)
{
    png_reader *r = png_get_io_ptr(png);
    const rayo_image_info *info = &r->image->info;
    int pass = png_get_current_pass_number(png);
    uint32_t y = png_get_current_row_number(png);
    uint32_t count = info->width, x0 = 0, dx = 1;
    if (r->interlaced && pass >= 0 && pass < 7) {
        count = PNG_PASS_COLS(info->width, pass);
        x0 = PNG_PASS_START_COL(pass);
        dx = 1u << PNG_PASS_COL_SHIFT(pass);
        y = PNG_ROW_FROM_PASS_ROW(y, pass);
    }
    if (r->rows_left == 0 || y >= info->height || row->width != count ||
        row->channels != r->in_channels ||
        row->rowbytes != in_row_bytes(r, count)) {
        rayo_error_set(&r->error, RAYO_ERR_FORMAT,
                       "%s: byte %llu: found a row libpng decoded as %lu "
                       "pixels of %u samples; expected %lu of %u",
                       r->src->name,
                       (unsigned long long)rayo_source_offset(r->src),
                       (unsigned long)row->width, (unsigned)row->channels,
                       (unsigned long)count, r->in_channels);
        png_longjmp(png, 1);
    }
    put_pixels(r, data, rayo_image_row(r->image, y), count, x0, dx);
    if (--r->rows_left == 0)
        r->complete = 1;
}

static rayo_status allocate(png_reader *r, const rayo_image_info *info)
{
    rayo_status status = rayo_image_info_check(info, NULL);
    size_t sample_bytes = info->sample == RAYO_SAMPLE_U16 ? 2 : 1;
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

/* Rows libpng decodes: the height, or the rows of Adam7's non-empty
   passes (libpng skips a pass with no pixels). */
static uint64_t rows_to_decode(const png_reader *r,
                               const rayo_image_info *info)
{
    uint64_t rows = 0;
    int pass;
    if (!r->interlaced)
        return info->height;
    for (pass = 0; pass < 7; pass++)
        if (PNG_PASS_COLS(info->width, pass) != 0)
            rows += PNG_PASS_ROWS(info->height, pass);
    return rows;
}

/* Everything that may longjmp; all state lives in *r. */
static rayo_status read_with_libpng(png_reader *r)
{
    rayo_image_info info;
    uint64_t rows, i;
    if (setjmp(png_jmpbuf(r->png))) {
        if (r->error.status != RAYO_OK)
            return r->error.status;
        if (!r->complete)
            return rayo_error_set(&r->error, RAYO_ERR_FORMAT,
                                  "%s: byte %llu: found a PNG libpng "
                                  "stopped reading; expected a well-formed "
                                  "PNG stream",
                                  r->src->name,
                                  (unsigned long long)rayo_source_offset(
                                      r->src));
        return rayo_png_chunks_finish(&r->chunks, r->src, &r->error);
    }
    png_set_read_fn(r->png, r, on_png_read);
    png_set_sig_bytes(r->png, 8);
    png_set_user_limits(r->png, RAYO_MAX_DIMENSION, RAYO_MAX_DIMENSION);
    png_set_chunk_malloc_max(r->png, PNG_CHUNK_MALLOC_MAX);
    /* 1: keep no text, sPLT or unknown chunk (0 would mean no limit). */
    png_set_chunk_cache_max(r->png, 1);
    /* Skip every chunk but IHDR, PLTE, tRNS, IDAT and IEND (-1), and
       every chunk libpng does not know. */
    png_set_keep_unknown_chunks(r->png, PNG_HANDLE_CHUNK_NEVER, NULL, -1);
    png_set_crc_action(r->png, PNG_CRC_ERROR_QUIT, PNG_CRC_ERROR_QUIT);
    png_set_read_user_transform_fn(r->png, place_row);
    png_read_info(r->png, r->info);
    choose_layout(r, &info);
    /* Before png_read_update_info: the file's channels and depth. */
    if (rayo_image_info_check(&info, NULL) == RAYO_OK &&
        check_room(r, &info) != RAYO_OK)
        return r->error.status;
    png_read_update_info(r->png, r->info);
    r->in_row_bytes = png_get_rowbytes(r->png, r->info);
    if (allocate(r, &info) != RAYO_OK)
        return r->error.status;
    rows = r->rows_left = rows_to_decode(r, &info);
    /* The last row's call usually ends in the longjmp above. */
    for (i = 0; i < rows; i++)
        png_read_row(r->png, NULL, NULL);
    if (!r->complete)
        return rayo_error_set(&r->error, RAYO_ERR_FORMAT,
                              "%s: byte %llu: found %llu rows of %llu "
                              "decoded; expected every row",
                              r->src->name,
                              (unsigned long long)rayo_source_offset(r->src),
                              (unsigned long long)(rows - r->rows_left),
                              (unsigned long long)rows);
    r->complete = 1;
    return rayo_png_chunks_finish(&r->chunks, r->src, &r->error);
}

rayo_status rayo_png_read(rayo_source *src, rayo_image *image,
                          rayo_error *err)
{
    png_reader *r;
    rayo_status status;
    /* On the heap: the CRC table makes it 1 KiB more than a frame
       should carry, and setjmp's frame stays small. */
    r = calloc(1, sizeof *r);
    if (r == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                              src->name);
    r->src = src;
    r->image = image;
    rayo_error_init(&r->error, rayo_error_lang(err));
    rayo_png_chunks_init(&r->chunks);
    r->png = png_create_read_struct(PNG_LIBPNG_VER_STRING, r, on_png_error,
                                    on_png_warning);
    if (r->png != NULL)
        r->info = png_create_info_struct(r->png);
    if (r->png == NULL || r->info == NULL) {
        png_destroy_read_struct(&r->png, &r->info, NULL);
        free(r);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "%s: out of memory",
                              src->name);
    }
    status = read_with_libpng(r);
    png_destroy_read_struct(&r->png, &r->info, NULL);
    if (status != RAYO_OK) {
        rayo_image_free(image);
        if (err != NULL)
            *err = r->error;
    }
    free(r);
    return status;
}

#endif /* RAYO_NO_PNG_READ */
