/*
 * tone.c - comparing gray and colour images by value: both taken as
 * 8-bit samples of one channel count, measured (tone_measure.c), judged
 * and diagnosed (tone_diagnose.c), put together in the report.
 *
 * rayo_compare_images comes here when either image is not bilevel (a
 * PBM, or a gray or colour image holding only black and white pixels:
 * those keep the mask comparison).  Samples of another maxval are
 * scaled to 0..255, rounded; an RGB image whose channels are equal in
 * every pixel is gray, so a gray PNG saved as RGB compares as gray.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tone_impl.h"

static unsigned sample_at(const rayo_image *image, const unsigned char *row,
                          size_t i)
{
    if (image->info.sample == RAYO_SAMPLE_U16) {
        uint16_t v;
        memcpy(&v, row + 2 * i, sizeof v);
        return v;
    }
    return row[i];
}

int tone_is_bilevel(const rayo_image *image)
{
    const rayo_image_info *info = &image->info;
    unsigned n = info->channels;
    uint32_t x, y, c;
    if (info->sample == RAYO_SAMPLE_BIT)
        return 1;
    for (y = 0; y < info->height; y++) {
        const unsigned char *row = rayo_image_row(image, y);
        for (x = 0; x < info->width; x++) {
            unsigned first = sample_at(image, row, (size_t)x * n);
            if (first != 0 && first != info->maxval)
                return 0;
            for (c = 1; c < n; c++)
                if (sample_at(image, row, (size_t)x * n + c) != first)
                    return 0;
        }
    }
    return 1;
}

int tone_has_colour(const rayo_image *image)
{
    const rayo_image_info *info = &image->info;
    uint32_t x, y;
    if (info->channels != 3)
        return 0;
    for (y = 0; y < info->height; y++) {
        const unsigned char *row = rayo_image_row(image, y);
        for (x = 0; x < info->width; x++) {
            size_t i = (size_t)x * 3;
            unsigned r = sample_at(image, row, i);
            if (sample_at(image, row, i + 1) != r ||
                sample_at(image, row, i + 2) != r)
                return 1;
        }
    }
    return 0;
}

static unsigned char to_level(unsigned v, unsigned maxval)
{
    if (maxval == 255)
        return (unsigned char)v;
    return (unsigned char)(((uint64_t)v * 255 + maxval / 2) / maxval);
}

rayo_status tone_image_make(const rayo_image *image, unsigned channels,
                            tone_image *out, rayo_error *err)
{
    const rayo_image_info *info = &image->info;
    size_t count;
    rayo_status s = rayo_image_info_check(info, err);
    memset(out, 0, sizeof *out);
    if (s != RAYO_OK)
        return s;
    count = (size_t)info->width * info->height;
    if (count > SIZE_MAX / channels)
        return rayo_error_set(err, RAYO_ERR_LIMIT, "compare: image too large");
    out->v = malloc(count * channels);
    if (out->v == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: out of memory for a %ux%u image",
                              info->width, info->height);
    out->width = info->width;
    out->height = info->height;
    out->channels = channels;
    tone_image_convert_rows(image, out, 0, info->height);
    return RAYO_OK;
}

void tone_image_convert_rows(const rayo_image *image, tone_image *out,
                             uint32_t first, uint32_t end)
{
    const rayo_image_info *info = &image->info;
    unsigned channels = out->channels, c;
    uint32_t x, y;
    if (info->sample == RAYO_SAMPLE_U8 && info->maxval == 255 &&
        (info->channels == channels || info->channels == 1)) {
        /* 8-bit samples as they are: copied, a gray one repeated. */
        for (y = first; y < end; y++) {
            const unsigned char *row = rayo_image_row(image, y);
            unsigned char *dst = out->v + (size_t)y * info->width * channels;
            if (info->channels == channels)
                memcpy(dst, row, (size_t)info->width * channels);
            else
                for (x = 0; x < info->width; x++, dst += 3)
                    dst[0] = dst[1] = dst[2] = row[x];
        }
        return;
    }
    for (y = first; y < end; y++) {
        const unsigned char *row = rayo_image_row(image, y);
        unsigned char *dst = out->v + (size_t)y * info->width * channels;
        for (x = 0; x < info->width; x++, dst += channels) {
            unsigned char v[3];
            if (info->sample == RAYO_SAMPLE_BIT) {
                v[0] = v[1] = v[2] = rayo_bit_get(row, x) ? 0 : 255;
            } else {
                size_t i = (size_t)x * info->channels;
                for (c = 0; c < 3; c++)
                    v[c] = to_level(sample_at(image, row,
                                              i + (info->channels == 3
                                                       ? c : 0)),
                                    info->maxval);
            }
            if (channels == 1) {
                /* Only gray images come here as one channel: r = g = b. */
                dst[0] = v[0];
            } else {
                dst[0] = v[0];
                dst[1] = v[1];
                dst[2] = v[2];
            }
        }
    }
}

void tone_image_drop_maps(tone_image *t)
{
    free(t->near);
    free(t->slope);
    free(t->lo);
    free(t->hi);
    t->near = t->slope = t->lo = t->hi = NULL;
}

void tone_image_free(tone_image *t)
{
    free(t->v);
    tone_image_drop_maps(t);
    memset(t, 0, sizeof *t);
}

static double psnr_of(double rmse)
{
    return rmse > 0 ? 20.0 * log10(255.0 / rmse) : INFINITY;
}

static void fill(const tone_counts *k, unsigned channels,
                 rayo_compare_report *r)
{
    rayo_compare_tone *t = &r->tone;
    unsigned c;
    for (c = 0; c < channels; c++) {
        t->channel[c].beyond = k->beyond[c];
        t->channel[c].max_difference = k->max_difference[c];
        t->channel[c].rmse =
            k->known ? sqrt(k->sum_squares[c] / (double)k->known) : 0;
        t->channel[c].psnr = psnr_of(t->channel[c].rmse);
    }
    t->differing = k->differing;
    t->at_edges = k->at_edges;
    t->in_shading = k->in_shading;
    t->unexplained = k->unexplained;
    t->max_edge_difference = k->max_edge_difference;
    t->first_x = k->first_x;
    t->first_y = k->first_y;
    r->mismatches = k->differing;
    r->mismatch_percent =
        r->pixels ? 100.0 * (double)k->differing / (double)r->pixels : 0;
    r->beyond_tolerance = k->unexplained;
    r->iou = 1;
    r->scale = 1;
}

/* How much better the image lays on the reference scaled a little: the
   course's references were drawn with a focal distance 0.47% long.  k:
   the unscaled comparison's counts. */
static void fit_scale(const tone_image *ref, const tone_image *image,
                      const tone_counts *k, rayo_compare_report *r)
{
    uint64_t left;
    double s, squares, none = k->sum_squares[0] + k->sum_squares[1] +
                              k->sum_squares[2];
    r->tone.scale_fit = 1;
    r->tone.differing_scaled = r->tone.differing;
    if (r->tone.differing == 0 || ref->width != image->width ||
        ref->height != image->height)
        return;
    s = tone_best_scale(ref, image, r->tone.levels, 0.98, 1.02, &left,
                        &squares);
    if (fabs(s - 1) >= 0.001 && 1.5 * squares <= none &&
        left < r->tone.differing) {
        r->tone.scale_fit = s;
        r->tone.differing_scaled = left;
    }
}

rayo_status tone_compare(const rayo_image *reference, const rayo_image *image,
                         const rayo_compare_options *options,
                         rayo_compare_report *r, rayo_error *err)
{
    tone_image ref, img;
    tone_xform identity = tone_identity();
    tone_counts k;
    int ref_colour = tone_has_colour(reference);
    int img_colour = tone_has_colour(image);
    unsigned channels = ref_colour || img_colour ? 3 : 1;
    rayo_status s = tone_image_make(reference, channels, &ref, err);
    if (s != RAYO_OK)
        return s;
    s = tone_image_make(image, channels, &img, err);
    if (s != RAYO_OK) {
        tone_image_free(&ref);
        return s;
    }
    s = tone_image_find_edges_kept(&ref, r->tolerance, options->levels,
                                   err);
    if (s != RAYO_OK) {
        tone_image_free(&ref);
        tone_image_free(&img);
        return s;
    }
    r->kind = RAYO_COMPARE_TONE;
    r->tone.channels = channels;
    r->tone.reference_channels = ref_colour ? 3 : 1;
    r->tone.image_channels = img_colour ? 3 : 1;
    r->tone.levels = options->levels;
    r->tone.course = -1;
    r->tone.order[0] = 0;
    r->tone.order[1] = 1;
    r->tone.order[2] = 2;
    tone_measure(&ref, &img, &identity, r->tolerance, options->levels, 1,
                 &k);
    fill(&k, channels, r);
    fit_scale(&ref, &img, &k, r);
    s = tone_diagnose(&ref, &img, options, r, err);
    tone_image_free(&ref);
    tone_image_free(&img);
    return s;
}
