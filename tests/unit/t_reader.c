/*
 * t_reader.c - the image readers against images made independently:
 * Netpbm text written out by hand here (comments, odd whitespace, 16-bit
 * samples, trailing data and what it holds), PNGs written by libpng
 * itself in every colour type, bit depth and interlace method, and the
 * malformed corpus read from memory.  The expected pixels come from the
 * same small functions that made the images, never from rayo's reader.
 *
 * The Netpbm tools' own files are checked by tests/cli/convert.t.
 */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "rayo.h"
#include "tap.h"

/* ---- helpers ---------------------------------------------------------- */

static rayo_status read_text(const char *text, rayo_image *image,
                             rayo_read_report *report, rayo_error *err)
{
    return rayo_image_read_memory(text, strlen(text), "test.pnm", image,
                                  report, err);
}

static unsigned sample(const rayo_image *image, uint32_t x, uint32_t y,
                       unsigned c)
{
    const unsigned char *row = rayo_image_row(image, y);
    size_t i = (size_t)x * image->info.channels + c;
    uint16_t v;
    if (image->info.sample == RAYO_SAMPLE_BIT)
        return (unsigned)rayo_bit_get(row, x);
    if (image->info.sample == RAYO_SAMPLE_U8)
        return row[i];
    memcpy(&v, row + 2 * i, sizeof v);
    return v;
}

/* A byte buffer libpng writes into. */
typedef struct buffer {
    unsigned char *data;
    size_t size, capacity;
} buffer;

static void buffer_write(png_structp png, png_bytep data, size_t length)
{
    buffer *b = png_get_io_ptr(png);
    if (b->size + length > b->capacity) {
        size_t capacity = (b->size + length) * 2;
        unsigned char *grown = realloc(b->data, capacity);
        if (grown == NULL)
            png_error(png, "out of memory");
        b->data = grown;
        b->capacity = capacity;
    }
    memcpy(b->data + b->size, data, length);
    b->size += length;
}

static void buffer_flush(png_structp png)
{
    (void)png;
}

/* The test pattern: sample c of pixel (x, y), 0..maxval. */
static unsigned pattern(uint32_t x, uint32_t y, unsigned c, unsigned maxval)
{
    return (unsigned)((x * 7u + y * 13u + c * 5u + x * y * 3u) %
                      (maxval + 1u));
}

static unsigned pattern16(uint32_t x, uint32_t y, unsigned c)
{
    return (unsigned)((x * 2731u + y * 9973u + c * 4099u + x * y * 17u) %
                      65536u);
}

/* Palette entry i: an arbitrary but distinct colour. */
static void palette_colour(unsigned i, unsigned rgb[3])
{
    rgb[0] = (i * 37u + 11u) % 256u;
    rgb[1] = (i * 91u + 7u) % 256u;
    rgb[2] = 255u - i;
}

typedef struct png_case {
    int colour_type, depth, interlace;
    int trns; /* gray: transparent value 0; palette: entry alpha */
} png_case;

static unsigned channels_of(int colour_type)
{
    switch (colour_type) {
    case PNG_COLOR_TYPE_GRAY:
    case PNG_COLOR_TYPE_PALETTE:
        return 1;
    case PNG_COLOR_TYPE_GRAY_ALPHA:
        return 2;
    case PNG_COLOR_TYPE_RGB:
        return 3;
    default:
        return 4;
    }
}

/* The stored sample c of pixel (x, y) in the PNG written for pc. */
static unsigned stored(const png_case *pc, uint32_t x, uint32_t y,
                       unsigned c)
{
    if (pc->depth == 16)
        return pattern16(x, y, c);
    return pattern(x, y, c, (1u << pc->depth) - 1);
}

/* Packs row y of pc's samples the way PNG stores them. */
static void pack_row(const png_case *pc, uint32_t width, uint32_t y,
                     unsigned char *row)
{
    unsigned n = channels_of(pc->colour_type), c;
    uint32_t x;
    size_t bits = 0;
    memset(row, 0, ((size_t)width * n * (size_t)pc->depth + 7) / 8);
    for (x = 0; x < width; x++) {
        for (c = 0; c < n; c++) {
            unsigned v = stored(pc, x, y, c);
            if (pc->depth == 16) {
                row[bits / 8] = (unsigned char)(v >> 8);
                row[bits / 8 + 1] = (unsigned char)(v & 255);
            } else if (pc->depth == 8) {
                row[bits / 8] = (unsigned char)v;
            } else {
                row[bits / 8] |= (unsigned char)(v << (8 - pc->depth -
                                                       bits % 8));
            }
            bits += (size_t)pc->depth;
        }
    }
}

static int write_png(const png_case *pc, uint32_t width, uint32_t height,
                     buffer *out)
{
    png_structp png;
    png_infop info;
    unsigned char *row;
    int passes, pass;
    uint32_t y;
    memset(out, 0, sizeof *out);
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    info = png_create_info_struct(png);
    row = malloc((size_t)width * 8 + 8);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        free(row);
        return 0;
    }
    png_set_write_fn(png, out, buffer_write, buffer_flush);
    png_set_IHDR(png, info, width, height, pc->depth, pc->colour_type,
                 pc->interlace, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (pc->colour_type == PNG_COLOR_TYPE_PALETTE) {
        png_color colours[256];
        png_byte alpha[256];
        unsigned i, n = 1u << pc->depth;
        for (i = 0; i < n; i++) {
            unsigned rgb[3];
            palette_colour(i, rgb);
            colours[i].red = (png_byte)rgb[0];
            colours[i].green = (png_byte)rgb[1];
            colours[i].blue = (png_byte)rgb[2];
            alpha[i] = (png_byte)(i * 255u / (n - 1));
        }
        png_set_PLTE(png, info, colours, (int)n);
        if (pc->trns)
            png_set_tRNS(png, info, alpha, (int)n, NULL);
    } else if (pc->trns) {
        png_color_16 value;
        memset(&value, 0, sizeof value);
        png_set_tRNS(png, info, NULL, 0, &value);
    }
    png_write_info(png, info);
    passes = png_set_interlace_handling(png);
    for (pass = 0; pass < passes; pass++) {
        for (y = 0; y < height; y++) {
            pack_row(pc, width, y, row);
            png_write_row(png, row);
        }
    }
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    free(row);
    return 1;
}

/* v composited over white: round((v a + M (M - a)) / M), in doubles. */
static unsigned over_white(unsigned v, unsigned a, unsigned maxval)
{
    double m = maxval;
    double mixed = ((double)v * a + m * (m - a)) / m;
    return (unsigned)(mixed + 0.5);
}

/* What rayo should hold for pixel (x, y), channel c. */
static unsigned expected(const png_case *pc, uint32_t x, uint32_t y,
                         unsigned c)
{
    unsigned maxval = pc->depth == 16 ? 65535u : 255u;
    if (pc->colour_type == PNG_COLOR_TYPE_PALETTE) {
        unsigned rgb[3], index = stored(pc, x, y, 0), n = 1u << pc->depth;
        palette_colour(index, rgb);
        if (!pc->trns)
            return rgb[c];
        return over_white(rgb[c], index * 255u / (n - 1), 255);
    }
    if (pc->colour_type == PNG_COLOR_TYPE_GRAY) {
        unsigned v = stored(pc, x, y, 0);
        if (pc->depth == 1 && !pc->trns)
            return v == 0; /* bit set = black = PNG 0 */
        if (!pc->trns)
            return v;
        if (pc->depth < 8) /* expanded to 8 bits by scaling */
            v = v * 255u / ((1u << pc->depth) - 1);
        return v == 0 ? maxval : v;
    }
    if (pc->colour_type == PNG_COLOR_TYPE_RGB)
        return stored(pc, x, y, c);
    {
        unsigned alpha_channel = channels_of(pc->colour_type) - 1;
        return over_white(stored(pc, x, y, c),
                          stored(pc, x, y, alpha_channel), maxval);
    }
}

static void expect_layout(const png_case *pc, rayo_image_info *info)
{
    int colour = pc->colour_type & PNG_COLOR_MASK_COLOR;
    info->channels = colour ? 3 : 1;
    info->sample = pc->depth == 16 ? RAYO_SAMPLE_U16 : RAYO_SAMPLE_U8;
    info->maxval = pc->depth == 16 ? 65535u : 255u;
    if (pc->colour_type == PNG_COLOR_TYPE_GRAY && !pc->trns &&
        pc->depth < 8) {
        info->maxval = (1u << pc->depth) - 1;
        if (pc->depth == 1)
            info->sample = RAYO_SAMPLE_BIT;
    }
}

static void check_png_case(const png_case *pc, uint32_t width,
                           uint32_t height)
{
    char name[128];
    buffer png;
    rayo_image image;
    rayo_image_info want;
    rayo_read_report report;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    uint32_t x, y;
    unsigned c, mismatches = 0;
    snprintf(name, sizeof name, "PNG type %d depth %d%s%s %lux%lu",
             pc->colour_type, pc->depth, pc->interlace ? " interlaced" : "",
             pc->trns ? " tRNS" : "", (unsigned long)width,
             (unsigned long)height);
    if (!write_png(pc, width, height, &png)) {
        ok(0, "%s: libpng wrote it", name);
        return;
    }
    status = rayo_image_read_memory(png.data, png.size, name, &image,
                                    &report, &err);
    free(png.data);
    is_int(status, RAYO_OK, "%s: read", name);
    if (status != RAYO_OK) {
        printf("#   %s\n", err.message);
        return;
    }
    expect_layout(pc, &want);
    is_int(report.format, RAYO_FORMAT_PNG, "%s: format from the signature",
           name);
    ok(image.info.width == width && image.info.height == height &&
           image.info.channels == want.channels &&
           image.info.sample == want.sample &&
           image.info.maxval == want.maxval,
       "%s: layout (got %u channels, sample %d, maxval %u)", name,
       image.info.channels, (int)image.info.sample, image.info.maxval);
    if (image.info.channels == want.channels &&
        image.info.sample == want.sample)
        for (y = 0; y < height; y++)
            for (x = 0; x < width; x++)
                for (c = 0; c < want.channels; c++)
                    if (sample(&image, x, y, c) != expected(pc, x, y, c))
                        mismatches++;
    is_int(mismatches, 0, "%s: every sample as written", name);
    rayo_image_free(&image);
}

/* ---- PNG -------------------------------------------------------------- */

static void test_png_every_type(void)
{
    static const png_case cases[] = {
        {PNG_COLOR_TYPE_GRAY, 1, 0, 0},       {PNG_COLOR_TYPE_GRAY, 2, 0, 0},
        {PNG_COLOR_TYPE_GRAY, 4, 0, 0},       {PNG_COLOR_TYPE_GRAY, 8, 0, 0},
        {PNG_COLOR_TYPE_GRAY, 16, 0, 0},      {PNG_COLOR_TYPE_RGB, 8, 0, 0},
        {PNG_COLOR_TYPE_RGB, 16, 0, 0},       {PNG_COLOR_TYPE_PALETTE, 1, 0, 0},
        {PNG_COLOR_TYPE_PALETTE, 2, 0, 0},    {PNG_COLOR_TYPE_PALETTE, 4, 0, 0},
        {PNG_COLOR_TYPE_PALETTE, 8, 0, 0},    {PNG_COLOR_TYPE_GRAY_ALPHA, 8, 0, 0},
        {PNG_COLOR_TYPE_GRAY_ALPHA, 16, 0, 0}, {PNG_COLOR_TYPE_RGBA, 8, 0, 0},
        {PNG_COLOR_TYPE_RGBA, 16, 0, 0},      {PNG_COLOR_TYPE_PALETTE, 4, 0, 1},
        {PNG_COLOR_TYPE_GRAY, 8, 0, 1},       {PNG_COLOR_TYPE_GRAY, 2, 0, 1},
        {PNG_COLOR_TYPE_GRAY, 16, 0, 1},
    };
    /* Adam7's passes are placed one by one: sizes where some are empty
       or end part-way (1x1 has only the first). */
    static const uint32_t small[][2] = {{1, 1}, {2, 1}, {3, 5}, {9, 9}};
    size_t i, k;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        png_case pc = cases[i];
        check_png_case(&pc, 13, 11);
        pc.interlace = PNG_INTERLACE_ADAM7;
        check_png_case(&pc, 13, 11);
        for (k = 0; k < sizeof small / sizeof small[0]; k++)
            check_png_case(&pc, small[k][0], small[k][1]);
    }
}

/* ---- Netpbm ----------------------------------------------------------- */

static void test_plain_pbm(void)
{
    rayo_image image;
    rayo_read_report report;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    /* Comments everywhere, tabs, CR, VT, FF, pixels with and without
       spaces between them, a comment inside the raster. */
    const char *text = "P1#magic\n# a comment\n\t11\r\n#between\n\v2\f"
                       "\n1 0 1 1 0 0 0 1 1 0 1\n0111#in the raster\n"
                       "1110001\n\n";
    rayo_status status = read_text(text, &image, &report, &err);
    is_int(status, RAYO_OK, "plain PBM with comments and odd whitespace");
    if (status != RAYO_OK) {
        printf("#   %s\n", err.message);
        return;
    }
    is_int(report.format, RAYO_FORMAT_PBM, "P1 is PBM");
    is_int(report.plain, 1, "P1 is plain");
    is_int(report.trailing_bytes, 0, "final newlines are not trailing data");
    is_int(image.info.width, 11, "width 11");
    is_int(image.info.height, 2, "height 2");
    is_int(image.info.sample, RAYO_SAMPLE_BIT, "bilevel layout");
    /* 1011 0001 101(0 0000) ; 0111 1110 001(0 0000) */
    is_int(rayo_image_row(&image, 0)[0], 0xB1, "row 0 byte 0");
    is_int(rayo_image_row(&image, 0)[1], 0xA0, "row 0 byte 1, padding clear");
    is_int(rayo_image_row(&image, 1)[0], 0x7E, "row 1 byte 0");
    is_int(rayo_image_row(&image, 1)[1], 0x20, "row 1 byte 1, padding clear");
    rayo_image_free(&image);
}

static void test_raw_pbm_padding(void)
{
    static const unsigned char data[] = {'P', '4', '\n', '1', '0', ' ',
                                         '2', '\n', 0xC3, 0xFF, 0x0F, 0x7F,
                                         'x', 'y'};
    rayo_image image;
    rayo_read_report report;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status = rayo_image_read_memory(data, sizeof data, "p4",
                                                &image, &report, &err);
    is_int(status, RAYO_OK, "raw PBM 10x2");
    if (status != RAYO_OK)
        return;
    is_int(report.plain, 0, "P4 is raw");
    is_int(rayo_image_row(&image, 0)[1], 0xC0, "padding bits cleared");
    is_int(rayo_image_row(&image, 1)[0], 0x0F, "second row kept");
    is_int(rayo_image_row(&image, 1)[1], 0x40, "second row padding cleared");
    is_int(report.trailing_bytes, 2, "two trailing bytes reported");
    is_int(report.trailing_samples, 10, "a whole 10-pixel row more");
    is_int(report.trailing_data, 2, "two bytes of data");
    rayo_image_free(&image);
}

static void test_gray_and_colour(void)
{
    rayo_image image;
    rayo_read_report report;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    static const unsigned char p5[] = {'P', '5', ' ', '2', ' ', '1', ' ',
                                       '1', '0', '0', '0', '\n', 0x03,
                                       0xE8, 0x01, 0x02, '\n'};
    static const unsigned char p6[] = "P6 2 1 7\n\x01\x02\x03\x04\x05\x06";
    rayo_status status =
        read_text("P2\n3 1\n1000\n0 999\n1000\n", &image, &report, &err);
    is_int(status, RAYO_OK, "plain PGM, maxval 1000");
    if (status == RAYO_OK) {
        is_int(image.info.sample, RAYO_SAMPLE_U16, "maxval 1000 is 16-bit");
        is_int(image.info.maxval, 1000, "maxval kept");
        is_int(sample(&image, 1, 0, 0), 999, "sample 999");
        is_int(sample(&image, 2, 0, 0), 1000, "sample 1000");
        rayo_image_free(&image);
    }
    status = rayo_image_read_memory(p5, sizeof p5, "p5", &image, &report,
                                    &err);
    is_int(status, RAYO_OK, "raw PGM with 16-bit samples");
    if (status == RAYO_OK) {
        is_int(sample(&image, 0, 0, 0), 1000, "big-endian 0x03E8 is 1000");
        is_int(sample(&image, 1, 0, 0), 258, "big-endian 0x0102 is 258");
        is_int(report.trailing_bytes, 1, "a newline after a raw raster is "
                                         "trailing data");
        is_int(report.trailing_samples, 0, "but no sample");
        is_int(report.trailing_data, 0, "and whitespace, not data");
        rayo_image_free(&image);
    }
    status = rayo_image_read_memory(p6, sizeof p6 - 1, "p6", &image, &report,
                                    &err);
    is_int(status, RAYO_OK, "raw PPM, maxval 7");
    if (status == RAYO_OK) {
        is_int(report.format, RAYO_FORMAT_PPM, "P6 is PPM");
        is_int(image.info.channels, 3, "three channels");
        is_int(sample(&image, 1, 0, 2), 6, "last sample");
        rayo_image_free(&image);
    }
    status = read_text("P3 1 2 65535 65535 0 1 2 3 4 P1 1 1 0\n", &image,
                       &report, &err);
    is_int(status, RAYO_OK, "plain PPM, 16-bit, followed by another image");
    if (status == RAYO_OK) {
        is_int(sample(&image, 0, 0, 0), 65535, "65535 kept");
        is_int(sample(&image, 0, 1, 2), 4, "last sample");
        is_int(report.trailing_bytes, 9, "the second image is trailing");
        rayo_image_free(&image);
    }
}

/* ---- what follows a Netpbm raster ------------------------------------ */

/* A plain PBM of width x rows whose header says height: each row of
   width digits without spaces, then a newline. */
static char *plain_pbm_rows(unsigned width, unsigned height, unsigned rows)
{
    size_t size = 32 + (size_t)rows * (width + 1), n;
    char *text = malloc(size);
    unsigned x, y;
    if (text == NULL)
        return NULL;
    n = (size_t)snprintf(text, size, "P1\n%u %u\n", width, height);
    for (y = 0; y < rows; y++) {
        for (x = 0; x < width; x++)
            text[n++] = (char)('0' + ((x ^ y) & 1));
        text[n++] = '\n';
    }
    text[n] = '\0';
    return text;
}

static void test_trailing_samples(void)
{
    rayo_image image;
    rayo_read_report report;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status;
    char path[] = "/tmp/t_reader.XXXXXX";
    char *text = plain_pbm_rows(640, 480, 481);
    const char *tail = "4 5 6 # c 7\n 8x 9";
    char pgm[64];
    FILE *f;
    int fd;
    static const unsigned char p5_row[] = {'P', '5', ' ', '4', ' ', '2', ' ',
                                           '2', '5', '5', '\n', 1, 2, 3, 4,
                                           5, 6, 7, 8, 0x00, 0xFF, 0x80,
                                           'A'};
    static const unsigned char p5_16[] = {'P', '5', ' ', '1', ' ', '1', ' ',
                                          '1', '0', '0', '0', '\n', 0x03,
                                          0xE8, 0x00, 0x01, 0x00, 0x02};
    static const unsigned char p4_row[] = {'P', '4', ' ', '1', '0', ' ',
                                           '1', '\n', 0xFF, 0xC0, 0x12,
                                           0x34, 0x56};
    static const unsigned char p6_more[] = "P6 1 1 255\n\x01\x02\x03"
                                           "\nP6 1 1 255\n\x04\x05\x06";

    /* The assignment's mistake: a 481st row in a 640x480 plain PBM, read
       from memory and from a regular file (whose tail the reader has to
       read, not just measure). */
    if (text == NULL) {
        ok(0, "out of memory for a test image");
        return;
    }
    status = read_text(text, &image, &report, &err);
    is_int(status, RAYO_OK, "640x480 plain PBM with 481 rows: read");
    if (status == RAYO_OK) {
        is_int(image.info.height, 480, "the header's 480 rows kept");
        is_int(report.trailing_samples, 640, "one row of 640 samples more");
        is_int(report.trailing_data, 640, "640 bytes of trailing data");
        is_int(report.trailing_bytes, 641, "the row and its newline");
        rayo_image_free(&image);
    }
    fd = mkstemp(path);
    f = fd >= 0 ? fdopen(fd, "w") : NULL;
    ok(f != NULL && fputs(text, f) >= 0 && fclose(f) == 0,
       "the 481-row PBM written to a file");
    status = rayo_image_read_file(path, &image, &report, &err);
    is_int(status, RAYO_OK, "read back from the file");
    if (status == RAYO_OK) {
        is_int(report.trailing_samples, 640, "file: 640 samples more");
        is_int(report.trailing_bytes, 641, "file: 641 trailing bytes");
        rayo_image_free(&image);
    }
    status = rayo_image_read_file(path, &image, NULL, &err);
    is_int(status, RAYO_OK, "read with no report: still accepted");
    if (status == RAYO_OK)
        rayo_image_free(&image);
    remove(path);
    free(text);

    text = plain_pbm_rows(7, 3, 3);
    if (text == NULL) {
        ok(0, "out of memory for a test image");
        return;
    }
    status = read_text(text, &image, &report, &err);
    is_int(status, RAYO_OK, "an exact plain PBM");
    if (status == RAYO_OK) {
        is_int(report.trailing_samples, 0, "exact: no sample more");
        is_int(report.trailing_data, 0, "exact: no trailing data");
        is_int(report.trailing_bytes, 0, "exact: no trailing byte");
        rayo_image_free(&image);
    }
    free(text);

    /* Plain PGM: samples up to the first thing that is not one; comments
       and whitespace are not data. */
    snprintf(pgm, sizeof pgm, "P2 3 1 255\n1 2 3\n%s", tail);
    status = read_text(pgm, &image, &report, &err);
    is_int(status, RAYO_OK, "plain PGM with a tail of samples and garbage");
    if (status == RAYO_OK) {
        is_int(report.trailing_samples, 3, "4 5 6 counted; 8x stops");
        is_int(report.trailing_data, 6, "4 5 6 8 x 9: six bytes of data");
        is_int(report.trailing_bytes, strlen(tail), "the whole tail");
        rayo_image_free(&image);
    }
    status = read_text("P2 2 1 9\n1 2\n300 4", &image, &report, &err);
    is_int(status, RAYO_OK, "plain PGM, samples over maxval after it");
    if (status == RAYO_OK) {
        is_int(report.trailing_samples, 2, "counted whatever their value");
        rayo_image_free(&image);
    }
    status = read_text("P3 1 1 255 1 2 3\n# only a comment\n\n", &image,
                       &report, &err);
    is_int(status, RAYO_OK, "plain PPM ending in a comment");
    if (status == RAYO_OK) {
        is_int(report.trailing_samples, 0, "a final comment: no sample");
        is_int(report.trailing_data, 0, "a final comment: no data");
        rayo_image_free(&image);
    }
    status = read_text("P3 1 2 65535 65535 0 1 2 3 4 P1 1 1 0\n", &image,
                       &report, &err);
    is_int(status, RAYO_OK, "plain PPM followed by another image");
    if (status == RAYO_OK) {
        is_int(report.trailing_samples, 0, "another image: no sample");
        is_int(report.trailing_data, 5, "P1 1 1 0: five bytes of data");
        rayo_image_free(&image);
    }

    /* Raw. */
    status = rayo_image_read_memory(p5_row, sizeof p5_row, "p5", &image,
                                    &report, &err);
    is_int(status, RAYO_OK, "raw PGM 4x2 with a third row");
    if (status == RAYO_OK) {
        is_int(report.trailing_samples, 4, "raw: a row of 4 samples more");
        is_int(report.trailing_data, 4, "raw: 4 bytes of data");
        is_int(report.trailing_bytes, 4, "raw: 4 trailing bytes");
        rayo_image_free(&image);
    }
    status = rayo_image_read_memory(p5_row, sizeof p5_row - 4, "p5", &image,
                                    &report, &err);
    is_int(status, RAYO_OK, "raw PGM 4x2, exact");
    if (status == RAYO_OK) {
        is_int(report.trailing_samples + report.trailing_data +
                   report.trailing_bytes,
               0, "raw, exact: nothing after");
        rayo_image_free(&image);
    }
    status = rayo_image_read_memory(p5_16, sizeof p5_16, "p5", &image,
                                    &report, &err);
    is_int(status, RAYO_OK, "raw 16-bit PGM with 4 bytes more");
    if (status == RAYO_OK) {
        is_int(report.trailing_samples, 2, "16-bit: two samples more");
        rayo_image_free(&image);
    }
    status = rayo_image_read_memory(p4_row, sizeof p4_row, "p4", &image,
                                    &report, &err);
    is_int(status, RAYO_OK, "raw PBM 10x1 with 3 bytes more");
    if (status == RAYO_OK) {
        /* a 2-byte row of 10 pixels, then 1 byte: 8 more */
        is_int(report.trailing_samples, 18, "P4: a row of 10, then 8");
        rayo_image_free(&image);
    }
    status = rayo_image_read_memory(p6_more, sizeof p6_more - 1, "p6",
                                    &image, &report, &err);
    is_int(status, RAYO_OK, "raw PPM followed by a newline and an image");
    if (status == RAYO_OK) {
        is_int(report.trailing_samples, 0, "a second raw image: no sample");
        /* "P6", "1", "1", "255" and three sample bytes */
        is_int(report.trailing_data, 10, "its 10 non-space bytes are data");
        rayo_image_free(&image);
    }
}

static void test_errors(void)
{
    static const struct {
        const char *text;
        rayo_status status;
        const char *message;
    } cases[] = {
        {"P1\n2 2\n0 1\n1 2\n", RAYO_ERR_FORMAT,
         "test.pnm: byte 13 (line 4): found '2'; expected 0 or 1"},
        {"P2\n1 1\n255\n256\n", RAYO_ERR_FORMAT,
         "test.pnm: byte 14 (line 4): found sample 256; expected 0 to "
         "maxval 255"},
        {"P1\n70000 1\n0\n", RAYO_ERR_LIMIT,
         "test.pnm: byte 3 (line 2): found width 70000"},
        {"P5\n4 4\n255\n\x01\x02", RAYO_ERR_FORMAT,
         "test.pnm: byte 11: found 2 bytes of raster; expected 16"},
        {"P6\n1 1\n0\n", RAYO_ERR_FORMAT, "found maxval 0"},
        {"GIF89a", RAYO_ERR_FORMAT, "test.pnm: byte 0: found \"GI\""},
    };
    size_t i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        rayo_image image;
        rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
        rayo_status status = read_text(cases[i].text, &image, NULL, &err);
        is_int(status, cases[i].status, "error case %lu: status",
               (unsigned long)i);
        ok(status != RAYO_OK && strstr(err.message, cases[i].message),
           "error case %lu: message names the place", (unsigned long)i);
        if (status != RAYO_OK && !strstr(err.message, cases[i].message))
            printf("#   got: %s\n#   want: %s\n", err.message,
                   cases[i].message);
        ok(image.pixels == NULL, "error case %lu: nothing left allocated",
           (unsigned long)i);
    }
}

static void test_empty_memory(void)
{
    rayo_image image;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status =
        rayo_image_read_memory(NULL, 0, "nothing", &image, NULL, &err);
    is_int(status, RAYO_ERR_FORMAT, "NULL, 0 is an empty input");
    ok(status != RAYO_OK && strstr(err.message, "nothing: byte 0: found an "
                                                "empty file") != NULL,
       "empty input: named, at byte 0");
    ok(image.pixels == NULL, "empty input: nothing allocated");
}

/* Reads a whole (small) file; returns its size, or 0. */
static size_t slurp(const char *path, unsigned char *data, size_t capacity)
{
    FILE *f = fopen(path, "rb");
    size_t size;
    if (f == NULL)
        return 0;
    size = fread(data, 1, capacity, f);
    fclose(f);
    return size;
}

/* Every file of the corpus, through the memory path this time. */
static void test_corpus_from_memory(void)
{
    const char *root = getenv("RAYO_SOURCE");
    char folder[1024];
    DIR *dir;
    struct dirent *entry;
    unsigned count = 0, refused = 0;
    snprintf(folder, sizeof folder, "%s/tests/data/malformed",
             root ? root : ".");
    dir = opendir(folder);
    if (dir == NULL) {
        ok(0, "opening the corpus tests/data/malformed");
        return;
    }
    while ((entry = readdir(dir)) != NULL) {
        char full[2048];
        unsigned char data[4096];
        const char *name = entry->d_name;
        size_t size;
        rayo_image image;
        rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
        rayo_status status;
        if (name[0] == '.' || strstr(name, ".py"))
            continue;
        snprintf(full, sizeof full, "%s/%s", folder, name);
        size = slurp(full, data, sizeof data);
        count++;
        status = rayo_image_read_memory(data, size, name, &image, NULL, &err);
        if ((status == RAYO_ERR_FORMAT || status == RAYO_ERR_LIMIT) &&
            image.pixels == NULL &&
            strncmp(err.message, name, strlen(name)) == 0)
            refused++;
        else
            printf("# %s: status %d: %s\n", name, (int)status,
                   status ? err.message : "");
    }
    closedir(dir);
    ok(count >= 30, "corpus has at least 30 files (%u)", count);
    is_int(refused, count, "every corpus file is refused from memory, "
                           "named, nothing allocated");
}

/* rayo_read_options.clamp: plain samples out of range taken into range
   and counted; without it the same file is refused. */
static void test_clamp(void)
{
    static const char text[] = "P2\n4 2\n255\n260 -3 7 255\n"
                               "0 300 -12 1\n";
    char path[] = "/tmp/rayo-t-reader-XXXXXX";
    rayo_read_options o;
    rayo_read_report rp;
    rayo_image image;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    int fd = mkstemp(path);
    ok(fd >= 0 && write(fd, text, sizeof text - 1) == (ssize_t)(sizeof text - 1),
       "clamp: a P2 with 260, -3, 300 and -12 written");
    if (fd >= 0)
        close(fd);
    is_int(rayo_image_read_file(path, &image, NULL, &err), RAYO_ERR_FORMAT,
           "clamp: refused without the option");
    memset(&o, 0, sizeof o);
    o.clamp = 1;
    is_int(rayo_image_read_file_with(path, &o, &image, &rp, &err), RAYO_OK,
           "clamp: read with it");
    if (image.pixels != NULL) {
        const unsigned char *r0 = rayo_image_row(&image, 0);
        const unsigned char *r1 = rayo_image_row(&image, 1);
        is_int(r0[0] * 1000000 + r0[1] * 1000 + r0[2], 255000007,
               "clamp: 260 -> 255, -3 -> 0, 7 kept");
        is_int(r1[1] * 1000 + r1[2], 255000, "clamp: 300 -> 255, -12 -> 0");
    }
    is_int(rp.clamped_high * 10 + rp.clamped_low, 22,
           "clamp: two above maxval, two negative");
    is_int(rp.first_high_line * 10 + rp.first_low_line, 44,
           "clamp: the first of each on line 4");
    is_int(rp.largest_found, 300, "clamp: the largest found, 300");
    is_int(rp.smallest_found, -12, "clamp: the smallest found, -12");
    rayo_image_free(&image);
    unlink(path);
}

int main(void)
{
    test_clamp();
    test_plain_pbm();
    test_raw_pbm_padding();
    test_gray_and_colour();
    test_trailing_samples();
    test_errors();
    test_empty_memory();
    test_png_every_type();
    test_corpus_from_memory();
    return tap_done();
}
