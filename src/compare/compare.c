/*
 * compare.c - rayo_compare_images: the measurements of one comparison
 * put together into a report, and the names of verdicts and diagnoses.
 *
 * The work is done elsewhere in src/compare (compare_impl.h lists the
 * pieces); this file orders it: masks, the reference's outline, one
 * measuring pass, the shapes, the diagnosis.
 */
#include <math.h>
#include <string.h>

#include "rayo/image_convert.h"

#include "compare_impl.h"
#include "tone/tone_impl.h"

rayo_status cmp_options_check(const rayo_compare_options *options,
                              rayo_error *err)
{
    if (!(options->tolerance >= 0) || !isfinite(options->tolerance))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "compare: tolerance %g; expected a finite "
                              "number of pixels, 0 or more",
                              options->tolerance);
    if (options->levels > 255)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "compare: %u levels; expected 0 to 255",
                              options->levels);
    return RAYO_OK;
}

void rayo_compare_options_init(rayo_compare_options *options)
{
    options->tolerance = 2;
    options->levels = 1;
    options->course = RAYO_COMPARE_COURSE_AUTO;
    options->lossy = 0;
    options->lang = RAYO_LANG_EN;
}

static void fill_counts(const cmp_counts *c, int has_edges,
                        rayo_compare_report *r)
{
    r->reference_only = c->reference_only;
    r->image_only = c->image_only;
    r->mismatches = c->reference_only + c->image_only;
    r->mismatch_percent =
        r->pixels ? 100.0 * (double)r->mismatches / (double)r->pixels : 0;
    r->iou = c->either ? (double)c->both / (double)c->either : 1.0;
    r->max_distance = c->max_distance;
    r->beyond_tolerance = c->beyond;
    if (!has_edges) {
        r->max_distance = r->mismatches ? -1 : 0;
        r->beyond_tolerance = r->mismatches;
    }
}

static void fill_shapes(const cmp_shape *rs, const cmp_shape *is,
                        rayo_compare_report *r)
{
    r->reference_black = rs->black;
    r->image_black = is->black;
    r->shapes_measured = rs->black != 0 && is->black != 0;
    r->scale = 1;
    if (!r->shapes_measured)
        return;
    r->offset_x = is->cx - rs->cx;
    r->offset_y = is->cy - rs->cy;
    r->scale = sqrt((double)is->black / (double)rs->black);
}

static rayo_status run(const cmp_pair *pair, rayo_compare_report *report,
                       rayo_error *err)
{
    cmp_transform identity = {CMP_IDENTITY, 0, 0, 1, 1, NULL, NULL};
    cmp_outline *outline;
    cmp_counts counts;
    cmp_shape rs, is;
    rayo_status s = cmp_outline_create(&outline, &pair->ref, err);
    if (s != RAYO_OK)
        return s;
    s = cmp_measure(&pair->ref, &pair->image, &identity, outline, 1,
                    report->tolerance, &counts, err);
    if (s == RAYO_OK) {
        fill_counts(&counts, cmp_outline_has_edges(outline), report);
        cmp_shape_measure(&pair->ref, &rs);
        cmp_shape_measure(&pair->image, &is);
        fill_shapes(&rs, &is, report);
        s = cmp_diagnose(&pair->ref, &pair->image, outline, &rs, &is, report,
                         err);
    }
    cmp_outline_free(outline);
    return s;
}

/* A lossily saved image (options->lossy): values within
 * RAYO_COMPARE_LOSSY_LEVELS at least, and against a bilevel reference the
 * image's mask (black where darker than half), the levels in the report. */
static rayo_status compare_lossy(const rayo_image *reference,
                                 const rayo_image *image,
                                 const rayo_compare_options *options,
                                 rayo_compare_report *report,
                                 rayo_error *err)
{
    rayo_compare_options plain = *options;
    rayo_image mask;
    rayo_status s;
    plain.lossy = 0;
    if (plain.levels < RAYO_COMPARE_LOSSY_LEVELS)
        plain.levels = RAYO_COMPARE_LOSSY_LEVELS;
    memset(&mask, 0, sizeof mask);
    if (tone_is_bilevel(reference) && !tone_is_bilevel(image)) {
        s = rayo_image_to_bit(image, &mask, err);
        if (s != RAYO_OK)
            return s;
        image = &mask;
    }
    s = rayo_compare_images(reference, image, &plain, report, err);
    rayo_image_free(&mask);
    if (s == RAYO_OK)
        report->image_lossy_levels = plain.levels;
    return s;
}

rayo_status rayo_compare_images(const rayo_image *reference,
                                const rayo_image *image,
                                const rayo_compare_options *options,
                                rayo_compare_report *report, rayo_error *err)
{
    cmp_pair pair;
    rayo_compare_options defaults;
    rayo_status s;
    memset(report, 0, sizeof *report);
    report->lang = options != NULL ? options->lang : RAYO_LANG_EN;
    rayo_compare_options_init(&defaults);
    if (options == NULL)
        options = &defaults;
    if (options->lossy)
        return compare_lossy(reference, image, options, report, err);
    report->tolerance = options->tolerance;
    if ((s = cmp_options_check(options, err)) != RAYO_OK)
        return s;
    if ((s = rayo_image_info_check(&reference->info, err)) != RAYO_OK ||
        (s = rayo_image_info_check(&image->info, err)) != RAYO_OK)
        return s;
    if (!tone_is_bilevel(reference) || !tone_is_bilevel(image)) {
        report->reference_width = reference->info.width;
        report->reference_height = reference->info.height;
        report->image_width = image->info.width;
        report->image_height = image->info.height;
        report->pixels =
            (uint64_t)reference->info.width * reference->info.height;
        return tone_compare(reference, image, options, report, err);
    }
    s = cmp_pair_make(&pair, reference, image, err);
    if (s != RAYO_OK)
        return s;
    report->reference_width = pair.ref.width;
    report->reference_height = pair.ref.height;
    report->image_width = pair.image.width;
    report->image_height = pair.image.height;
    report->pixels = (uint64_t)pair.ref.width * pair.ref.height;
    report->scale_found = 1;
    s = run(&pair, report, err);
    cmp_pair_free(&pair);
    return s;
}

const char *rayo_compare_verdict_name(rayo_compare_verdict verdict)
{
    switch (verdict) {
    case RAYO_VERDICT_IDENTICAL:
        return "identical";
    case RAYO_VERDICT_CONSISTENT:
        return "consistent";
    default:
        return "inconsistent";
    }
}

const char *rayo_compare_diagnosis_name(rayo_compare_diagnosis diagnosis)
{
    static const char *const names[] = {
        "none",        "flipped-vertically", "flipped-horizontally",
        "rotated-180", "inverted",           "transposed",
        "shifted",     "scaled",             "different-size",
        "empty",       "not-a-sphere",       "other-sphere",
        "unknown",     "channels-swapped",   "offset",
        "wrapped",     "mistake",            "out-of-range",
        "scene"};
    if ((size_t)diagnosis >= sizeof names / sizeof names[0])
        return "unknown";
    return names[diagnosis];
}

void rayo_compare_note_clamped(rayo_compare_report *report,
                               const rayo_read_report *read)
{
    report->image_clamped_high = read->clamped_high;
    report->image_clamped_low = read->clamped_low;
    report->image_first_high_line = read->first_high_line;
    report->image_first_low_line = read->first_low_line;
    report->image_largest = read->largest_found;
    report->image_smallest = read->smallest_found;
    if (read->format == RAYO_FORMAT_BMP) {
        report->image_bmp = 1;
        report->image_bmp_bits = read->bmp_bits != 24 ? read->bmp_bits : 0;
        report->image_bmp_top_down = read->bmp_top_down;
        report->image_bmp_unpadded = read->bmp_unpadded;
    }
    if (read->clamped_high + read->clamped_low == 0 ||
        report->verdict == RAYO_VERDICT_INCONSISTENT)
        return;
    report->verdict = RAYO_VERDICT_INCONSISTENT;
    report->diagnosis = RAYO_DIAGNOSIS_OUT_OF_RANGE;
    report->diagnosis_exact = 1;
}
