/*
 * tone_format.c - a tone comparison's report as text for a student and
 * as JSON for a program (the mask report's forms: report_format.c).
 *
 * Both carry the same numbers; the text says in words where the
 * differences lie, why the outlines of a correct image may differ from
 * the course's references (their focal distance), and what the
 * diagnosed mistake is in the student's terms.  Sentences hold no
 * double quote and no backslash, so they go into JSON as they are.
 */
#include <math.h>

#include "../report_sink.h"
#include "tone_impl.h"

static const char *channel_name(const rayo_compare_tone *t, unsigned c)
{
    static const char *const rgb[3] = {"red", "green", "blue"};
    return t->channels == 1 ? "gray" : rgb[c];
}

/* A channel's name as the text's rows show it. */
static const char *channel_words(const cmp_sink *s,
                                 const rayo_compare_tone *t, unsigned c)
{
    switch (t->channels == 1 ? 3 : c) {
    case 0: return rayo_gettext(s->lang, "red");
    case 1: return rayo_gettext(s->lang, "green");
    case 2: return rayo_gettext(s->lang, "blue");
    default: return rayo_gettext(s->lang, "gray");
    }
}

/* The focal distance the course's references were drawn with: about
   0.47% longer than the formula's (pi taken as sqrt(9.81)). */
static int looks_like_course_focal(const rayo_compare_report *r)
{
    return r->reference_width == 640 &&
           fabs(1.0 / r->tone.scale_fit - 1.0047) < 0.002;
}

static void put_scale(cmp_sink *s, const rayo_compare_report *r)
{
    const rayo_compare_tone *t = &r->tone;
    double larger = 1.0 / t->scale_fit;
    if (t->scale_fit == 1)
        return;
    if (larger > 1)
        cmp_put(s, "scale: the reference is this picture enlarged %.4f times "
                   "about the centre (%llu pixels differ then, not %llu): its "
                   "focal distance is about %.2f%% longer",
                larger, (unsigned long long)t->differing_scaled,
                (unsigned long long)t->differing, fabs(larger - 1) * 100);
    else
        cmp_put(s, "scale: the reference is this picture shrunk %.4f times "
                   "about the centre (%llu pixels differ then, not %llu): its "
                   "focal distance is about %.2f%% shorter",
                larger, (unsigned long long)t->differing_scaled,
                (unsigned long long)t->differing, fabs(larger - 1) * 100);
    if (looks_like_course_focal(r))
        cmp_put(s, "; at 640 pixels and 90 degrees the formula gives z = 320 "
                   "and the reference was most likely drawn with z = 321.5, "
                   "as the course's references for EJ1 and EJ2 were: that is "
                   "why outlines and shadow edges differ");
    cmp_json(s, "\n");
}

static const char *flip_text(rayo_lang lang, rayo_compare_diagnosis d)
{
    switch (d) {
    case RAYO_DIAGNOSIS_FLIPPED_VERTICALLY:
        return rayo_gettext(lang, "the image is upside down: rows must run from the top (y = "
               "ALTO/2) down, and the direction is (x, y, z) with y "
               "decreasing down the picture");
    case RAYO_DIAGNOSIS_FLIPPED_HORIZONTALLY:
        return rayo_gettext(lang, "the image is mirrored left to right: columns must run from "
               "x = -ANCHO/2 to the right");
    case RAYO_DIAGNOSIS_ROTATED_180:
        return rayo_gettext(lang, "the image is upside down and mirrored (a half turn)");
    case RAYO_DIAGNOSIS_INVERTED:
        return rayo_gettext(lang, "the values are inverted (255 - v): 0 is black, 255 white, "
               "and a ray that hits nothing is black");
    case RAYO_DIAGNOSIS_EMPTY:
        return rayo_gettext(lang, "the image is all black: no ray lights anything");
    case RAYO_DIAGNOSIS_WRAPPED:
        return "values past 255 wrapped around to small numbers where the "
               "reference is at its brightest (255): the value was stored "
               "in an unsigned char before being clamped; clamp to 255 "
               "first";
    default:
        return NULL;
    }
}

static void put_channels(cmp_sink *s, const rayo_compare_tone *t)
{
    rayo_compare_tone rgb = *t;
    rgb.channels = 3;
    cmp_put(s, "the colour channels are in another order: the image's red, "
               "green and blue show the reference's %s, %s and %s; print R G "
               "B in that order (color_imprimir)",
        channel_words(s, &rgb, t->order[0]), channel_words(s, &rgb, t->order[1]),
        channel_words(s, &rgb, t->order[2]));
}

static void put_offset(cmp_sink *s, const rayo_compare_tone *t)
{
    unsigned c;
    if (t->offset_on_shapes)
        cmp_put(s, "every pixel of the objects (not the background) is off "
                   "by a constant: ");
    else
        cmp_put(s, "every pixel is off by a constant: ");
    for (c = 0; c < t->channels; c++)
        cmp_json(s, "%s%+d", c ? ", " : "", t->offset[c]);
    cmp_putn(s,
        t->channels == 1 && (t->offset[0] == 1 || t->offset[0] == -1) ? 1 : 2,
        " level", " levels");
    if (t->offset_on_shapes && t->offset[0] < 0)
        cmp_put(s, " (darker): is the ambient term missing (IA in I = IA + II "
                   "(L.N), Ia ka in C = Ia ka + ...)?");
    else if (t->offset_on_shapes)
        cmp_put(s, " (brighter): is the ambient term too large or added "
                   "twice?");
    else
        cmp_put(s, ": a constant added to or missing from every value");
}

/* "the picture is moved 3 pixels left and 1 row down" */
static void put_moved(cmp_sink *s, int x, int y)
{
    unsigned long ax = (unsigned long)(x < 0 ? -x : x);
    unsigned long ay = (unsigned long)(y < 0 ? -y : y);
    cmp_put(s, "the picture is moved ");
    if (x < 0)
        cmp_putn(s, ax, "%lu pixel left", "%lu pixels left", ax);
    else if (x > 0)
        cmp_putn(s, ax, "%lu pixel right", "%lu pixels right", ax);
    if (x != 0 && y != 0)
        cmp_put(s, " and ");
    if (y < 0)
        cmp_putn(s, ay, "%lu row up", "%lu rows up", ay);
    else if (y > 0)
        cmp_putn(s, ay, "%lu row down", "%lu rows down", ay);
}

void tone_put_diagnosis(const rayo_compare_report *r, cmp_sink *s)
{
    const rayo_compare_tone *t = &r->tone;
    const char *text = flip_text(s->lang, r->diagnosis);
    if (!r->diagnosis_exact && r->diagnosis != RAYO_DIAGNOSIS_NONE &&
        r->diagnosis != RAYO_DIAGNOSIS_DIFFERENT_SIZE &&
        r->diagnosis != RAYO_DIAGNOSIS_EMPTY &&
        r->diagnosis != RAYO_DIAGNOSIS_UNKNOWN &&
        r->diagnosis != RAYO_DIAGNOSIS_SCENE)
        cmp_put(s, "most likely (undoing it comes close, not exact): ");
    if (text != NULL) {
        cmp_json(s, "%s", text);
        return;
    }
    switch (r->diagnosis) {
    case RAYO_DIAGNOSIS_NONE:
        cmp_put(s, "none");
        break;
    case RAYO_DIAGNOSIS_OUT_OF_RANGE:
        cmp_put_out_of_range(s, r);
        break;
    case RAYO_DIAGNOSIS_MISTAKE:
        cmp_json(s, "%s",
            rayo_course_mistake_text_lang((rayo_course_exercise)t->course,
                                          t->mistake, s->lang));
        break;
    case RAYO_DIAGNOSIS_CHANNELS_SWAPPED:
        put_channels(s, t);
        break;
    case RAYO_DIAGNOSIS_OFFSET:
        put_offset(s, t);
        break;
    case RAYO_DIAGNOSIS_SHIFTED:
        put_moved(s, r->shift_x, r->shift_y);
        cmp_put(s, ": check the pixel grid, x = i - ANCHO/2 and rows from y = "
                   "ALTO/2 at the top");
        break;
    case RAYO_DIAGNOSIS_SCALED:
        cmp_put(s, "the picture is scaled by %.3f about the centre: a wrong "
                   "field of view or focal distance (z = ANCHO / (2 "
                   "tan(FOV/2)), FOV in radians)", r->scale_found);
        break;
    case RAYO_DIAGNOSIS_DIFFERENT_SIZE:
        cmp_put(s, "the image is %ux%u but the reference is %ux%u: check the "
                   "width and height (ANCHO, ALTO)",
            r->image_width, r->image_height, r->reference_width,
            r->reference_height);
        break;
    case RAYO_DIAGNOSIS_SCENE:
        tone_put_findings(r, s);
        break;
    default:
        if (t->findings > 0) { /* where they lie, on the course's scene */
            cmp_put(s, "no single mistake explains the differences: ");
            tone_put_findings(r, s);
        } else if (t->first_x < 0) /* crowded: nothing unexplained */
            cmp_put(s, "no single mistake explains the differences, and "
                       "there are too many of them for one picture drawn a "
                       "pixel or two apart");
        else
            cmp_put(s, "no single mistake explains the differences; the "
                       "first unexplained pixel is column %d, row %d",
                (int)t->first_x, (int)t->first_y);
        break;
    }
}

void tone_format_text(const rayo_compare_report *r, cmp_sink *s)
{
    const rayo_compare_tone *t = &r->tone;
    unsigned c;
    if (t->reference_channels == 1)
        cmp_put(s, "reference: %ux%u, gray\n", r->reference_width,
                r->reference_height);
    else
        cmp_put(s, "reference: %ux%u, colour\n", r->reference_width,
                r->reference_height);
    if (t->image_channels == 1)
        cmp_put(s, "image:     %ux%u, gray\n", r->image_width,
                r->image_height);
    else
        cmp_put(s, "image:     %ux%u, colour\n", r->image_width,
                r->image_height);
    if (t->channels == 1)
        cmp_putn(s, t->levels,
                 "compared:  gray values; a pixel differs when off by more "
                 "than %u level (of 255)\n",
                 "compared:  gray values; a pixel differs when off by more "
                 "than %u levels (of 255)\n", t->levels);
    else
        cmp_putn(s, t->levels,
                 "compared:  RGB values; a pixel differs when off by more "
                 "than %u level (of 255)\n",
                 "compared:  RGB values; a pixel differs when off by more "
                 "than %u levels (of 255)\n", t->levels);
    for (c = 0; c < t->channels; c++) {
        const rayo_compare_channel *ch = &t->channel[c];
        cmp_put(s, "%-6s %llu pixels off (%.3f%%), largest difference %u, "
                   "RMSE %.3f, ",
            channel_words(s, t, c), (unsigned long long)ch->beyond,
            r->pixels ? 100.0 * (double)ch->beyond / (double)r->pixels : 0,
            ch->max_difference, ch->rmse);
        if (isinf(ch->psnr))
            cmp_put(s, "PSNR infinite\n");
        else
            cmp_put(s, "PSNR %.2f dB\n", ch->psnr);
    }
    cmp_put(s, "differing pixels: %llu of %llu (%.3f%%): %llu at outlines and "
               "shadow edges (largest difference %u), %llu in shading where "
               "the reference takes their value within %g px, %llu "
               "unexplained\n",
        (unsigned long long)t->differing, (unsigned long long)r->pixels,
        r->mismatch_percent, (unsigned long long)t->at_edges,
        t->max_edge_difference, (unsigned long long)t->in_shading,
        r->tolerance, (unsigned long long)t->unexplained);
    put_scale(s, r);
    if (r->verdict == RAYO_VERDICT_CONSISTENT && t->at_edges > 0)
        cmp_put(s, "note: the differences at outlines and shadow edges are "
                   "the same picture drawn a pixel or two apart there "
                   "(another focal distance, float instead of double), not a "
                   "mistake\n");
    if (r->crowded)
        cmp_put(s, "note: every differing pixel is explained, but they are "
                   "%.1f%% of the %llu pixels near an edge or in shading that "
                   "varies within %g px (a picture drawn a pixel or two apart "
                   "changes about half of them at most; the limit is %.0f%%): "
                   "the pictures disagree\n",
            cmp_band_percent(t->differing, r->band),
            (unsigned long long)r->band, r->tolerance,
            100 * RAYO_COMPARE_BAND_SHARE);
    cmp_put_verdict(s, r->verdict);
    if (r->diagnosis != RAYO_DIAGNOSIS_NONE) {
        cmp_put(s, "diagnosis: ");
        tone_put_diagnosis(r, s);
        cmp_json(s, "\n");
    }
}

static void put_number(cmp_sink *s, double v)
{
    if (isfinite(v))
        cmp_json(s, "%.6f", v);
    else
        cmp_json(s, "null");
}

void tone_format_json(const rayo_compare_report *r, cmp_sink *s)
{
    const rayo_compare_tone *t = &r->tone;
    unsigned c;
    cmp_json(s, "{\"kind\": \"tone\", \"reference\": {\"width\": %u, "
               "\"height\": %u, \"channels\": %u}, \"image\": {\"width\": %u, "
               "\"height\": %u, \"channels\": %u}, \"pixels\": %llu, "
               "\"levels\": %u, \"tolerance\": %.6g, \"channels\": [",
        r->reference_width, r->reference_height, t->reference_channels,
        r->image_width, r->image_height, t->image_channels,
        (unsigned long long)r->pixels, t->levels, r->tolerance);
    for (c = 0; c < t->channels; c++) {
        const rayo_compare_channel *ch = &t->channel[c];
        cmp_json(s, "%s{\"name\": \"%s\", \"beyond\": %llu, "
                   "\"max_difference\": %u, \"rmse\": %.6f, \"psnr\": ",
            c ? ", " : "", channel_name(t, c), (unsigned long long)ch->beyond,
            ch->max_difference, ch->rmse);
        put_number(s, ch->psnr);
        cmp_json(s, "}");
    }
    cmp_json(s, "], \"differing\": %llu, \"mismatches\": %llu, "
               "\"mismatch_percent\": %.6f, \"at_edges\": %llu, "
               "\"max_edge_difference\": %u, \"in_shading\": %llu, "
               "\"unexplained\": %llu, \"beyond_tolerance\": %llu",
        (unsigned long long)t->differing, (unsigned long long)r->mismatches,
        r->mismatch_percent, (unsigned long long)t->at_edges,
        t->max_edge_difference, (unsigned long long)t->in_shading,
        (unsigned long long)t->unexplained,
        (unsigned long long)r->beyond_tolerance);
    cmp_put_crowded_json(s, r);
    if (t->first_x >= 0)
        cmp_json(s, ", \"first_unexplained\": {\"x\": %d, \"y\": %d}",
            (int)t->first_x, (int)t->first_y);
    else
        cmp_json(s, ", \"first_unexplained\": null");
    cmp_json(s, ", \"reference_surplus\": %llu, \"image_surplus\": %llu",
        (unsigned long long)r->reference_surplus,
        (unsigned long long)r->image_surplus);
    cmp_put_clamped_json(s, r);
    cmp_json(s, ", \"scale_fit\": %.6f, \"differing_scaled\": %llu, "
               "\"course\": ",
        t->scale_fit, (unsigned long long)t->differing_scaled);
    if (t->course >= 0)
        cmp_json(s, "\"%s\"",
            rayo_course_name((rayo_course_exercise)t->course));
    else
        cmp_json(s, "null");
    cmp_json(s, ", \"verdict\": \"%s\", \"diagnosis\": {\"kind\": \"%s\", "
               "\"exact\": %s",
        rayo_compare_verdict_name(r->verdict),
        rayo_compare_diagnosis_name(r->diagnosis),
        r->diagnosis_exact ? "true" : "false");
    if (r->diagnosis == RAYO_DIAGNOSIS_MISTAKE)
        cmp_json(s, ", \"mistake\": \"%s\"",
            rayo_course_mistake_name(t->mistake));
    if (r->diagnosis == RAYO_DIAGNOSIS_SHIFTED)
        cmp_json(s, ", \"shift\": {\"x\": %d, \"y\": %d}",
            r->shift_x, r->shift_y);
    if (r->diagnosis == RAYO_DIAGNOSIS_SCALED)
        cmp_json(s, ", \"scale\": %.6f", r->scale_found);
    if (r->diagnosis == RAYO_DIAGNOSIS_CHANNELS_SWAPPED)
        cmp_json(s, ", \"order\": [%u, %u, %u]",
            t->order[0], t->order[1], t->order[2]);
    if (r->diagnosis == RAYO_DIAGNOSIS_OFFSET) {
        cmp_json(s, ", \"offset\": [");
        for (c = 0; c < t->channels; c++)
            cmp_json(s, "%s%d", c ? ", " : "", t->offset[c]);
        cmp_json(s, "], \"on_shapes\": %s",
            t->offset_on_shapes ? "true" : "false");
    }
    if (t->findings > 0)
        tone_put_findings_json(r, s);
    cmp_json(s, ", \"text\": \"");
    tone_put_diagnosis(r, s);
    cmp_json(s, "\"}}\n");
}
