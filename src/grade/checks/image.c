/*
 * image.c - the fifth criterion: the picture is consistent with the
 * exercise's reference, as `rayo compare` judges it (compare.h), and
 * when it is not, what the mistake looks like, in the student's terms.
 *
 * The pixels come from the strict checker when the output is P1 (even a
 * slightly wrong P1: its pixels are read as if the header were right,
 * and the report says so), or from the tolerant readers for any other
 * format.  The diagnosis names are compare's; the sentences and the
 * hints about likely causes in the code are this file's.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/compare.h"
#include "rayo/lang.h"
#include "rayo/output.h"
#include "rayo/reader.h"

#include "../grade_impl.h"

/* tan(45 rad) / tan(45 deg): how much bigger the focal distance is
   when FOV is given to tan() in degrees: the sphere looks this much
   smaller. */
#define DEGREES_AS_RADIANS_SCALE (1.0 / tan(45.0))

/* The shift in words, "2 pixels left", "1 row down", each a phrase of
   the catalog with its plural, put into a whole sentence by say_shift. */
static void shift_phrase(rayo_lang lang, int32_t d, int across, char *out,
                         size_t room)
{
    unsigned long n = (unsigned long)(d < 0 ? -(long)d : (long)d);
    if (across && d < 0)
        snprintf(out, room,
                 rayo_ngettext(lang, "%lu pixel left", "%lu pixels left", n),
                 n);
    else if (across)
        snprintf(out, room,
                 rayo_ngettext(lang, "%lu pixel right", "%lu pixels right",
                               n),
                 n);
    else if (d < 0)
        snprintf(out, room,
                 rayo_ngettext(lang, "%lu row up", "%lu rows up", n), n);
    else
        snprintf(out, room,
                 rayo_ngettext(lang, "%lu row down", "%lu rows down", n), n);
}

static rayo_status say_shift(rayo_grade_item *item, int32_t dx, int32_t dy,
                             rayo_error *err)
{
    rayo_lang lang = rayo_error_lang(err);
    char h[96] = "", v[96] = "";
    if (dx != 0)
        shift_phrase(lang, dx, 1, h, sizeof h);
    if (dy != 0)
        shift_phrase(lang, dy, 0, v, sizeof v);
    if (dx != 0 && dy != 0)
        return grade_fail(item, err, "the image is moved %s and %s: the "
                                     "centre of the picture must be x = 0, "
                                     "y = 0 (x = i - ANCHO/2, y = j - "
                                     "ALTO/2)",
                          h, v);
    return grade_fail(item, err, "the image is moved %s: the centre of "
                                 "the picture must be x = 0, y = 0 (x "
                                 "= i - ANCHO/2, y = j - ALTO/2)",
                      dx != 0 ? h : v);
}

static rayo_status say_scaled(rayo_grade_item *item,
                              const rayo_compare_report *r, rayo_error *err)
{
    double wrong = fabs(DEGREES_AS_RADIANS_SCALE);
    rayo_status status = grade_fail(
        item, err, "the sphere is %.2f times the size of the reference's: "
                   "the focal distance z = ancho / (2 tan(fov / 2)) is off",
        r->scale_found);
    if (status == RAYO_OK && fabs(r->scale_found - wrong) < 0.03)
        status = grade_say(item, err, "that is exactly what tan() of FOV "
                                      "in degrees gives: tan() takes "
                                      "radians, FOV * PI / 180 (define PI "
                                      "yourself: M_PI is not C99)");
    return status;
}

static rayo_status say_diagnosis(rayo_grade_item *item,
                                 const rayo_compare_report *r,
                                 rayo_error *err)
{
    switch (r->diagnosis) {
    case RAYO_DIAGNOSIS_NONE:
        return RAYO_OK;
    case RAYO_DIAGNOSIS_FLIPPED_VERTICALLY:
        return grade_fail(item, err, "the image is upside down: rows must "
                                     "go from the top (y = -ALTO/2) down, "
                                     "and the direction is (x, -y, z)");
    case RAYO_DIAGNOSIS_FLIPPED_HORIZONTALLY:
        return grade_fail(item, err, "the image is mirrored left to right: "
                                     "columns must go from x = -ANCHO/2 "
                                     "to the right");
    case RAYO_DIAGNOSIS_ROTATED_180:
        return grade_fail(item, err, "the image is rotated 180 degrees "
                                     "(upside down and mirrored)");
    case RAYO_DIAGNOSIS_INVERTED:
        return grade_fail(item, err, "black and white are swapped: PBM's 1 "
                                     "is black, and must be written where "
                                     "the ray hits the sphere");
    case RAYO_DIAGNOSIS_TRANSPOSED:
        return grade_fail(item, err, "rows and columns are swapped: write "
                                     "the image row by row, each row from "
                                     "left to right");
    case RAYO_DIAGNOSIS_SHIFTED:
        return say_shift(item, r->shift_x, r->shift_y, err);
    case RAYO_DIAGNOSIS_SCALED:
        return say_scaled(item, r, err);
    case RAYO_DIAGNOSIS_DIFFERENT_SIZE:
        return grade_fail(item, err, "the image is %ux%u; the reference is "
                                     "%ux%u",
                          (unsigned)r->image_width,
                          (unsigned)r->image_height,
                          (unsigned)r->reference_width,
                          (unsigned)r->reference_height);
    case RAYO_DIAGNOSIS_EMPTY:
        return grade_fail(item, err, "the image is all white: no ray hits "
                                     "the sphere");
    case RAYO_DIAGNOSIS_NOT_A_SPHERE:
        if (r->image_black * 2 > r->pixels)
            return grade_fail(item, err, "the black region is not round "
                                         "like a sphere seen through the "
                                         "camera; most of the image is "
                                         "black: is the direction "
                                         "normalised before "
                                         "intersecta_esfera?");
        return grade_fail(item, err, "the black region is not round like a "
                                     "sphere seen through the camera");
    case RAYO_DIAGNOSIS_OTHER_SPHERE:
        return grade_fail(item, err, "there is a sphere, but elsewhere or "
                                     "of another size: its centre is "
                                     "%.0f, %.0f pixels off, its size %.2f "
                                     "times the reference's",
                          r->offset_x, r->offset_y, r->scale);
    case RAYO_DIAGNOSIS_UNKNOWN:
    case RAYO_DIAGNOSIS_CHANNELS_SWAPPED:
    case RAYO_DIAGNOSIS_OFFSET:
    case RAYO_DIAGNOSIS_WRAPPED:
    case RAYO_DIAGNOSIS_MISTAKE:
    case RAYO_DIAGNOSIS_OUT_OF_RANGE:
    case RAYO_DIAGNOSIS_SCENE:
        break;
    }
    if (r->image_black * 2 > r->pixels)
        return grade_fail(item, err, "no simple mistake explains the "
                                     "difference; most of the image is "
                                     "black: is the direction normalised "
                                     "before intersecta_esfera?");
    return grade_fail(item, err, "no simple mistake explains the "
                                 "difference");
}

static rayo_status judge_mask(rayo_grade_item *item,
                              const rayo_compare_report *r, rayo_error *err)
{
    rayo_status status;
    if (r->verdict == RAYO_VERDICT_IDENTICAL) {
        item->result = RAYO_GRADE_PASS;
        return grade_say(item, err, "identical to the reference, pixel for "
                                    "pixel");
    }
    if (r->verdict == RAYO_VERDICT_CONSISTENT && r->scale_found > 1) {
        /* compare found the course's focal distance (diagnose.c) */
        item->result = RAYO_GRADE_PASS;
        return grade_say(item, err, "consistent with the reference: %llu "
                                    "pixels differ (%.3f%%), all within %g "
                                    "pixels of the sphere's outline, "
                                    "because your sphere is %.2f%% larger "
                                    "than the formula's, as in the course's "
                                    "own reference: z = ANCHO / (2 "
                                    "tan(FOV/2)) gives 320 and yours is "
                                    "about 321.5 (is PI sqrt(9.81)?)",
                         (unsigned long long)r->mismatches,
                         r->mismatch_percent, r->tolerance,
                         100 * (r->scale_found - 1));
    }
    if (r->verdict == RAYO_VERDICT_CONSISTENT && r->scale_found < 1) {
        item->result = RAYO_GRADE_PASS;
        return grade_say(item, err, "consistent with the reference: %llu "
                                    "pixels differ (%.3f%%), all within %g "
                                    "pixels of the sphere's outline, "
                                    "because the reference was drawn with "
                                    "the course's focal distance, z = 321.5 "
                                    "(pi as sqrt(9.81)), where the formula "
                                    "gives 320",
                         (unsigned long long)r->mismatches,
                         r->mismatch_percent, r->tolerance);
    }
    if (r->verdict == RAYO_VERDICT_CONSISTENT) {
        item->result = RAYO_GRADE_PASS;
        return grade_say(item, err, "consistent with the reference: %llu "
                                    "pixels differ (%.3f%%), all within %g "
                                    "pixels of the sphere's outline "
                                    "(rounding, float precision)",
                         (unsigned long long)r->mismatches,
                         r->mismatch_percent, r->tolerance);
    }
    status = grade_fail(item, err, "inconsistent with the reference: %llu "
                                   "pixels differ (%.2f%%), %llu of them "
                                   "more than %g pixels from the sphere's "
                                   "outline",
                        (unsigned long long)r->mismatches,
                        r->mismatch_percent,
                        (unsigned long long)r->beyond_tolerance,
                        r->tolerance);
    if (status == RAYO_OK)
        status = say_diagnosis(item, r, err);
    return status;
}

static rayo_status judge_tone(rayo_grade_item *item,
                              const rayo_compare_report *r, rayo_error *err)
{
    const rayo_compare_tone *t = &r->tone;
    char sentence[4096]; /* up to six findings of the scene */
    unsigned c, largest = 0;
    for (c = 0; c < t->channels; c++)
        if (t->channel[c].max_difference > largest)
            largest = t->channel[c].max_difference;
    if (r->verdict == RAYO_VERDICT_IDENTICAL && largest == 0) {
        item->result = RAYO_GRADE_PASS;
        return grade_say(item, err, "identical to the reference, pixel for "
                                    "pixel");
    }
    if (r->verdict == RAYO_VERDICT_IDENTICAL) {
        item->result = RAYO_GRADE_PASS;
        if (t->channels == 1)
            return grade_say(
                item, err,
                rayo_ngettext(rayo_error_lang(err),
                              "the same as the reference to within %u level "
                              "in every pixel (rounding, float precision)",
                              "the same as the reference to within %u levels "
                              "in every pixel (rounding, float precision)",
                              t->levels),
                t->levels);
        return grade_say(
            item, err,
            rayo_ngettext(rayo_error_lang(err),
                          "the same as the reference to within %u level in "
                          "every channel (rounding, float precision)",
                          "the same as the reference to within %u levels in "
                          "every channel (rounding, float precision)",
                          t->levels),
            t->levels);
    }
    if (r->verdict == RAYO_VERDICT_CONSISTENT) {
        item->result = RAYO_GRADE_PASS;
        return grade_say(
            item, err,
            rayo_ngettext(rayo_error_lang(err),
                          "consistent with the reference: %llu pixels differ "
                          "by more than %u level (%.3f%%), %llu at outlines "
                          "and shadow edges, %llu in shading within %g "
                          "pixels of the same value (rounding, float "
                          "precision, the focal distance)",
                          "consistent with the reference: %llu pixels differ "
                          "by more than %u levels (%.3f%%), %llu at outlines "
                          "and shadow edges, %llu in shading within %g "
                          "pixels of the same value (rounding, float "
                          "precision, the focal distance)",
                          t->levels),
                         (unsigned long long)t->differing, t->levels,
                         r->mismatch_percent,
                         (unsigned long long)t->at_edges,
                         (unsigned long long)t->in_shading, r->tolerance);
    }
    rayo_compare_format_diagnosis(r, sentence, sizeof sentence);
    if (t->unexplained == 0)
        return grade_fail(item, err, "every pixel is near what the "
                                     "reference shows, but %s",
                          sentence);
    {
        rayo_status status = grade_fail(
            item, err,
            rayo_ngettext(rayo_error_lang(err),
                          "inconsistent with the reference: %llu pixels "
                          "differ by more than %u level (%.2f%%), %llu of "
                          "them away from any outline or shadow edge and "
                          "from any pixel of the same value",
                          "inconsistent with the reference: %llu pixels "
                          "differ by more than %u levels (%.2f%%), %llu of "
                          "them away from any outline or shadow edge and "
                          "from any pixel of the same value",
                          t->levels),
            (unsigned long long)t->differing, t->levels, r->mismatch_percent,
            (unsigned long long)t->unexplained);
        if (status != RAYO_OK)
            return status;
        if (r->diagnosis == RAYO_DIAGNOSIS_NONE)
            return RAYO_OK;
        return grade_fail(item, err, "%s", sentence);
    }
}

/* The course's own references of the sphere and the gray scene were
   drawn with a focal distance about 0.47% longer than the formula's
   (z = 321.5 for 320, pi computed as sqrt(9.81)): when the scale that
   best lays one picture on the other is that, say which one follows
   the formula. */
#define COURSE_FOCAL_SCALE 1.0047

static rayo_status say_focal(rayo_grade_item *item,
                             const rayo_compare_report *r, rayo_error *err)
{
    double s = r->tone.scale_fit;
    if (r->kind != RAYO_COMPARE_TONE || s == 1)
        return RAYO_OK;
    if (fabs(1 / s - COURSE_FOCAL_SCALE) < 0.002)
        return grade_say(item, err, "note: the reference's picture is "
                                    "%.4f times yours about the centre: it "
                                    "was drawn with the course's focal "
                                    "distance, z = 321.5 (pi as sqrt(9.81)), "
                                    "where the formula gives 320; that is "
                                    "why outlines and shadow edges differ",
                         1 / s);
    if (fabs(s - COURSE_FOCAL_SCALE) < 0.002)
        return grade_say(item, err, "note: your picture is %.4f times the "
                                    "reference's about the centre: z = "
                                    "ANCHO / (2 tan(FOV/2)) gives 320, and "
                                    "yours is about 321.5, the course's own "
                                    "value (is PI sqrt(9.81)?)",
                         s);
    return RAYO_OK;
}

static rayo_status judge(rayo_grade_item *item, const rayo_compare_report *r,
                         rayo_error *err)
{
    rayo_status status = r->kind == RAYO_COMPARE_TONE
                             ? judge_tone(item, r, err)
                             : judge_mask(item, r, err);
    if (status == RAYO_OK && r->verdict != RAYO_VERDICT_INCONSISTENT)
        status = say_focal(item, r, err);
    return status;
}

static rayo_status write_diff(rayo_grade_item *item, const char *path,
                              const rayo_image *reference,
                              const rayo_image *image,
                              const rayo_compare_options *options,
                              int tone, rayo_error *err)
{
    rayo_output *out;
    rayo_status status = rayo_output_open(&out, path, err);
    if (status != RAYO_OK)
        return status;
    status = rayo_compare_write_diff(reference, image, options, out, err);
    if (status == RAYO_OK)
        status = rayo_output_commit(out, err);
    else
        rayo_output_abort(out);
    if (status != RAYO_OK)
        return status;
    if (tone)
        return grade_say(item, err, "difference picture: %s (your "
                                    "differences over the reference "
                                    "dimmed: amber where it explains them, "
                                    "red where nothing does)",
                         path);
    return grade_say(item, err, "difference picture: %s (red: black only "
                                "in the reference; blue: black only in "
                                "yours)",
                     path);
}

/* The statement's y in [-alto/2, alto/2) read literally runs the rows
   from y = 239 down to -240, one row above the course's own code (240
   down to -239); the course accepts that image for the exercises whose
   registry entry says so (literal_rows).  When the image fails
   against rayo's render but matches the literal reading, it passes with
   a note saying which reading it follows. */
static rayo_status try_literal_rows(grade_context *ctx,
                                    const rayo_image *image,
                                    const rayo_compare_options *options,
                                    rayo_compare_report *r, int *literal,
                                    rayo_error *err)
{
    const rayo_grade_exercise *e = ctx->options->exercise;
    const rayo_course_info *info = rayo_course_info_of(e->course);
    rayo_course_options co;
    rayo_image other;
    rayo_compare_report lr;
    rayo_status status;
    *literal = 0;
    if (ctx->options->reference != NULL || info == NULL ||
        !info->literal_rows || r->verdict != RAYO_VERDICT_INCONSISTENT)
        return RAYO_OK;
    rayo_course_options_init(&co);
    co.literal_rows = 1;
    status = rayo_course_render(e->course, &co, &other, err);
    if (status != RAYO_OK)
        return status;
    status = rayo_compare_images(&other, image, options, &lr, err);
    rayo_image_free(&other);
    if (status == RAYO_OK && lr.verdict != RAYO_VERDICT_INCONSISTENT) {
        *r = lr;
        *literal = 1;
    }
    return status;
}

rayo_status grade_step_image(grade_context *ctx, const rayo_image *image,
                             const rayo_image *reference, int salvaged,
                             rayo_error *err)
{
    rayo_grade_item *item = &ctx->report->items[RAYO_GRADE_IMAGE];
    rayo_compare_options options;
    rayo_compare_report r;
    rayo_status status;
    int literal = 0;
    rayo_compare_options_init(&options);
    options.lang = ctx->options->lang;
    options.course = (int)ctx->options->exercise->course;
    status = rayo_compare_images(reference, image, &options, &r, err);
    if (status == RAYO_OK)
        status = try_literal_rows(ctx, image, &options, &r, &literal, err);
    if (status != RAYO_OK)
        return status;
    ctx->report->verdict = malloc(strlen(rayo_compare_verdict_name(
                                      r.verdict)) + 1);
    if (ctx->report->verdict == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "grade: out of memory");
    strcpy(ctx->report->verdict, rayo_compare_verdict_name(r.verdict));
    status = judge(item, &r, err);
    if (status == RAYO_OK && literal)
        status = grade_say(item, err, "note: the rows run from y = %u down "
                                      "to -%u, the statement's y in "
                                      "[-alto/2, alto/2) read literally, so "
                                      "the picture is one row higher than "
                                      "the course's own program's, which "
                                      "runs them from %u down to -%u; the "
                                      "course accepts both",
                           ctx->options->exercise->height / 2 - 1,
                           ctx->options->exercise->height / 2,
                           ctx->options->exercise->height / 2,
                           ctx->options->exercise->height / 2 - 1);
    if (status == RAYO_OK && salvaged)
        status = grade_warn(item, err, "warning: the pixels were read as if "
                                      "the output's mistakes above were "
                                      "fixed");
    if (status == RAYO_OK && ctx->options->diff != NULL)
        status = write_diff(item, ctx->options->diff, reference, image,
                            &options, r.kind == RAYO_COMPARE_TONE, err);
    return status;
}
