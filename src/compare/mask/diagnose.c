/*
 * diagnose.c - the verdict, and for an inconsistent image the mistake
 * that explains it.
 *
 * Consistent means every mismatch within the tolerance of the outline,
 * the mismatches at most RAYO_COMPARE_BAND_SHARE of the pixels there and
 * fewer than chance (band.c).  Otherwise every candidate mistake is tried
 * the same way: undo it on the image (transform.c) and compare again; the
 * one leaving fewest far mismatches, and close enough to consistent,
 * wins.  Thresholds are written once, below, with their reasons.  Not a
 * registration algorithm: one mistake at a time, no combinations.
 */
#include <math.h>
#include <stdlib.h>

#include "../compare_impl.h"

/*
 * A candidate is named only if the result is consistent with the
 * reference, or close to it (at most a twentieth of the far mismatches
 * left and the black regions' IoU at least 0.97).  Counting alone is
 * cheap, so a candidate whose undoing does not halve the mismatches is
 * dropped before any distance is computed.  The shift to try comes from
 * the centroids; the scale from the areas and the centroids, refined by a
 * golden-section search on a sampled grid.  When nothing fits, the image's
 * black region is judged on its own: empty, an outline that no ellipse
 * fits (not a sphere), or another sphere.
 */

/* A candidate "comes close": far mismatches cut twentyfold and IoU. */
#define CLOSE_REDUCTION 20
#define CLOSE_IOU 0.97
/* A black region is a sphere when its outline (its edge inside the
 * frame, so a sphere cut by the frame still counts) lies on average
 * within this many pixels of the best-fitting ellipse.  Rendered
 * spheres score about 0.3 (pixel rounding); a straight edge, a ring, two
 * blobs or noise fit no ellipse at all or miss by far more. */
#define SPHERE_OUTLINE_ERROR 1.0
/* A flip or transposition is tried only if it would bring the
 * reference's centroid within this distance of the image's: a fraction
 * of the shape's size (square root of its area), at least a few pixels. */
#define CENTROID_SLACK 0.15
#define CENTROID_SLACK_MIN 4.0
/* Scales closer to 1 than this are not worth a diagnosis. */
#define SCALE_EPSILON 0.004
/* The scale search samples about this many pixels, and first scans this
 * many scales. */
#define SCALE_SAMPLES 65536.0
#define SCALE_SCAN 33

typedef struct candidate_result {
    int tried;
    cmp_counts counts;
} candidate_result;

static double iou_of(const cmp_counts *c)
{
    return c->either ? (double)c->both / (double)c->either : 1.0;
}

static uint64_t mismatches_of(const cmp_counts *c)
{
    return c->reference_only + c->image_only;
}

/* Measures t fully if counting shows it could explain the mismatches. */
static rayo_status try_candidate(const cmp_mask *ref, const cmp_mask *image,
                                 cmp_outline *outline,
                                 const rayo_compare_report *report,
                                 const cmp_transform *t,
                                 candidate_result *result, rayo_error *err)
{
    rayo_status s;
    result->tried = 0;
    s = cmp_measure(ref, image, t, NULL, 0, report->tolerance, &result->counts,
                    err);
    if (s != RAYO_OK)
        return s;
    if (2 * mismatches_of(&result->counts) > report->mismatches)
        return RAYO_OK;
    s = cmp_measure(ref, image, t, outline, 0, report->tolerance,
                    &result->counts, err);
    result->tried = s == RAYO_OK;
    return s;
}

/* Whether a candidate's mismatches, over the pixels it places, agree
 * with the reference beyond chance (band.c): over noise or a
 * checkerboard every mismatch is near an outline, and a transform that
 * places only part of the frame (a scale up) halves the count by
 * itself, so without this the luckiest of the scales searched was
 * named. */
static int beats_chance(const cmp_counts *c)
{
    return (double)mismatches_of(c) <=
           cmp_chance_limit(c->known, c->both + c->reference_only,
                            c->both + c->image_only);
}

static int fits(const candidate_result *r, const rayo_compare_report *report)
{
    if (!r->tried)
        return 0;
    if (r->counts.beyond == 0)
        return beats_chance(&r->counts);
    return r->counts.beyond * CLOSE_REDUCTION <= report->beyond_tolerance &&
           iou_of(&r->counts) >= CLOSE_IOU;
}

static int better(const candidate_result *a, const candidate_result *b)
{
    if (a->counts.beyond != b->counts.beyond)
        return a->counts.beyond < b->counts.beyond;
    return mismatches_of(&a->counts) < mismatches_of(&b->counts);
}

/* 1 - IoU of ref and the image scaled by s, on a sampled grid. */
static rayo_status scale_loss(const cmp_mask *ref, const cmp_mask *image,
                              double s, uint32_t step, double *loss,
                              rayo_error *err)
{
    cmp_transform t = {CMP_SCALE, 0, 0, 0, 0, NULL, NULL};
    cmp_counts c;
    rayo_status st;
    t.scale = s;
    t.step = step;
    st = cmp_measure(ref, image, &t, NULL, 0, 0, &c, err);
    *loss = 1.0 - iou_of(&c);
    return st;
}

/* The scale s (image = reference scaled by s about the optical centre)
 * that best lays the image on the reference: a coarse scan of scales
 * around the estimates from the areas and the centroids (both biased
 * when the frame cuts the shape, hence the wide range), then a
 * golden-section search between the neighbours of the best. */
static rayo_status search_scale(const cmp_mask *ref, const cmp_mask *image,
                                const cmp_shape *rs, const cmp_shape *is,
                                double area_scale, double *best,
                                rayo_error *err)
{
    double lo = area_scale, hi = area_scale, rn, in, a, b, c, d, fc, fd;
    double pixels = (double)ref->width * ref->height, ratio, f, fbest = 2;
    uint32_t step = (uint32_t)ceil(sqrt(pixels / SCALE_SAMPLES)), i;
    uint32_t ibest = 0;
    rayo_status s;
    rn = hypot(rs->cx, rs->cy);
    in = hypot(is->cx, is->cy);
    if (rn > 8 && in > 8) {
        lo = fmin(lo, in / rn);
        hi = fmax(hi, in / rn);
    }
    lo /= 2;
    hi *= 2;
    ratio = pow(hi / lo, 1.0 / (SCALE_SCAN - 1));
    for (i = 0; i < SCALE_SCAN; i++) {
        if ((s = scale_loss(ref, image, lo * pow(ratio, i), step, &f,
                            err)) != RAYO_OK)
            return s;
        if (f < fbest) {
            fbest = f;
            ibest = i;
        }
    }
    a = lo * pow(ratio, (double)ibest - 1);
    b = lo * pow(ratio, (double)ibest + 1);
    c = b - (b - a) * 0.6180339887;
    d = a + (b - a) * 0.6180339887;
    if ((s = scale_loss(ref, image, c, step, &fc, err)) != RAYO_OK ||
        (s = scale_loss(ref, image, d, step, &fd, err)) != RAYO_OK)
        return s;
    for (i = 0; i < 20; i++) {
        if (fc <= fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - (b - a) * 0.6180339887;
            s = scale_loss(ref, image, c, step, &fc, err);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + (b - a) * 0.6180339887;
            s = scale_loss(ref, image, d, step, &fd, err);
        }
        if (s != RAYO_OK)
            return s;
    }
    *best = (a + b) / 2;
    return RAYO_OK;
}

typedef struct chooser {
    candidate_result best;
    cmp_transform transform;
    int found;
} chooser;

static rayo_status consider(chooser *ch, const cmp_mask *ref,
                            const cmp_mask *image, cmp_outline *outline,
                            const rayo_compare_report *report,
                            const cmp_transform *t, rayo_error *err)
{
    candidate_result r;
    rayo_status s = try_candidate(ref, image, outline, report, t, &r, err);
    if (s != RAYO_OK || !fits(&r, report))
        return s;
    if (!ch->found || better(&r, &ch->best)) {
        ch->best = r;
        ch->transform = *t;
        ch->found = 1;
    }
    return RAYO_OK;
}

/* The scale candidate at full resolution, through a column map. */
static rayo_status consider_scaled(chooser *ch, const cmp_mask *ref,
                                   const cmp_mask *image,
                                   cmp_outline *outline,
                                   const rayo_compare_report *report,
                                   cmp_transform *t, rayo_error *err)
{
    int32_t *columns = malloc((size_t)ref->width * sizeof *columns);
    rayo_status s;
    if (columns == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "compare: out of memory for a column map");
    cmp_transform_columns(t, ref->width, image->width, columns);
    t->columns = columns;
    t->step = 1;
    s = consider(ch, ref, image, outline, report, t, err);
    t->columns = NULL; /* the chooser may keep a copy of t */
    if (ch->found && ch->transform.columns == columns)
        ch->transform.columns = NULL;
    free(columns);
    return s;
}

/* The transposition candidate, read from a transposed copy. */
static rayo_status consider_transposed(chooser *ch, const cmp_mask *ref,
                                       const cmp_mask *image,
                                       cmp_outline *outline,
                                       const rayo_compare_report *report,
                                       cmp_transform *t, rayo_error *err)
{
    cmp_mask transposed;
    unsigned char *bits;
    rayo_status s = cmp_mask_transpose(image, &transposed, &bits, err);
    if (s != RAYO_OK)
        return s;
    t->transposed = &transposed;
    s = consider(ch, ref, image, outline, report, t, err);
    t->transposed = NULL; /* the chooser may keep a copy of t */
    if (ch->found)
        ch->transform.transposed = NULL;
    free(bits);
    return s;
}

/* A candidate that undoes every far mismatch ends the search. */
static int exact_found(const chooser *ch)
{
    return ch->found && ch->best.counts.beyond == 0;
}

static rayo_compare_diagnosis diagnosis_of(cmp_transform_kind kind)
{
    switch (kind) {
    case CMP_INVERT:
        return RAYO_DIAGNOSIS_INVERTED;
    case CMP_FLIP_V:
        return RAYO_DIAGNOSIS_FLIPPED_VERTICALLY;
    case CMP_FLIP_H:
        return RAYO_DIAGNOSIS_FLIPPED_HORIZONTALLY;
    case CMP_FLIP_BOTH:
        return RAYO_DIAGNOSIS_ROTATED_180;
    case CMP_TRANSPOSE:
        return RAYO_DIAGNOSIS_TRANSPOSED;
    case CMP_SHIFT:
        return RAYO_DIAGNOSIS_SHIFTED;
    case CMP_SCALE:
        return RAYO_DIAGNOSIS_SCALED;
    default:
        return RAYO_DIAGNOSIS_UNKNOWN;
    }
}

static void name_choice(const chooser *ch, rayo_compare_report *report)
{
    report->diagnosis = diagnosis_of(ch->transform.kind);
    report->diagnosis_exact = ch->best.counts.beyond == 0;
    report->shift_x = ch->transform.dx;
    report->shift_y = ch->transform.dy;
    report->scale_found = ch->transform.scale;
}

static int32_t round_offset(double v)
{
    return (int32_t)floor(v + 0.5);
}

/* The centroid offset left after the scale about the optical centre
 * (which is what a focal distance a little off produces). */
static void residual_offset(const cmp_shape *rs, const cmp_shape *is,
                            const rayo_compare_report *report, int32_t *dx,
                            int32_t *dy)
{
    double s = rs->touches_border || is->touches_border ? 1 : report->scale;
    *dx = round_offset(is->cx - s * rs->cx);
    *dy = round_offset(is->cy - s * rs->cy);
}

/* Within tolerance everywhere: consistent unless a whole-pixel shift
 * explains the mismatches (then they are a mistake, not rounding). */
static rayo_status judge_close(const cmp_mask *ref, const cmp_mask *image,
                               const cmp_shape *rs, const cmp_shape *is,
                               rayo_compare_report *report, rayo_error *err)
{
    cmp_transform t = {CMP_SHIFT, 0, 0, 1, 1, NULL, NULL};
    cmp_counts c;
    rayo_status s;
    int32_t ex, ey, dx, dy;
    uint64_t fewest = UINT64_MAX;
    report->verdict = RAYO_VERDICT_CONSISTENT;
    if (!report->shapes_measured)
        return RAYO_OK;
    residual_offset(rs, is, report, &ex, &ey);
    if (ex == 0 && ey == 0)
        return RAYO_OK;
    /* The centroids move less than the picture when the frame cuts the
       shape: try the shifts around their estimate, keep the best. */
    for (dy = ey - 1; dy <= ey + 1; dy++)
        for (dx = ex - 1; dx <= ex + 1; dx++) {
            cmp_transform u = t;
            if (dx == 0 && dy == 0)
                continue;
            u.dx = dx;
            u.dy = dy;
            s = cmp_measure(ref, image, &u, NULL, 0, 0, &c, err);
            if (s != RAYO_OK)
                return s;
            if (mismatches_of(&c) < fewest) {
                fewest = mismatches_of(&c);
                t = u;
            }
        }
    if (2 * fewest > report->mismatches)
        return RAYO_OK;
    report->verdict = RAYO_VERDICT_INCONSISTENT;
    report->diagnosis = RAYO_DIAGNOSIS_SHIFTED;
    report->diagnosis_exact = 1;
    report->shift_x = t.dx;
    report->shift_y = t.dy;
    return RAYO_OK;
}

/* The focal distance the course's own programs had, as a factor of the
 * formula's: pi computed as sqrt(9.81) makes tan(FOV/2) smaller, z =
 * 321.5 where ANCHO / (2 tan(45 degrees)) is 320, and every shape
 * 1.0048 times larger about the centre (the course's references for EJ1
 * and EJ2 were drawn so). */
static double course_focal(void)
{
    return 1.0 / tan(sqrt(9.81) / 4.0);
}

/* A consistent picture drawn with the course's focal distance, or
 * against a reference drawn with it: when the image scaled about the
 * optical centre by that factor (or its inverse) leaves at most half
 * the mismatches, scale_found says which (else it stays 1), so the
 * report can name it instead of rounding. */
static rayo_status focal_of_consistent(const cmp_mask *ref,
                                       const cmp_mask *image,
                                       rayo_compare_report *report,
                                       rayo_error *err)
{
    double scales[2];
    uint64_t fewest = report->mismatches;
    size_t i;
    scales[0] = course_focal();
    scales[1] = 1.0 / scales[0];
    for (i = 0; i < 2; i++) {
        cmp_transform t = {CMP_SCALE, 0, 0, 0, 1, NULL, NULL};
        cmp_counts c;
        rayo_status s;
        t.scale = scales[i];
        s = cmp_measure(ref, image, &t, NULL, 0, 0, &c, err);
        if (s != RAYO_OK)
            return s;
        if (2 * mismatches_of(&c) <= report->mismatches &&
            mismatches_of(&c) < fewest) {
            fewest = mismatches_of(&c);
            report->scale_found = scales[i];
        }
    }
    return RAYO_OK;
}

/* Whether the reference's centroid, moved as the mistake would move it,
 * lands near the image's: a cheap test that spares most candidates a
 * full pass.  Inversion, which moves the centroid unpredictably, is
 * judged by the number of mismatches instead. */
static int centroid_agrees(const cmp_mask *ref, const cmp_shape *rs,
                           const cmp_shape *is, double mismatches,
                           cmp_transform_kind kind)
{
    double w = ref->width, h = ref->height;
    double mx = rs->cx + floor(w / 2), my = rs->cy + floor(h / 2), t;
    double slack = fmax(CENTROID_SLACK_MIN,
                        CENTROID_SLACK * sqrt((double)rs->black));
    if (kind == CMP_INVERT) /* leaves known - m of m mismatches: it can
                               halve them only if m >= 2/3 of the frame */
        return 3 * mismatches >= 2 * (double)ref->width * ref->height;
    if (rs->black == 0 || is->black == 0)
        return 1;
    if (kind == CMP_FLIP_V || kind == CMP_FLIP_BOTH)
        my = h - 1 - my;
    if (kind == CMP_FLIP_H || kind == CMP_FLIP_BOTH)
        mx = w - 1 - mx;
    if (kind == CMP_TRANSPOSE) {
        t = mx;
        mx = my;
        my = t;
    }
    return hypot(mx - floor(w / 2) - is->cx, my - floor(h / 2) - is->cy) <=
           slack;
}

/* Whether a flip or a transposition, which moves the image's black
 * pixels without changing their number, surely leaves more than half the
 * mismatches: it leaves at least the difference of the black counts.
 * (try_candidate would count that, at the cost of a pass.) */
static int cannot_halve(const rayo_compare_report *report)
{
    uint64_t rb = report->reference_black, ib = report->image_black;
    uint64_t least = rb > ib ? rb - ib : ib - rb;
    return 2 * least > report->mismatches;
}

static rayo_status try_all(const cmp_mask *ref, const cmp_mask *image,
                           cmp_outline *outline, const cmp_shape *rs,
                           const cmp_shape *is, rayo_compare_report *report,
                           chooser *ch, rayo_error *err)
{
    static const cmp_transform_kind plain[] = {
        CMP_INVERT, CMP_FLIP_V, CMP_FLIP_H, CMP_FLIP_BOTH, CMP_TRANSPOSE};
    cmp_transform t = {CMP_IDENTITY, 0, 0, 1, 1, NULL, NULL};
    rayo_status s = RAYO_OK;
    size_t i;
    for (i = 0; i < sizeof plain / sizeof plain[0] && s == RAYO_OK &&
                !exact_found(ch);
         i++) {
        t.kind = plain[i];
        if (t.kind != CMP_INVERT && cannot_halve(report))
            continue;
        if ((t.kind != CMP_TRANSPOSE || ref->width == ref->height) &&
            centroid_agrees(ref, rs, is, (double)report->mismatches, t.kind))
            s = t.kind == CMP_TRANSPOSE
                    ? consider_transposed(ch, ref, image, outline, report, &t,
                                          err)
                    : consider(ch, ref, image, outline, report, &t, err);
    }
    if (s != RAYO_OK || !report->shapes_measured || exact_found(ch))
        return s;
    t.kind = CMP_SHIFT;
    t.dx = round_offset(report->offset_x);
    t.dy = round_offset(report->offset_y);
    if ((t.dx != 0 || t.dy != 0) &&
        (s = consider(ch, ref, image, outline, report, &t, err)) != RAYO_OK)
        return s;
    if (exact_found(ch))
        return RAYO_OK;
    t.kind = CMP_SCALE;
    t.dx = t.dy = 0;
    if ((s = search_scale(ref, image, rs, is, report->scale, &t.scale,
                          err)) != RAYO_OK)
        return s;
    if (fabs(t.scale - 1) < SCALE_EPSILON)
        return RAYO_OK;
    return consider_scaled(ch, ref, image, outline, report, &t, err);
}

static void judge_shape(const cmp_mask *image, const cmp_shape *is,
                        rayo_compare_report *report)
{
    if (is->black == 0)
        report->diagnosis = RAYO_DIAGNOSIS_EMPTY;
    else if (!(cmp_shape_ellipse_error(image, SPHERE_OUTLINE_ERROR) <=
               SPHERE_OUTLINE_ERROR))
        report->diagnosis = RAYO_DIAGNOSIS_NOT_A_SPHERE;
    else if (report->reference_black != 0)
        report->diagnosis = RAYO_DIAGNOSIS_OTHER_SPHERE;
    else
        report->diagnosis = RAYO_DIAGNOSIS_UNKNOWN;
}

/* Different sizes are always inconsistent; transposed when laying the
 * image's rows as columns fits the reference. */
static rayo_status diagnose_size(const cmp_mask *ref, const cmp_mask *image,
                                 cmp_outline *outline,
                                 rayo_compare_report *report,
                                 rayo_error *err)
{
    cmp_transform t = {CMP_TRANSPOSE, 0, 0, 1, 1, NULL, NULL};
    cmp_counts c;
    cmp_mask transposed;
    unsigned char *bits;
    rayo_status s;
    report->verdict = RAYO_VERDICT_INCONSISTENT;
    report->diagnosis = RAYO_DIAGNOSIS_DIFFERENT_SIZE;
    if (image->width != ref->height || image->height != ref->width)
        return RAYO_OK;
    if ((s = cmp_mask_transpose(image, &transposed, &bits, err)) != RAYO_OK)
        return s;
    t.transposed = &transposed;
    s = cmp_measure(ref, image, &t, outline, 0, report->tolerance, &c,
                    err);
    free(bits);
    if (s != RAYO_OK)
        return s;
    if (c.beyond == 0 || iou_of(&c) >= CLOSE_IOU) {
        report->diagnosis = RAYO_DIAGNOSIS_TRANSPOSED;
        report->diagnosis_exact = c.beyond == 0;
    }
    return RAYO_OK;
}

rayo_status cmp_diagnose(const cmp_mask *ref, const cmp_mask *image,
                         cmp_outline *outline, const cmp_shape *rs,
                         const cmp_shape *is, rayo_compare_report *report,
                         rayo_error *err)
{
    chooser ch;
    rayo_status s;
    report->diagnosis = RAYO_DIAGNOSIS_NONE;
    if (ref->width != image->width || ref->height != image->height)
        return diagnose_size(ref, image, outline, report, err);
    if (report->mismatches == 0) {
        report->verdict = RAYO_VERDICT_IDENTICAL;
        return RAYO_OK;
    }
    if (report->beyond_tolerance == 0) {
        s = judge_close(ref, image, rs, is, report, err);
        if (s != RAYO_OK || report->verdict != RAYO_VERDICT_CONSISTENT)
            return s;
        s = cmp_outline_band(ref, outline, report->tolerance, &report->band,
                             err);
        if (s != RAYO_OK)
            return s;
        if (!cmp_mask_crowded(report))
            return focal_of_consistent(ref, image, report, err);
        report->crowded = 1;
    }
    report->verdict = RAYO_VERDICT_INCONSISTENT;
    if (is->black == 0) {
        report->diagnosis = RAYO_DIAGNOSIS_EMPTY;
        return RAYO_OK;
    }
    ch.found = 0;
    s = try_all(ref, image, outline, rs, is, report, &ch, err);
    if (s != RAYO_OK)
        return s;
    if (ch.found)
        name_choice(&ch, report);
    else if (report->crowded) /* no shape to judge: the note says why */
        report->diagnosis = RAYO_DIAGNOSIS_UNKNOWN;
    else
        judge_shape(image, is, report);
    return RAYO_OK;
}
