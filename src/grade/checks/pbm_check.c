/*
 * pbm_check.c - the strict plain PBM checker (pbm_check.h): one pass
 * over the header and one over the raster, noting every deviation with
 * its line and column, then a single verdict on the pixel count.
 *
 * Positions are counted from 1 (line:column, as compilers and editors
 * do) and bytes from 0 (as the readers do).  The header, the count and
 * the line lengths are checked as for PGM and PPM (netpbm_scan.c); the
 * raster of 0s and 1s is this file's.  What it does not do is decide
 * whether the picture is right: that is compare's job.
 */
#include <string.h>

#include "rayo/pbm_check.h"

#include "netpbm_scan.h"
#include "rayo/lang.h"

typedef struct raster_tally {
    unsigned long long pixels, bad, comments;
    size_t first_bad, first_comment;
} raster_tally;

/* Walks the raster, filling image (when not NULL) with the first pixels. */
static void walk_raster(netpbm_scan *s, rayo_image *image, raster_tally *t)
{
    unsigned long long limit =
        image != NULL ? (unsigned long long)image->info.width *
                            image->info.height
                      : 0;
    while (s->pos < s->size) {
        int c = s->data[s->pos];
        if (c == '0' || c == '1') {
            if (t->pixels < limit && c == '1')
                rayo_bit_set(rayo_image_row(image, (uint32_t)(
                                 t->pixels / image->info.width)),
                             (uint32_t)(t->pixels % image->info.width), 1);
            t->pixels++;
        } else if (c == '#') {
            if (t->comments++ == 0)
                t->first_comment = s->pos;
            while (s->pos + 1 < s->size && s->data[s->pos + 1] != '\n')
                s->pos++;
        } else if (!netpbm_is_space(c)) {
            if (t->bad++ == 0)
                t->first_bad = s->pos;
        }
        s->pos++;
    }
}

static void check_raster_tally(netpbm_scan *s, const raster_tally *t)
{
    unsigned long line, column;
    char seen[80];
    if (t->bad > 0) {
        netpbm_where(s, t->first_bad, &line, &column);
        netpbm_excerpt(s, t->first_bad, 16, seen, sizeof seen);
        NETPBM_FAIL(s,
                    rayo_ngettext(rayo_error_lang(s->err),
                                  "%llu character in the pixels other than "
                                  "0, 1 and whitespace; the first at line "
                                  "%lu, column %lu: '%s'",
                                  "%llu characters in the pixels other than "
                                  "0, 1 and whitespace; the first at line "
                                  "%lu, column %lu: '%s'",
                                  (unsigned long)t->bad),
                    t->bad, line, column, seen);
    }
    if (t->comments > 0) {
        netpbm_where(s, t->first_comment, &line, &column);
        NETPBM_FAIL(s, N_("a '#' comment among the pixels (line %lu); Netpbm "
                       "allows comments only in the header"),
                    line);
    }
}

void netpbm_check_p1(netpbm_scan *s, uint32_t width, uint32_t height,
                     rayo_image *image)
{
    const netpbm_kind *kind = netpbm_kind_of('1');
    unsigned long w = 0, h = 0;
    raster_tally tally;
    netpbm_magic magic = netpbm_check_magic(s, kind);
    memset(&tally, 0, sizeof tally);
    if (magic == NETPBM_MAGIC_OTHER)
        netpbm_refuse_other(s, kind);
    if (magic != NETPBM_MAGIC_WANTED)
        return; /* not text PBM: line lengths mean nothing */
    if (netpbm_check_dimensions(s, kind, width, height, &w, &h)) {
        rayo_image_info info = rayo_image_info_bit((uint32_t)w,
                                                   (uint32_t)h);
        if (s->pos < s->size && !netpbm_is_space(netpbm_peek(s)))
            NETPBM_FAIL(s, N_("there is no whitespace between the height and "
                           "the pixels"));
        if (s->status == RAYO_OK)
            s->status = rayo_image_create(image, &info, s->err);
        if (s->status != RAYO_OK)
            return;
        walk_raster(s, image, &tally);
        check_raster_tally(s, &tally);
        netpbm_say_count(s, kind, w, h, tally.pixels);
    }
    netpbm_note_line_lengths(s);
    if (s->item->result == RAYO_GRADE_PASS)
        NETPBM_SAY(s, N_("plain PBM (P1), %lux%lu, %llu pixels"), w, h,
                   tally.pixels);
}

rayo_status rayo_pbm_check(const void *data, size_t size, uint32_t width,
                           uint32_t height, rayo_grade_item *item,
                           rayo_image *image, rayo_error *err)
{
    return rayo_pnm_check(data, size, '1', width, height, item, image, err);
}
