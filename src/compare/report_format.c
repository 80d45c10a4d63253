/*
 * report_format.c - a comparison report as text for a student or as JSON
 * for a program.
 *
 * Both forms carry the same numbers; the text adds a sentence saying what
 * the diagnosis means and what to look at in one's code.  Writing goes
 * into the caller's buffer with snprintf semantics (the full length is
 * returned, the text is cut to fit), so the library never prints.  The
 * text is in the report's language (cmp_put looks each sentence up);
 * the JSON always in English (cmp_json), for programs.
 */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "compare_impl.h"
#include "report_sink.h"
#include "tone/tone_impl.h"

/* Appends text (already formatted) as snprintf would: counted whole,
   cut to the room left. */
static void append(cmp_sink *s, const char *text)
{
    size_t n = strlen(text);
    size_t room = s->length < s->size ? s->size - s->length : 0;
    if (room > 0) {
        size_t fit = n < room - 1 ? n : room - 1;
        memcpy(s->buffer + s->length, text, fit);
        s->buffer[s->length + fit] = '\0';
    }
    s->length += n;
}

/* A sentence of the report is well under this (the longest, a course
   mistake's, is some 300 bytes). */
#define CMP_SENTENCE_MAX 4096

static void put_translated(cmp_sink *s, const char *format, va_list ap)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 2, 0)))
#endif
    ;
static void put_translated(cmp_sink *s, const char *format, va_list ap)
{
    char text[CMP_SENTENCE_MAX];
    rayo_lang_vformat(s->lang, text, sizeof text, format, ap);
    append(s, text);
}

void cmp_put(cmp_sink *s, const char *format, ...)
{
    va_list ap;
    va_start(ap, format);
    put_translated(s, format, ap);
    va_end(ap);
}

void cmp_putn(cmp_sink *s, unsigned long long count, const char *singular,
              const char *plural, ...)
{
    va_list ap;
    va_start(ap, plural);
    /* already translated: looking it up again finds nothing and keeps it */
    put_translated(s, rayo_ngettext(s->lang, singular, plural,
                                    (unsigned long)count), ap);
    va_end(ap);
}

void cmp_json(cmp_sink *s, const char *format, ...)
{
    va_list ap;
    int n;
    size_t room = s->length < s->size ? s->size - s->length : 0;
    va_start(ap, format);
    n = vsnprintf(room ? s->buffer + s->length : NULL, room, format, ap);
    va_end(ap);
    if (n > 0)
        s->length += (size_t)n;
}

/* The note about pixels beyond a raster, for each file that had any. */
static void put_surplus(cmp_sink *s, int reference, uint64_t pixels,
                        uint32_t width)
{
    unsigned long long n = pixels;
    if (pixels == 0)
        return;
    if (reference)
        cmp_putn(s, n, "note: the reference's file holds %llu pixel beyond "
                       "the raster its header promises",
                 "note: the reference's file holds %llu pixels beyond the "
                 "raster its header promises", n);
    else
        cmp_putn(s, n, "note: the image's file holds %llu pixel beyond the "
                       "raster its header promises",
                 "note: the image's file holds %llu pixels beyond the "
                 "raster its header promises", n);
    if (width > 0 && pixels % width == 0)
        cmp_putn(s, n / width, " (%llu more row)", " (%llu more rows)",
                 n / width);
    cmp_put(s, "; they were not compared\n");
}

double cmp_band_percent(unsigned long long differences,
                        unsigned long long band)
{
    return band ? 100.0 * (double)differences / (double)band : 0;
}

void cmp_put_crowded_json(cmp_sink *s, const rayo_compare_report *r)
{
    if (r->crowded)
        cmp_json(s, ", \"band\": %llu, \"crowded\": true",
            (unsigned long long)r->band);
}

/* How the image's file departs from what the course hands in. */
static void put_file_json(cmp_sink *s, const rayo_compare_report *r)
{
    if (r->image_lossy_levels == 0 && r->image_bmp_bits == 0 &&
        !r->image_bmp_top_down && !r->image_bmp_unpadded)
        return;
    cmp_json(s, ", \"image_file\": {\"lossy_levels\": %u, \"bmp_bits\": %u, "
               "\"bmp_top_down\": %s, \"bmp_unpadded\": %s}",
            r->image_lossy_levels, r->image_bmp_bits,
            r->image_bmp_top_down ? "true" : "false",
            r->image_bmp_unpadded ? "true" : "false");
}

void cmp_put_clamped_json(cmp_sink *s, const rayo_compare_report *r)
{
    cmp_put_kinds_json(s, r);
    put_file_json(s, r);
    if (r->image_clamped_high + r->image_clamped_low == 0)
        return;
    cmp_json(s, ", \"image_clamped\": {\"high\": %llu, \"low\": %llu, "
               "\"largest\": %ld, \"smallest\": %ld}",
        (unsigned long long)r->image_clamped_high,
        (unsigned long long)r->image_clamped_low, r->image_largest,
        r->image_smallest);
}

void cmp_put_out_of_range(cmp_sink *s, const rayo_compare_report *r)
{
    if (r->image_clamped_high > 0) {
        cmp_putn(s, r->image_clamped_high,
                 "%llu sample above the maximum (the first on line %llu, "
                 "the largest %ld): ",
                 "%llu samples above the maximum (the first on line %llu, "
                 "the largest %ld): ",
                 (unsigned long long)r->image_clamped_high,
                 (unsigned long long)r->image_first_high_line,
                 r->image_largest);
        if (r->image_largest == 256)
            cmp_put(s, "0..1 scaled by 256 instead of 255, or ");
        cmp_put(s, "values not clamped: the statements say values above 255 "
                   "become 255 (each channel above 1 becomes 1)");
    }
    if (r->image_clamped_low > 0 && r->image_clamped_high > 0)
        cmp_json(s, "; ");
    if (r->image_clamped_low > 0)
        cmp_putn(s, r->image_clamped_low,
                 "%llu negative sample (the first on line %llu, the "
                 "smallest %ld): a negative intensity, the diffuse term "
                 "added where L.N < 0; the statements add it only when L.N "
                 "> 0",
                 "%llu negative samples (the first on line %llu, the "
                 "smallest %ld): a negative intensity, the diffuse term "
                 "added where L.N < 0; the statements add it only when L.N "
                 "> 0",
                 (unsigned long long)r->image_clamped_low,
                 (unsigned long long)r->image_first_low_line,
                 r->image_smallest);
}

void cmp_put_surplus(char *buffer, size_t size, size_t *length,
                     const rayo_compare_report *r)
{
    cmp_sink s;
    s.buffer = buffer;
    s.size = size;
    s.lang = r->lang;
    s.length = *length;
    cmp_put_kinds(&s, r);
    put_surplus(&s, 1, r->reference_surplus, r->reference_width);
    put_surplus(&s, 0, r->image_surplus, r->image_width);
    if (r->image_clamped_high + r->image_clamped_low > 0 &&
        r->diagnosis != RAYO_DIAGNOSIS_OUT_OF_RANGE) {
        cmp_put(&s, "note: the image was compared with its samples clamped to "
                    "0..maxval: ");
        cmp_put_out_of_range(&s, r);
        cmp_json(&s, "\n");
    }
    if (r->image_lossy_levels > 0)
        cmp_put(&s, "note: the image is a JPEG, which is lossy: values were "
                    "compared within %u levels (of 255) to allow for its "
                    "artifacts, and bilevel pictures as black where darker "
                    "than half; hand in PNG or the statement's format\n",
                r->image_lossy_levels);
    if (r->image_bmp && !r->image_bmp_top_down &&
        r->diagnosis == RAYO_DIAGNOSIS_FLIPPED_VERTICALLY)
        cmp_put(&s, "note: a BMP with a positive height, as the course's "
                    "layout has it, stores its rows bottom up: the picture's "
                    "last row first\n");
    if (r->image_bmp_top_down)
        cmp_put(&s, "note: the BMP's rows are stored top down (a negative "
                    "height); the course's layout stores them bottom up, "
                    "with a positive height\n");
    if (r->image_bmp_unpadded)
        cmp_put(&s, "note: the BMP's rows are not padded to a multiple of 4 "
                    "bytes, as the format and the course's layout ask; read "
                    "as written because the file's size says so, but other "
                    "programs show it slanted\n");
    if (r->image_bmp_bits > 0)
        cmp_put(&s, "note: the BMP has %u bits a pixel; the course's layout "
                    "has 24 (B, G, R)\n",
                r->image_bmp_bits);
    *length = s.length;
}

void cmp_put_verdict(cmp_sink *s, int verdict)
{
    switch (verdict) {
    case RAYO_VERDICT_IDENTICAL:
        cmp_put(s, "verdict: identical\n");
        break;
    case RAYO_VERDICT_CONSISTENT:
        cmp_put(s, "verdict: consistent\n");
        break;
    default:
        cmp_put(s, "verdict: inconsistent\n");
        break;
    }
}

/* One sentence (no quotes, no backslashes) saying what went wrong. */
static void put_diagnosis(cmp_sink *s, const rayo_compare_report *r)
{
    if (!r->diagnosis_exact && r->diagnosis <= RAYO_DIAGNOSIS_SCALED &&
        r->diagnosis != RAYO_DIAGNOSIS_NONE)
        cmp_put(s, "most likely (undoing it comes close, not exact): ");
    switch (r->diagnosis) {
    case RAYO_DIAGNOSIS_NONE:
        cmp_put(s, "none");
        break;
    case RAYO_DIAGNOSIS_FLIPPED_VERTICALLY:
        cmp_put(s, "the image is upside down (flipped vertically): rows "
                   "written from the bottom up, or y not negated in the ray "
                   "direction");
        break;
    case RAYO_DIAGNOSIS_FLIPPED_HORIZONTALLY:
        cmp_put(s, "the image is mirrored left to right (flipped "
                   "horizontally): columns written from the right, or x "
                   "negated");
        break;
    case RAYO_DIAGNOSIS_ROTATED_180:
        cmp_put(s, "the image is upside down and mirrored (flipped both ways, "
                   "a half turn)");
        break;
    case RAYO_DIAGNOSIS_INVERTED:
        cmp_put(s, "the colours are inverted (0 and 1 swapped): in PBM 1 is "
                   "black, and a ray that hits the sphere is black");
        break;
    case RAYO_DIAGNOSIS_TRANSPOSED:
        cmp_put(s, "the image is transposed (width and height swapped): rows "
                   "written as columns");
        break;
    case RAYO_DIAGNOSIS_SHIFTED:
        cmp_put(s, "the picture is shifted by (%+d, %+d) pixels (right, "
                   "down): check the pixel grid, x = i - w/2 and y = j - h/2",
            r->shift_x, r->shift_y);
        break;
    case RAYO_DIAGNOSIS_SCALED:
        cmp_put(s, "the shape is scaled by %.3f about the centre of the "
                   "image: a wrong field of view or focal distance (z = w / "
                   "(2 tan(fov/2)), fov in radians)", r->scale_found);
        break;
    case RAYO_DIAGNOSIS_DIFFERENT_SIZE:
        cmp_put(s, "the image is %ux%u but the reference is %ux%u: check the "
                   "width and height (ANCHO, ALTO)",
            r->image_width, r->image_height, r->reference_width,
            r->reference_height);
        break;
    case RAYO_DIAGNOSIS_EMPTY:
        cmp_put(s, "the image has no black pixel: no ray hit the sphere");
        break;
    case RAYO_DIAGNOSIS_NOT_A_SPHERE:
        cmp_put(s, "the black region is not an ellipse-shaped blob: this does "
                   "not look like a picture of a sphere");
        break;
    case RAYO_DIAGNOSIS_OTHER_SPHERE:
        cmp_put(s, "a sphere, but not the reference's: its shape is offset by "
                   "(%+.1f, %+.1f) pixels and %.3f times the size; check the "
                   "sphere's centre and radius",
            r->offset_x, r->offset_y, r->scale);
        break;
    case RAYO_DIAGNOSIS_OUT_OF_RANGE:
        cmp_put_out_of_range(s, r);
        break;
    default:
        cmp_put(s, "no single mistake (flip, inversion, transposition, shift, "
                   "scale) explains the differences");
        break;
    }
}

/* A consistent picture whose mismatches the course's focal distance
   explains (mask/diagnose.c: scale_found, about 1.0048 or its inverse). */
static void put_focal_text(cmp_sink *s, const rayo_compare_report *r)
{
    if (r->verdict != RAYO_VERDICT_CONSISTENT || r->scale_found == 1)
        return;
    if (r->scale_found > 1)
        cmp_put(s, "note: the image is the reference enlarged %.4f times "
                   "about the centre (the sphere %.2f%% larger): it was drawn "
                   "with the course's focal distance, z = 321.5 (pi computed "
                   "as sqrt(9.81)), where ANCHO / (2 tan(FOV/2)) gives 320; "
                   "that, not rounding, is why the outlines differ\n",
            r->scale_found, 100 * (r->scale_found - 1));
    else
        cmp_put(s, "note: the reference is the image enlarged %.4f times "
                   "about the centre: the reference was drawn with the "
                   "course's focal distance, z = 321.5 (pi computed as "
                   "sqrt(9.81)), where ANCHO / (2 tan(FOV/2)) gives 320; "
                   "that, not rounding, is why the outlines differ\n",
            1 / r->scale_found);
}

/* Why mismatches all within the tolerance are not consistent. */
static void put_crowded_text(cmp_sink *s, const rayo_compare_report *r)
{
    double chance = cmp_chance_mismatches(r->pixels, r->reference_black,
                                          r->image_black);
    if (!r->crowded)
        return;
    if (cmp_crowded(r->mismatches, r->band))
        cmp_put(s, "note: every mismatch is within %g px of the reference's "
                   "outline, but they are %.1f%% of the %llu pixels within "
                   "that distance of it (an outline drawn a pixel or two "
                   "apart changes about half of them at most; the limit is "
                   "%.0f%%): the shapes disagree\n",
            r->tolerance, cmp_band_percent(r->mismatches, r->band),
            (unsigned long long)r->band, 100 * RAYO_COMPARE_BAND_SHARE);
    else if ((double)r->mismatches >= chance)
        cmp_put(s, "note: every mismatch is within %g px of the reference's "
                   "outline, but there are as many as between black pixels "
                   "placed at random (%.0f): the shapes disagree\n",
            r->tolerance, chance);
    else
        cmp_put(s, "note: every mismatch is within %g px of the reference's "
                   "outline, but there are more than half as many as "
                   "between black pixels placed at random (%llu of %.0f; "
                   "the shapes agreeing would leave at most %.0f%%): the "
                   "shapes disagree\n",
            r->tolerance, (unsigned long long)r->mismatches, chance,
            100 * CMP_CHANCE_SHARE);
}

static void put_distance_text(cmp_sink *s, const rayo_compare_report *r)
{
    if (r->max_distance < 0)
        cmp_put(s, "farthest mismatch from the reference's outline: - (the "
                   "reference is all one colour)\n");
    else
        cmp_put(s, "farthest mismatch from the reference's outline: %.2f px "
                   "(tolerance %g px; %llu beyond it)\n",
            r->max_distance, r->tolerance,
            (unsigned long long)r->beyond_tolerance);
}

size_t rayo_compare_format_text(const rayo_compare_report *r, char *buffer,
                                size_t size)
{
    cmp_sink s = {buffer, size, 0, r->lang};
    if (size > 0)
        buffer[0] = '\0';
    if (r->kind == RAYO_COMPARE_TONE) {
        cmp_sink t = {buffer, size, 0, r->lang};
        tone_format_text(r, &t);
        cmp_put_surplus(buffer, size, &t.length, r);
        return t.length;
    }
    cmp_put(&s, "reference: %ux%u, %llu black pixels\n",
        r->reference_width, r->reference_height,
        (unsigned long long)r->reference_black);
    cmp_put(&s, "image:     %ux%u, %llu black pixels\n",
        r->image_width, r->image_height, (unsigned long long)r->image_black);
    cmp_put(&s, "mismatched pixels: %llu of %llu (%.3f%%): %llu black only in "
                "the reference, %llu black only in the image\n",
        (unsigned long long)r->mismatches, (unsigned long long)r->pixels,
        r->mismatch_percent, (unsigned long long)r->reference_only,
        (unsigned long long)r->image_only);
    cmp_put(&s, "IoU of the black regions: %.4f\n", r->iou);
    put_distance_text(&s, r);
    if (r->shapes_measured)
        cmp_put(&s, "black shape of the image vs the reference: offset "
                    "(%+.2f, %+.2f) px (right, down), scale %.4f\n",
            r->offset_x, r->offset_y, r->scale);
    else
        cmp_put(&s, "black shape of the image vs the reference: - (one of "
                    "them has no black pixel)\n");
    put_crowded_text(&s, r);
    put_focal_text(&s, r);
    cmp_put_verdict(&s, r->verdict);
    if (r->diagnosis != RAYO_DIAGNOSIS_NONE) {
        cmp_put(&s, "diagnosis: ");
        put_diagnosis(&s, r);
        cmp_json(&s, "\n");
    }
    cmp_put_surplus(buffer, size, &s.length, r);
    return s.length;
}

size_t rayo_compare_format_json(const rayo_compare_report *r, char *buffer,
                                size_t size)
{
    cmp_sink s = {buffer, size, 0, RAYO_LANG_EN};
    if (size > 0)
        buffer[0] = '\0';
    if (r->kind == RAYO_COMPARE_TONE) {
        cmp_sink t = {buffer, size, 0, RAYO_LANG_EN};
        tone_format_json(r, &t);
        return t.length;
    }
    cmp_json(&s, "{\"reference\": {\"width\": %u, \"height\": %u, \"black\": "
                "%llu}, \"image\": {\"width\": %u, \"height\": %u, \"black\": "
                "%llu}",
        r->reference_width, r->reference_height,
        (unsigned long long)r->reference_black, r->image_width,
        r->image_height, (unsigned long long)r->image_black);
    cmp_json(&s, ", \"pixels\": %llu, \"mismatches\": %llu, "
                "\"reference_only\": %llu, \"image_only\": %llu, "
                "\"mismatch_percent\": %.6f, \"iou\": %.6f",
        (unsigned long long)r->pixels, (unsigned long long)r->mismatches,
        (unsigned long long)r->reference_only,
        (unsigned long long)r->image_only, r->mismatch_percent, r->iou);
    if (r->max_distance < 0)
        cmp_json(&s, ", \"max_distance\": null");
    else
        cmp_json(&s, ", \"max_distance\": %.6f", r->max_distance);
    cmp_json(&s, ", \"tolerance\": %.6g, \"beyond_tolerance\": %llu",
        r->tolerance, (unsigned long long)r->beyond_tolerance);
    cmp_put_crowded_json(&s, r);
    if (r->shapes_measured)
        cmp_json(&s, ", \"offset\": {\"x\": %.6f, \"y\": %.6f}, "
                    "\"scale\": %.6f",
            r->offset_x, r->offset_y, r->scale);
    else
        cmp_json(&s, ", \"offset\": null, \"scale\": null");
    if (r->reference_surplus != 0 || r->image_surplus != 0)
        cmp_json(&s, ", \"reference_surplus\": %llu, \"image_surplus\": %llu",
            (unsigned long long)r->reference_surplus,
            (unsigned long long)r->image_surplus);
    cmp_put_clamped_json(&s, r);
    cmp_json(&s, ", \"verdict\": \"%s\", \"diagnosis\": {\"kind\": \"%s\", "
                "\"exact\": %s",
        rayo_compare_verdict_name(r->verdict),
        rayo_compare_diagnosis_name(r->diagnosis),
        r->diagnosis_exact ? "true" : "false");
    if (r->diagnosis == RAYO_DIAGNOSIS_SHIFTED)
        cmp_json(&s, ", \"shift\": {\"x\": %d, \"y\": %d}",
            r->shift_x, r->shift_y);
    if (r->diagnosis == RAYO_DIAGNOSIS_SCALED)
        cmp_json(&s, ", \"scale\": %.6f", r->scale_found);
    cmp_json(&s, ", \"text\": \"");
    put_diagnosis(&s, r);
    cmp_json(&s, "\"}}\n");
    return s.length;
}

size_t rayo_compare_format_diagnosis(const rayo_compare_report *r,
                                     char *buffer, size_t size)
{
    cmp_sink s = {buffer, size, 0, r->lang};
    if (size > 0)
        buffer[0] = '\0';
    if (r->kind == RAYO_COMPARE_TONE) {
        cmp_sink t = {buffer, size, 0, r->lang};
        tone_put_diagnosis(r, &t);
        return t.length;
    }
    put_diagnosis(&s, r);
    return s.length;
}
