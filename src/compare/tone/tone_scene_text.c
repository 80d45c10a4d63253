/*
 * tone_scene_text.c - the findings of tone_scene.c in words, for a
 * student, and as JSON.
 *
 * Each finding is one whole sentence in the statement's terms (IA, II,
 * Ia ka, "a ray that meets no sphere gives 0"), naming a sphere by where
 * it appears in the picture (column, row) and by its centre and radius
 * in the statement, so the student can find it in the code.  Sentences
 * hold no double quote and no backslash: they go into JSON as they are.
 * The measuring is tone_scene.c's.
 */
#include <math.h>

#include "rayo/course/course_scene.h"

#include "../report_sink.h"
#include "tone_scene.h"

static const char *const kind_names[] = {
    "background", "added", "missing", "moved", "partly",
    "ambient", "light", "below-ambient", "where", "size",
    "light-direction", "lamp-position", "lamp-colour", "lamp-missing"};

static int gray_course(const rayo_compare_report *r)
{
    return tone_course_gray(r->tone.course);
}

static const rayo_course_ball *ball_of(const rayo_compare_report *r,
                                       const rayo_compare_finding *f)
{
    const rayo_course_data *d =
        rayo_course_data_of((rayo_course_exercise)r->tone.course);
    if (d == NULL || f->ball < 0 || (size_t)f->ball >= d->ball_count)
        return NULL;
    return &d->balls[f->ball];
}

/* A region that looks like a disc: filling about pi/4 of a box about
   as wide as high. */
static int round_region(const rayo_compare_finding *f)
{
    double w = f->box[2] - f->box[0] + 1, h = f->box[3] - f->box[1] + 1;
    double fill = (double)f->pixels / (w * h);
    return fill > 0.6 && fill < 0.95 && w < 1.5 * h && h < 1.5 * w;
}

static void put_background(cmp_sink *s, const rayo_compare_report *r,
                           const rayo_compare_finding *f)
{
    const rayo_course_data *d =
        rayo_course_data_of((rayo_course_exercise)r->tone.course);
    if (!gray_course(r))
        cmp_put(s, "the background is (%.0f, %.0f, %.0f), not black (0, 0, "
                   "0): a ray that meets no sphere gives black",
            f->value[0], f->value[1], f->value[2]);
    else if (d != NULL && fabs(f->value[0] - d->ambient[0]) < 1.5)
        cmp_put(s, "the background is %.0f, the ambient intensity IA, not 0 "
                   "(black): a ray that meets no sphere gives 0, and IA "
                   "belongs only to the spheres",
            f->value[0]);
    else
        cmp_put(s, "the background is %.0f, not 0 (black): a ray that meets "
                   "no sphere gives 0",
            f->value[0]);
}

static void put_ball_finding(cmp_sink *s, const rayo_compare_finding *f,
                             const rayo_course_ball *b)
{
    switch (f->kind) {
    case RAYO_FINDING_MISSING:
        cmp_put(s, "the sphere at about (%.0f, %.0f) px, centre (%g, %g, %g) "
                   "and radius %g in the statement, is missing: its pixels "
                   "show the background",
            f->x, f->y, b->center[0], b->center[1], b->center[2], b->radius);
        break;
    case RAYO_FINDING_MOVED:
        if (f->value[2] > 0) { /* read from its outline, centre hidden */
            cmp_put(s, "the sphere at about (%.0f, %.0f) px, centre (%g, %g, "
                       "%g) and radius %g in the statement, whose centre is "
                       "hidden, is drawn centred at about (%.0f, %.0f) px, "
                       "as a centre of about (%.2f, %.2f, %g) would be: the "
                       "outline that shows is the scene's moved; check its "
                       "centre",
                f->x, f->y, b->center[0], b->center[1], b->center[2],
                b->radius, f->value[0], f->value[1], f->expected[0],
                f->expected[1], f->expected[2]);
            break;
        }
        cmp_put(s, "the sphere at about (%.0f, %.0f) px, centre (%g, %g, %g) "
                   "and radius %g in the statement, is missing there, and "
                   "an object of about its size is at about (%.0f, %.0f) px "
                   "instead: check its centre",
            f->x, f->y, b->center[0], b->center[1], b->center[2], b->radius,
            f->value[0], f->value[1]);
        break;
    case RAYO_FINDING_SIZE:
        cmp_put(s, "the sphere at about (%.0f, %.0f) px, centre (%g, %g, %g) "
                   "and radius %g in the statement, is drawn with a radius "
                   "of about %.2g (%.0f px instead of %.0f): check its "
                   "radius",
            f->x, f->y, b->center[0], b->center[1], b->center[2], b->radius,
            f->value[1], f->value[0], f->expected[0]);
        break;
    default: /* PARTLY */
        cmp_put(s, "the sphere at about (%.0f, %.0f) px, centre (%g, %g, %g) "
                   "and radius %g in the statement, shows the background in "
                   "%llu of its %llu pixels away from its outline: it is "
                   "drawn smaller, cut or hidden",
            f->x, f->y, b->center[0], b->center[1], b->center[2], b->radius,
            (unsigned long long)f->pixels, (unsigned long long)f->total);
        break;
    }
}

static void put_added(cmp_sink *s, const rayo_compare_finding *f)
{
    if (round_region(f))
        cmp_put(s, "there is a sphere at about (%.0f, %.0f) px (columns %d to "
                   "%d, rows %d to %d) that is not in the course's scene",
            f->x, f->y, (int)f->box[0], (int)f->box[2], (int)f->box[1],
            (int)f->box[3]);
    else
        cmp_put(s, "something is drawn at about (%.0f, %.0f) px (columns %d "
                   "to %d, rows %d to %d, %llu pixels) where the course's "
                   "scene shows only background",
            f->x, f->y, (int)f->box[0], (int)f->box[2], (int)f->box[1],
            (int)f->box[3], (unsigned long long)f->pixels);
}

static void put_ambient(cmp_sink *s, const rayo_compare_report *r,
                        const rayo_compare_finding *f)
{
    if (gray_course(r))
        cmp_put(s, "the ambient intensity looks like %.0f, not the "
                   "statement's IA = %.0f: where the light does not reach "
                   "(L.N <= 0, or in shadow) I = IA",
            f->value[0], f->expected[0]);
    else
        cmp_put(s, "the ambient light looks like (%.3f, %.3f, %.3f), not the "
                   "statement's Ia = (%g, %g, %g): where no light reaches, C "
                   "= Ia ka (then times M)",
            f->value[0], f->value[1], f->value[2], f->expected[0],
            f->expected[1], f->expected[2]);
}

static void put_below(cmp_sink *s, const rayo_compare_report *r,
                      const rayo_compare_finding *f)
{
    if (gray_course(r))
        cmp_put(s, "%llu pixels of the spheres are darker than IA = %g, which "
                   "the model never gives (I = IA + II (L.N) where lit, IA "
                   "in shadow and where L.N <= 0); %llu of them lie in a "
                   "shadow another sphere casts, and most (%llu) are on the "
                   "sphere at about (%.0f, %.0f) px",
            (unsigned long long)f->pixels, f->expected[0],
            (unsigned long long)f->shadowed, (unsigned long long)f->total,
            f->x, f->y);
    else
        cmp_put(s, "%llu pixels of the spheres are darker than their ambient "
                   "colour Ia ka M, which the model never gives (C = Ia ka + "
                   "the lights, then times M); %llu of them lie in a shadow "
                   "another sphere casts, and most (%llu) are on the sphere "
                   "at about (%.0f, %.0f) px",
            (unsigned long long)f->pixels, (unsigned long long)f->shadowed,
            (unsigned long long)f->total, f->x, f->y);
}

static void put_where(cmp_sink *s, const rayo_compare_finding *f)
{
    if (f->ball >= 0)
        cmp_put(s, "%llu of the %llu pixels of the sphere at about (%.0f, "
                   "%.0f) px differ, away from its outline",
            (unsigned long long)f->pixels, (unsigned long long)f->total,
            f->x, f->y);
    else
        cmp_put(s, "%llu of the %llu pixels of the background differ, within "
                   "columns %d to %d and rows %d to %d",
            (unsigned long long)f->pixels, (unsigned long long)f->total,
            (int)f->box[0], (int)f->box[2], (int)f->box[1], (int)f->box[3]);
}

/* A point light of the colour scene whose colour differs, or left out,
   named by its place in the statement. */
static void put_lamp(cmp_sink *s, const rayo_compare_report *r,
                     const rayo_compare_finding *f)
{
    const rayo_course_data *d =
        rayo_course_data_of((rayo_course_exercise)r->tone.course);
    const double *at;
    if (d == NULL || f->box[0] < 0 || (size_t)f->box[0] >= d->lamp_count)
        return;
    at = d->lamps[f->box[0]].vector;
    if (f->kind == RAYO_FINDING_LAMP_MISSING)
        cmp_put(s, "the light at (%g, %g, %g) of the statement is not in "
                   "your image: the channel it alone lights stays at Ia ka "
                   "(and the other lights) on the %llu pixels it should "
                   "light",
            at[0], at[1], at[2], (unsigned long long)f->total);
    else
        cmp_put(s, "the light at (%g, %g, %g) looks like colour (%.2f, "
                   "%.2f, %.2f), not the statement's (%g, %g, %g): C = Ia "
                   "ka + Ii kd (L.N) fits %llu of the %llu pixels it lights "
                   "with that Ii",
            at[0], at[1], at[2], f->value[0], f->value[1], f->value[2],
            f->expected[0], f->expected[1], f->expected[2],
            (unsigned long long)f->pixels, (unsigned long long)f->total);
}

static void put_one(cmp_sink *s, const rayo_compare_report *r,
                    const rayo_compare_finding *f)
{
    const rayo_course_ball *b = ball_of(r, f);
    switch (f->kind) {
    case RAYO_FINDING_BACKGROUND:
        put_background(s, r, f);
        break;
    case RAYO_FINDING_ADDED:
        put_added(s, f);
        break;
    case RAYO_FINDING_MISSING:
    case RAYO_FINDING_MOVED:
    case RAYO_FINDING_PARTLY:
    case RAYO_FINDING_SIZE:
        if (b != NULL)
            put_ball_finding(s, f, b);
        break;
    case RAYO_FINDING_AMBIENT:
        put_ambient(s, r, f);
        break;
    case RAYO_FINDING_LIGHT:
        cmp_put(s, "the light's intensity looks like %.0f, not the "
                   "statement's II = %.0f: I = IA + II (L.N)",
            f->value[0], f->expected[0]);
        break;
    case RAYO_FINDING_LIGHT_DIRECTION:
        if (!gray_course(r)) {
            cmp_put(s, "the directional light seems to come from (%.2f, "
                       "%.2f, %.2f), not the statement's (%.3g, %.3g, "
                       "%.3g): C = Ia ka + Ii kd (L.N) fits %llu of the %llu "
                       "values it lights with that L",
                f->value[0], f->value[1], f->value[2], f->expected[0],
                f->expected[1], f->expected[2],
                (unsigned long long)f->pixels, (unsigned long long)f->total);
            break;
        }
        cmp_put(s, "the light seems to come from (%.2f, %.2f, %.2f), not the "
                   "statement's (%.3g, %.3g, %.3g): I = IA + II (L.N) fits "
                   "%llu of the %llu lit pixels of the spheres with that L",
            f->value[0], f->value[1], f->value[2], f->expected[0],
            f->expected[1], f->expected[2], (unsigned long long)f->pixels,
            (unsigned long long)f->total);
        break;
    case RAYO_FINDING_LAMP_POSITION:
        cmp_put(s, "the point light at (%g, %g, %g) in the statement seems "
                   "to be at about (%.1f, %.1f, %.1f) in the image: C = Ia "
                   "ka + Ii kd (L.N) fits %llu of the %llu pixels it lights "
                   "with L towards that point",
            f->expected[0], f->expected[1], f->expected[2], f->value[0],
            f->value[1], f->value[2], (unsigned long long)f->pixels,
            (unsigned long long)f->total);
        break;
    case RAYO_FINDING_LAMP_COLOUR:
    case RAYO_FINDING_LAMP_MISSING:
        put_lamp(s, r, f);
        break;
    case RAYO_FINDING_BELOW_AMBIENT:
        put_below(s, r, f);
        break;
    case RAYO_FINDING_WHERE:
        put_where(s, f);
        break;
    }
}

void tone_put_findings(const rayo_compare_report *r, cmp_sink *s)
{
    unsigned i;
    for (i = 0; i < r->tone.findings; i++) {
        if (i > 0)
            cmp_json(s, "; ");
        put_one(s, r, &r->tone.finding[i]);
    }
}

static void put_triple(cmp_sink *s, const char *name, const double *v,
                       unsigned n)
{
    unsigned c;
    cmp_json(s, ", \"%s\": [", name);
    for (c = 0; c < n; c++)
        cmp_json(s, "%s%.6g", c ? ", " : "", v[c]);
    cmp_json(s, "]");
}

void tone_put_findings_json(const rayo_compare_report *r, cmp_sink *s)
{
    unsigned i, n = r->tone.channels;
    cmp_json(s, ", \"findings\": [");
    for (i = 0; i < r->tone.findings; i++) {
        const rayo_compare_finding *f = &r->tone.finding[i];
        cmp_json(s, "%s{\"kind\": \"%s\"", i ? ", " : "",
            (size_t)f->kind < sizeof kind_names / sizeof kind_names[0]
                ? kind_names[f->kind]
                : "unknown");
        if (f->ball >= 0)
            cmp_json(s, ", \"ball\": %d, \"x\": %.1f, \"y\": %.1f", f->ball,
                f->x, f->y);
        if (f->kind == RAYO_FINDING_ADDED)
            cmp_json(s, ", \"x\": %.1f, \"y\": %.1f", f->x, f->y);
        if (f->kind == RAYO_FINDING_MOVED)
            cmp_json(s, ", \"to\": {\"x\": %.1f, \"y\": %.1f}", f->value[0],
                f->value[1]);
        if (f->kind == RAYO_FINDING_MOVED && f->value[2] > 0)
            put_triple(s, "centre", f->expected, 3);
        if (f->kind == RAYO_FINDING_ADDED || f->kind == RAYO_FINDING_MOVED ||
            (f->kind == RAYO_FINDING_WHERE && f->ball < 0))
            cmp_json(s, ", \"box\": [%d, %d, %d, %d]", (int)f->box[0],
                (int)f->box[1], (int)f->box[2], (int)f->box[3]);
        if (f->kind == RAYO_FINDING_SIZE)
            cmp_json(s, ", \"radius_px\": %.1f, \"expected_px\": %.1f, "
                       "\"radius\": %.3g",
                f->value[0], f->expected[0], f->value[1]);
        if (f->kind == RAYO_FINDING_LAMP_POSITION ||
            f->kind == RAYO_FINDING_LAMP_COLOUR ||
            f->kind == RAYO_FINDING_LAMP_MISSING)
            cmp_json(s, ", \"lamp\": %d", (int)f->box[0]);
        if (f->kind == RAYO_FINDING_LIGHT_DIRECTION ||
            f->kind == RAYO_FINDING_LAMP_POSITION ||
            f->kind == RAYO_FINDING_LAMP_COLOUR ||
            f->kind == RAYO_FINDING_LAMP_MISSING) {
            put_triple(s, "value", f->value, 3);
            put_triple(s, "expected", f->expected, 3);
        }
        if (f->kind == RAYO_FINDING_BACKGROUND ||
            f->kind == RAYO_FINDING_AMBIENT || f->kind == RAYO_FINDING_LIGHT)
            put_triple(s, "value", f->value,
                       f->kind == RAYO_FINDING_LIGHT ? 1 : n);
        if (f->kind == RAYO_FINDING_AMBIENT || f->kind == RAYO_FINDING_LIGHT)
            put_triple(s, "expected", f->expected,
                       f->kind == RAYO_FINDING_LIGHT ? 1 : n);
        if (f->kind == RAYO_FINDING_SIZE) {
            cmp_json(s, "}");
            continue; /* no pixels counted */
        }
        cmp_json(s, ", \"pixels\": %llu", (unsigned long long)f->pixels);
        if (f->kind == RAYO_FINDING_BELOW_AMBIENT)
            cmp_json(s, ", \"on_ball\": %llu, \"shadowed\": %llu",
                (unsigned long long)f->total,
                (unsigned long long)f->shadowed);
        else if (f->kind != RAYO_FINDING_ADDED)
            cmp_json(s, ", \"of\": %llu", (unsigned long long)f->total);
        cmp_json(s, "}");
    }
    cmp_json(s, "]");
}
