/*
 * pnm_write.c - writing PBM, PGM and PPM, plain (P1-P3) and raw (P4-P6),
 * exactly as the Netpbm format pages describe them.
 *
 * The header is "Pn\nWIDTH HEIGHT\n" followed, for PGM and PPM, by
 * "MAXVAL\n".  Plain rasters put each row on lines of at most 70
 * characters (PBM digits unseparated, as Netpbm's own tools write them;
 * PGM and PPM samples separated by spaces).  Raw PBM rows are packed bits
 * with the padding bits of the last byte zero; raw samples are bytes, or
 * two bytes big-endian when maxval > 255.  Rows go to the output with as
 * few copies as they allow (below).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../io/output_reserve.h"
#include "pbm_plain.h"
#include "writer_impl.h"

/*
 * Each row is formatted straight into the output's buffer
 * (rayo_output_reserve), or into a scratch buffer when a row is larger
 * than that; plain PBM rows come from pbm_plain.c, as bits or, from
 * render.c, as runs (writer_runs.h).  Raw rows that need no change
 * (bytes, or bits whose padding is already zero) go to the output
 * straight from the caller's memory, a whole block of rows in one call;
 * long stretches of white plain PBM rows given as runs go to it by
 * reference to the formatter's white rows.
 */

#define PLAIN_LINE_MAX 70

typedef struct pnm_state {
    unsigned char *scratch;
    size_t scratch_size;
    rayo_pbm_plain *plain_bits; /* plain PBM only */
} pnm_state;

static int magic_number(const rayo_writer *writer)
{
    int base = writer->options.format == RAYO_FORMAT_PBM   ? 1
               : writer->options.format == RAYO_FORMAT_PGM ? 2
                                                           : 3;
    return writer->options.plain ? base : base + 3;
}

static rayo_status check_layout(const rayo_writer *writer, rayo_error *err)
{
    const rayo_image_info *info = &writer->info;
    const char *name = rayo_format_name(writer->options.format);
    switch (writer->options.format) {
    case RAYO_FORMAT_PBM:
        if (info->sample == RAYO_SAMPLE_BIT)
            return RAYO_OK;
        break;
    case RAYO_FORMAT_PGM:
        if (info->sample != RAYO_SAMPLE_BIT && info->channels == 1)
            return RAYO_OK;
        break;
    case RAYO_FORMAT_PPM:
        if (info->sample != RAYO_SAMPLE_BIT && info->channels == 3)
            return RAYO_OK;
        break;
    case RAYO_FORMAT_PNG:
    case RAYO_FORMAT_BMP:
    case RAYO_FORMAT_JPEG:
        break;
    }
    return rayo_error_set(err, RAYO_ERR_INVALID,
                          "%s: a %s file cannot hold a %s image",
                          rayo_output_name(writer->out), name,
                          info->sample == RAYO_SAMPLE_BIT ? "bilevel"
                          : info->channels == 1           ? "gray"
                                                          : "colour");
}

/* Largest formatted row, including line breaks. */
static size_t scratch_bytes(const rayo_writer *writer)
{
    const rayo_image_info *info = &writer->info;
    size_t samples = (size_t)info->width * info->channels;
    if (!writer->options.plain)
        return rayo_image_info_row_bytes(info);
    if (info->sample == RAYO_SAMPLE_BIT)
        return rayo_pbm_plain_row_size(info->width);
    /* "65535 " per sample, and a newline at worst every 11 samples. */
    return samples * 6 + samples / 11 + 2;
}

static rayo_status pnm_open(rayo_writer *writer, rayo_error *err)
{
    char header[64];
    int length;
    pnm_state *state;
    rayo_status status = check_layout(writer, err);
    if (status != RAYO_OK)
        return status;
    state = malloc(sizeof *state);
    if (state == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    state->scratch_size = scratch_bytes(writer);
    state->scratch = malloc(state->scratch_size);
    state->plain_bits = writer->options.plain &&
                                writer->info.sample == RAYO_SAMPLE_BIT
                            ? rayo_pbm_plain_new(writer->info.width)
                            : NULL;
    if (state->scratch == NULL ||
        (state->plain_bits == NULL && writer->options.plain &&
         writer->info.sample == RAYO_SAMPLE_BIT)) {
        free(state->scratch);
        free(state);
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    }
    writer->state = state;
    writer->takes_runs = state->plain_bits != NULL;
    if (writer->options.format == RAYO_FORMAT_PBM)
        length = snprintf(header, sizeof header, "P%d\n%lu %lu\n",
                          magic_number(writer),
                          (unsigned long)writer->info.width,
                          (unsigned long)writer->info.height);
    else
        length = snprintf(header, sizeof header, "P%d\n%lu %lu\n%u\n",
                          magic_number(writer),
                          (unsigned long)writer->info.width,
                          (unsigned long)writer->info.height,
                          writer->info.maxval);
    status = rayo_output_write(writer->out, header, (size_t)length, err);
    if (status != RAYO_OK) {
        free(state->scratch);
        rayo_pbm_plain_free(state->plain_bits);
        free(state);
    }
    return status;
}

static unsigned sample_at(const rayo_image_info *info,
                          const unsigned char *row, size_t i)
{
    if (info->sample == RAYO_SAMPLE_U8)
        return row[i];
    {
        uint16_t v;
        memcpy(&v, row + 2 * i, 2);
        return v;
    }
}

static size_t format_plain_samples(const rayo_writer *writer,
                                   const unsigned char *row,
                                   unsigned char *out)
{
    size_t samples = (size_t)writer->info.width * writer->info.channels;
    size_t n = 0, line = 0, i;
    for (i = 0; i < samples; i++) {
        char digits[8];
        int length = snprintf(digits, sizeof digits, "%u",
                              sample_at(&writer->info, row, i));
        if (line > 0 && line + 1 + (size_t)length > PLAIN_LINE_MAX) {
            out[n++] = '\n';
            line = 0;
        } else if (line > 0) {
            out[n++] = ' ';
            line++;
        }
        memcpy(out + n, digits, (size_t)length);
        n += (size_t)length;
        line += (size_t)length;
    }
    out[n++] = '\n';
    return n;
}

static size_t format_raw(const rayo_writer *writer, const unsigned char *row,
                         unsigned char *out)
{
    const rayo_image_info *info = &writer->info;
    size_t bytes = rayo_image_info_row_bytes(info);
    if (info->sample == RAYO_SAMPLE_BIT) {
        memcpy(out, row, bytes);
        if (info->width % 8 != 0)
            out[bytes - 1] = (unsigned char)(out[bytes - 1] &
                                             (0xFF00u >> (info->width % 8)));
    } else if (info->sample == RAYO_SAMPLE_U8 || info->maxval > 255) {
        size_t i, samples = (size_t)info->width * info->channels;
        if (info->sample == RAYO_SAMPLE_U8) {
            memcpy(out, row, bytes);
        } else {
            for (i = 0; i < samples; i++) {
                unsigned v = sample_at(info, row, i);
                out[2 * i] = (unsigned char)(v >> 8);
                out[2 * i + 1] = (unsigned char)(v & 0xFF);
            }
        }
    } else {
        /* U16 samples with maxval <= 255 are one byte each in the file. */
        size_t i, samples = (size_t)info->width * info->channels;
        for (i = 0; i < samples; i++)
            out[i] = (unsigned char)sample_at(info, row, i);
        bytes = samples;
    }
    return bytes;
}

/* count rows in the file's layout into out, which has room for count
 * times scratch_bytes(); returns the bytes written.  runs (plain PBM
 * only) is NULL or gives the rows as pnm_runs takes them. */
static size_t format_rows(const rayo_writer *writer,
                          const unsigned char *rows, size_t stride,
                          const rayo_row_runs *runs, uint32_t count,
                          unsigned char *out)
{
    const pnm_state *state = writer->state;
    size_t used = 0;
    uint32_t r;
    if (state->plain_bits != NULL)
        return rayo_pbm_plain_rows(state->plain_bits, rows, stride, runs,
                                   count, out);
    for (r = 0; r < count; r++, rows += stride)
        used += writer->options.plain
                    ? format_plain_samples(writer, rows, out + used)
                    : format_raw(writer, rows, out + used);
    return used;
}

/* 1 when the rows can go to the file as they are, stride included. */
static int raw_as_is(const rayo_writer *writer, const unsigned char *rows,
                     size_t stride, uint32_t count)
{
    const rayo_image_info *info = &writer->info;
    size_t bytes = rayo_image_info_row_bytes(info);
    unsigned padding;
    uint32_t r;
    if (writer->options.plain || stride != bytes)
        return 0;
    if (info->sample == RAYO_SAMPLE_U8)
        return 1;
    if (info->sample != RAYO_SAMPLE_BIT)
        return 0;
    if (info->width % 8 == 0)
        return 1; /* no padding bits: the rows are not even read */
    padding = 0xFFu >> (info->width % 8);
    for (r = 0; r < count; r++)
        if (rows[(size_t)r * stride + bytes - 1] & padding)
            return 0;
    return 1;
}

/*
 * Plain PBM rows given as runs that are all white, this many bytes of
 * them in a row at least, are not formatted: the output takes them by
 * reference to the formatter's white rows (output_reserve.h), and the
 * kernel copies them from there.  Shorter stretches are copied: a
 * reference costs the kernel about what copying 1 KB does.
 */
#define WHITE_REFER_BYTES 4096u

/* The first row from r on that starts min_rows white rows (runs with no
 * run), or count. */
static uint32_t white_stretch(const rayo_row_runs *runs, uint32_t r,
                              uint32_t count, uint32_t min_rows)
{
    uint32_t start = r, length = 0;
    for (; r < count; r++) {
        if (runs[r].count != 0) {
            length = 0;
            continue;
        }
        if (length++ == 0)
            start = r;
        if (length == min_rows)
            return start;
    }
    return count;
}

/* The white rows from r on, by reference; returns the next row. */
static rayo_status refer_white(rayo_writer *writer,
                               const rayo_row_runs *runs, uint32_t *r,
                               uint32_t count, rayo_error *err)
{
    const pnm_state *state = writer->state;
    size_t per_block;
    const unsigned char *white =
        rayo_pbm_plain_white(state->plain_bits, &per_block);
    while (*r < count && runs[*r].count == 0) {
        size_t rows = 0;
        rayo_status status;
        while (rows < per_block && *r + rows < count &&
               runs[*r + rows].count == 0)
            rows++;
        status = rayo_output_refer(writer->out, white,
                                   rows * state->scratch_size, err);
        if (status != RAYO_OK)
            return status;
        *r += (uint32_t)rows;
        writer->rows_referred += (uint32_t)rows;
    }
    return RAYO_OK;
}

/* Formats count rows (runs: as format_rows) into the output's buffer, as
 * many at a time as it has room for; long stretches of white rows given
 * as runs go by reference instead. */
static rayo_status write_formatted(rayo_writer *writer,
                                   const unsigned char *rows, size_t stride,
                                   const rayo_row_runs *runs, uint32_t count,
                                   rayo_error *err)
{
    pnm_state *state = writer->state;
    uint32_t r, min_white = 0, stop = count;
    if (runs != NULL && state->plain_bits != NULL) {
        min_white = (uint32_t)((WHITE_REFER_BYTES + state->scratch_size - 1) /
                               state->scratch_size);
        stop = 0; /* where the next white stretch starts: not looked for */
    }
    for (r = 0; r < count;) {
        unsigned char *room;
        size_t available, fits;
        rayo_status status;
        if (min_white > 0 && stop <= r) {
            stop = white_stretch(runs, r, count, min_white);
            if (stop == r) {
                status = refer_white(writer, runs, &r, count, err);
                if (status != RAYO_OK)
                    return status;
                stop = r; /* look again from here */
                continue;
            }
        }
        status = rayo_output_reserve(writer->out, state->scratch_size,
                                     &room, &available, err);
        if (status != RAYO_OK)
            return status;
        if (room == NULL) {
            /* A row larger than the output's buffer. */
            status = rayo_output_write(
                writer->out, state->scratch,
                format_rows(writer, rows + (size_t)r * stride, stride,
                            runs != NULL ? runs + r : NULL, 1,
                            state->scratch),
                err);
            if (status != RAYO_OK)
                return status;
            r++;
            continue;
        }
        /* As many rows as the room surely holds, up to the next white
         * stretch, then one advance. */
        fits = available / state->scratch_size;
        if (fits > stop - r)
            fits = stop - r;
        rayo_output_advance(writer->out,
                            format_rows(writer, rows + (size_t)r * stride,
                                        stride, runs != NULL ? runs + r : NULL,
                                        (uint32_t)fits, room));
        r += (uint32_t)fits;
    }
    return RAYO_OK;
}

static rayo_status pnm_rows(rayo_writer *writer, const unsigned char *rows,
                            size_t stride, uint32_t count, rayo_error *err)
{
    if (raw_as_is(writer, rows, stride, count))
        return rayo_output_write(writer->out, rows, (size_t)count * stride,
                                 err);
    return write_formatted(writer, rows, stride, NULL, count, err);
}

/* Plain PBM rows as runs (writer_runs.h): set up by pnm_open only for
 * plain PBM. */
static rayo_status pnm_runs(rayo_writer *writer, const unsigned char *rows,
                            size_t stride, const rayo_row_runs *runs,
                            uint32_t count, rayo_error *err)
{
    return write_formatted(writer, rows, stride, runs, count, err);
}

static void pnm_discard(rayo_writer *writer)
{
    pnm_state *state = writer->state;
    if (state != NULL) {
        free(state->scratch);
        rayo_pbm_plain_free(state->plain_bits);
        free(state);
        writer->state = NULL;
    }
}

/* The output may hold references to the white rows: written out before
 * the rows go.  (rayo_writer_discard drops them instead.) */
static rayo_status pnm_finish(rayo_writer *writer, rayo_error *err)
{
    rayo_status status = rayo_output_release(writer->out, err);
    pnm_discard(writer);
    return status;
}

const rayo_writer_ops rayo_pnm_writer_ops = {
    .open = pnm_open,
    .rows = pnm_rows,
    .runs = pnm_runs,
    .finish = pnm_finish,
    .discard = pnm_discard,
};
