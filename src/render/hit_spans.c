/*
 * hit_spans.c - hit-mode rows by spans: for each sphere, where along the
 * row its hits begin and end, so that only the pixels near those two ends
 * are traced.  It exists for speed (the seed job, huge frames); it is not
 * a renderer of its own and must give, bit for bit, what row.c's
 * per-pixel loop gives (tests/unit/t_hit_spans.c), for the reasons
 * below.  Scenes with planes or triangles, and cameras outside the range
 * the bounds cover, go back to that loop (hit_spans_plan.c decides, once
 * a frame).
 */
/*
 * The geometry.  Pixel x of row y has direction d(x) = x a + b, with
 * a = right and b = -y up + f forward (camera.h).  With l = C - O, the
 * exact ray test asks for h(x) = l.d(x) / |d(x)| (the assignment's beta)
 * and g(x) = h^2 - (l.l - R^2) (its delta).  Seen from outside the ball
 * (l.l > R^2) the ray hits iff h >= sqrt(l.l - R^2): d lies in a convex
 * cone, and a line meets a convex cone in an interval.  From inside, every
 * ray hits.  Along the line, h has one maximum, at x* = N / D (below), or
 * grows towards one end; every superlevel set of h is an interval around
 * that maximum.
 *
 * Why the output is exact.  rayo_sphere_hit works in floating point, so
 * its answer can differ from the real-number one near the outline.  Its
 * delta is within E = 512 u (l.l + R^2) of the exact g (u = 2^-53; the
 * rounding of the direction, its normalisation, beta, beta^2 and the sums
 * add up to about 35 u (l.l + R^2)), and our own estimate of g within
 * T = E of it.  So:
 *   - estimate > E + T (front side)  =>  g > E  =>  the exact test hits;
 *     those pixels form an interval (a superlevel set of h), so two such
 *     pixels prove every pixel between them;
 *   - estimate < -(E + 3T) or behind  =>  outside the set M where
 *     g >= -(E + 2T), which holds every pixel the exact test can call a
 *     hit; M is an interval containing x*, so one such pixel proves every
 *     pixel beyond it (away from x*) a miss -- or, without knowing x*,
 *     every pixel beyond it away from a pixel known to be in M, such as
 *     one that surely hits (what quick_span and track_span rely on);
 *   - everything else gets the exact test, rayo_camera_ray followed by
 *     rayo_sphere_hit, the very calls of the per-pixel loop.
 * The analytic ends (roots of a quadratic) are only hints of where to
 * look: a wrong hint costs time, never a bit.  When the camera is within
 * a few E of a sphere's surface, or x* cannot be located, that sphere is
 * tested at every pixel of the row.
 */
#include "hit_spans_impl.h"

#include <math.h>
#include <string.h>

#include "../image/row_runs.h"

/* The tracking path below runs on almost every row: inlined whole, its
 * values stay in registers instead of going through the stack
 * (docs/performance.md, "Spans instead of
 * pixels"). */
#if defined(__GNUC__)
#define TRACKING_INLINE inline __attribute__((always_inline))
#else
#define TRACKING_INLINE inline
#endif

/* How far tracking follows an end before it asks the roots instead. */
#define TRACK_STEPS 8
/* Spans are tracked across rows in scenes of at most this many spheres. */
#define TRACK_SPHERES 16

/*
 * The output.  A row goes into packed bits, or, when render.c asks for
 * runs (for the plain PBM writer: image/row_runs.h), into the runs of
 * black pixels the spans are; such a row never touches its bits unless a
 * pixel must be tested alone or the runs overflow, and then moves to its
 * bits for good (to_bits).
 */
static int bit_set(const unsigned char *out, int64_t i)
{
    return (out[i >> 3] >> (7 - (i & 7))) & 1;
}

static void set_bit(unsigned char *out, int64_t i)
{
    out[i >> 3] = (unsigned char)(out[i >> 3] | (0x80u >> (i & 7)));
}

/* Moves the row from its runs to its bits, for good. */
static void to_bits(const row_frame *f)
{
    row_target *t = f->target;
    if (t->runs == NULL)
        return;
    rayo_row_runs_to_bits(t->runs, (uint32_t)f->width, t->bits);
    t->runs->count = RAYO_ROW_RUNS_BITS;
    t->runs = NULL;
}

/* Pixels first..last (inclusive) hit. */
static void paint(const row_frame *f, int64_t first, int64_t last)
{
    row_target *t = f->target;
    if (t->runs != NULL &&
        rayo_row_runs_add(t->runs, (uint32_t)first, (uint32_t)last))
        return;
    to_bits(f);
    rayo_row_bits_fill(t->bits, (uint32_t)first, (uint32_t)last);
}

/* The per-pixel loop's own test, for one sphere. */
static void exact_test(const row_frame *f, const rayo_sphere *sphere,
                       int64_t i)
{
    rayo_ray ray;
    to_bits(f); /* pixels one at a time, after other spheres' hits */
    if (bit_set(f->target->bits, i))
        return;
    ray = rayo_camera_ray(f->camera, (double)i, (double)f->row);
    if (rayo_sphere_hit(sphere, &ray, 0.0))
        set_bit(f->target->bits, i);
}

static void exact_range(const row_frame *f, const rayo_sphere *sphere,
                        int64_t first, int64_t last)
{
    int64_t i;
    for (i = first; i <= last; i++)
        exact_test(f, sphere, i);
}

/*
 * Our estimate of g at pixel i against a threshold, without dividing:
 * g > t  <=>  (p x + q)^2 > (k + t) |d|^2.  Returns -1 when pixel i is
 * behind (l.d <= 0) or its g is below s->surely_missed, 1 when above
 * s->surely_hit, else 0.
 */
static inline int classify(const row_frame *f, const sphere_row *s,
                           int64_t i)
{
    double x = (double)i - f->half_width;
    double num = s->p * x + s->q;
    double den = (f->a2 * x + 2.0 * f->ab) * x + f->b2;
    double square = num * num;
    if (!(num > 0.0) || square < s->miss_level * den)
        return -1;
    return square > s->hit_level * den ? 1 : 0;
}

/* 1 when pixel i is proven outside M (see the top of the file). */
static int surely_outside(const row_frame *f, const sphere_row *s,
                          int64_t i)
{
    return classify(f, s, i) < 0;
}

/*
 * The supremum of h^2 over the whole line is |l projected on the plane of
 * a and b|^2; when even that misses, so does the row.
 */
static int row_misses(const row_frame *f, const sphere_row *s)
{
    double p = s->p, q = s->q;
    double h2_gram = p * p * f->b2 - 2.0 * p * q * f->ab + q * q * f->a2;
    double gram = f->a2 * f->b2 - f->ab * f->ab;
    return h2_gram < s->miss_level * gram;
}

/*
 * Where h peaks along the line: [*lo, *hi] in x holds x*, or both are
 * +-INFINITY when h grows towards that end.  Returns 0 when the row
 * surely misses, -1 when x* cannot be located, 1 otherwise.
 */
static int peak_window(const row_frame *f, const sphere_row *s, double *lo,
                       double *hi)
{
    double p = s->p, q = s->q;
    double d = q * f->a2 - p * f->ab;
    double n = p * f->b2 - q * f->ab;
    double nb = sqrt(f->b2), na = sqrt(f->a2);
    double err_d = PEAK_ERROR * UNIT_ROUNDOFF * s->length * f->a2 * nb;
    double err_n = PEAK_ERROR * UNIT_ROUNDOFF * s->length * na * f->b2;
    double x, err;
    if (fabs(d) <= err_d) {
        /* x* may be anywhere past 2^20 pixels, or h may have no maximum:
         * either way it grows towards the end where p x grows, provided
         * N says so beyond doubt. */
        if (!(fabs(n) - err_n > 2.0 * err_d * 1048576.0 && n * p > 0.0))
            return -1;
        *lo = *hi = p > 0.0 ? INFINITY : -INFINITY;
        return 1;
    }
    if (d < 0.0) {
        /* A minimum: the supremum is |p|/|a|, towards the end where p x
         * grows. */
        if (p * p < s->miss_level * f->a2)
            return 0;
        *lo = *hi = p > 0.0 ? INFINITY : -INFINITY;
        return 1;
    }
    x = n / d;
    err = (err_n + fabs(x) * err_d) / (d - err_d) + 0.5;
    if (!isfinite(x) || !isfinite(err))
        return -1;
    *lo = x - err;
    *hi = x + err;
    return 1;
}

/*
 * Roots of (p x + q)^2 = k |x a + b|^2 nearest the peak window on either
 * side; NaN or +-INFINITY when there is none.  Hints only.
 */
static void root_hints(const row_frame *f, const sphere_row *s, double lo,
                       double hi, double *left, double *right)
{
    double p = s->p, q = s->q, k = s->k;
    double alpha = p * p - k * f->a2;
    double beta = p * q - k * f->ab;
    double gamma = q * q - k * f->b2;
    double disc = beta * beta - alpha * gamma;
    double t, r1, r2, roots[2];
    int j;
    *left = -INFINITY;
    *right = INFINITY;
    if (!(disc >= 0.0))
        return;
    t = -(beta + copysign(sqrt(disc), beta));
    r1 = t / alpha;
    r2 = gamma / t;
    roots[0] = r1;
    roots[1] = r2;
    for (j = 0; j < 2; j++) {
        if (!isfinite(roots[j]))
            continue;
        if (roots[j] <= lo && roots[j] > *left)
            *left = roots[j];
        if (roots[j] >= hi && roots[j] < *right)
            *right = roots[j];
    }
}

/* floor(v) as a pixel index, clamped to [-1, width]. */
static int64_t index_floor(double v, int64_t width)
{
    if (!(v >= -1.0))
        return -1;
    if (v >= (double)width)
        return width;
    return (int64_t)floor(v);
}

static int64_t index_ceil(double v, int64_t width)
{
    if (!(v >= -1.0))
        return -1;
    if (v >= (double)width)
        return width;
    return (int64_t)ceil(v);
}

/*
 * From start, moves by doubling steps in direction (+1 or -1) until a
 * pixel is surely outside M, or past the row's end (-1 or width).
 */
static int64_t walk_out(const row_frame *f, const sphere_row *s,
                        int64_t start, int direction)
{
    int64_t i = start, step = 1;
    while (i >= 0 && i < f->width && !surely_outside(f, s, i)) {
        i += direction * step;
        step *= 2;
    }
    return i < 0 ? -1 : i >= f->width ? f->width : i;
}

/*
 * Pixels strictly between left and right may hit: go inwards from both
 * ends until a pixel surely hits, and fill between the two found.  On the
 * way, pixels proven outside M are misses; the rest get the exact test.
 */
static void resolve_between(const row_frame *f, const sphere_row *s,
                            int64_t left, int64_t right)
{
    int64_t i, j;
    int verdict = 0;
    for (i = left + 1; i < right; i++) {
        verdict = classify(f, s, i);
        if (verdict > 0)
            break;
        if (verdict == 0)
            exact_test(f, s->sphere, i);
    }
    if (i >= right)
        return;
    for (j = right - 1; j > i; j--) {
        verdict = classify(f, s, j);
        if (verdict > 0)
            break;
        if (verdict == 0)
            exact_test(f, s->sphere, j);
    }
    paint(f, i, j);
}

/*
 * The cost.  What a sphere's rows share (C - O, the error bounds, l.a)
 * is worked out once a frame (rayo_hit_spans_plan).  On most rows the
 * roots of the quadratic, rounded inwards, are the first and last hit,
 * and four classified pixels prove it (quick_span): a row then costs a
 * square root, two divisions and four estimates.  Rendered in bands
 * (rayo_hit_spans_render_rows, as render.c does), a row starts from the
 * span of the row before and moves each end while the same rules allow
 * (track_span): four estimates, and one more for each pixel an end
 * moves.  Only rows where rounding leaves a doubt take the walks and the
 * exact tests.
 */

/*
 * The usual row in one try: when the hits are a bounded interval (the
 * quadratic opens downwards), its roots rounded inwards to pixels are
 * the first and last hit, provided those two pixels surely hit and their
 * outer neighbours are surely outside M; then everything between is hit
 * and everything beyond missed, by the two rules at the top of the file.
 * Returns 0, having touched nothing, when any of the four is in doubt.
 */
static int quick_span(const row_frame *f, const sphere_row *s,
                      span_hint *hint)
{
    double p = s->p, q = s->q, k = s->k;
    double alpha = p * p - k * f->a2;
    double beta = p * q - k * f->ab;
    double gamma = q * q - k * f->b2;
    double disc = beta * beta - alpha * gamma;
    double t, r1, r2, lo, hi;
    int64_t left, right;
    if (!(alpha < 0.0) || !(disc > 0.0))
        return 0;
    t = -(beta + copysign(sqrt(disc), beta));
    r1 = t / alpha + f->half_width;
    r2 = gamma / t + f->half_width;
    lo = r1 < r2 ? r1 : r2;
    hi = r1 < r2 ? r2 : r1;
    /* ceil(lo) and floor(hi), clipped to the row (no NaN gets past). */
    if (!(hi >= 0.0) || !(lo < (double)f->width))
        return 0;
    left = lo > 0.0 ? (int64_t)lo : 0;
    if ((double)left < lo)
        left++;
    right = hi < (double)(f->width - 1) ? (int64_t)hi : f->width - 1;
    if (left > right)
        return 0;
    if (classify(f, s, left) <= 0 || classify(f, s, right) <= 0 ||
        (left > 0 && classify(f, s, left - 1) >= 0) ||
        (right < f->width - 1 && classify(f, s, right + 1) >= 0))
        return 0;
    paint(f, left, right);
    hint->first = left;
    hint->last = right;
    return 1;
}

/*
 * One end of the span, followed from where it was on the row before:
 * from `at`, outwards (step -1 for the first pixel, +1 for the last)
 * while the next pixel surely hits, or inwards while `at` is surely
 * outside M.  Sets *end to a pixel that surely hits whose outer
 * neighbour is surely outside M or off the row; 0 when a pixel is in
 * doubt or the end moved more than TRACK_STEPS.
 */
static TRACKING_INLINE int track_end(const row_frame *f,
                                     const sphere_row *s, int64_t at,
                                     int64_t step, int64_t *end)
{
    int c = classify(f, s, at), steps;
    if (c > 0) {
        for (steps = 0;; steps++) {
            int64_t next = at + step;
            if (next < 0 || next >= f->width)
                break;
            c = classify(f, s, next);
            if (c < 0)
                break;
            if (c == 0 || steps == TRACK_STEPS)
                return 0;
            at = next;
        }
    } else if (c < 0) {
        for (steps = 0; c < 0; steps++) {
            at -= step;
            if (at < 0 || at >= f->width || steps == TRACK_STEPS)
                return 0;
            c = classify(f, s, at);
        }
        if (c == 0)
            return 0;
    } else {
        return 0;
    }
    *end = at;
    return 1;
}

/*
 * The row after one whose span is known: each end followed from where it
 * was, by the rules of quick_span (the first and last pixel surely hit,
 * their outer neighbours surely outside M), without the roots.
 */
static TRACKING_INLINE int track_span(const row_frame *f,
                                      const sphere_row *s, span_hint *hint)
{
    int64_t left, right;
    if (hint->first > hint->last ||
        !track_end(f, s, hint->first, -1, &left) ||
        !track_end(f, s, hint->last, 1, &right) || left > right)
        return 0;
    paint(f, left, right);
    hint->first = left;
    hint->last = right;
    return 1;
}

/* A sphere seen from outside (s->k well above the error bounds). */
static void trace_outside(const row_frame *f, const sphere_row *s,
                          span_hint *hint)
{
    double lo, hi, hint_left, hint_right;
    int64_t left, right, start;
    int located;
    if (track_span(f, s, hint))
        return;
    hint->first = 1;
    hint->last = 0; /* none to track from, unless quick_span finds one */
    if (row_misses(f, s) || quick_span(f, s, hint))
        return;
    located = peak_window(f, s, &lo, &hi);
    if (located == 0)
        return;
    if (located < 0) {
        exact_range(f, s->sphere, 0, f->width - 1);
        return;
    }
    root_hints(f, s, lo, hi, &hint_left, &hint_right);
    start = index_floor(lo + f->half_width, f->width) - 1;
    left = isfinite(hint_left)
               ? index_floor(hint_left + f->half_width, f->width) - 1
               : start;
    left = walk_out(f, s, left < start ? left : start, -1);
    start = index_ceil(hi + f->half_width, f->width) + 1;
    right = isfinite(hint_right)
                ? index_ceil(hint_right + f->half_width, f->width) + 1
                : start;
    right = walk_out(f, s, right > start ? right : start, 1);
    resolve_between(f, s, left, right);
}

/* Traces one sphere into the row; returns 1 when the row is now full. */
static int trace_sphere(const row_frame *f, const sphere_frame *frame,
                        span_hint *hint)
{
    sphere_row s;
    switch (frame->kind) {
    case SPHERE_AROUND:
        paint(f, 0, f->width - 1);
        return 1;
    case SPHERE_NEAR:
        exact_range(f, frame->row.sphere, 0, f->width - 1);
        return 0;
    case SPHERE_OUTSIDE:
        break;
    }
    s = frame->row;
    s.q = rayo_vec3_dot(frame->l, f->b);
    trace_outside(f, &s, hint);
    return 0;
}

/* Row `row` into out, or into *runs when that is not NULL and the row's
 * hits fit there (runs->count is RAYO_ROW_RUNS_BITS when they did not);
 * hints[i] is sphere i's span on the row before (updated), or NULL. */
static void render_row(const rayo_hit_spans *plan, uint32_t row,
                       unsigned char *out, rayo_row_runs *runs,
                       span_hint *hints)
{
    const rayo_camera *camera = plan->camera;
    double y = (double)row - plan->half_height;
    row_frame f;
    row_target target;
    span_hint none;
    size_t i;
    f.camera = camera;
    f.row = row;
    f.width = camera->width;
    f.half_width = plan->half_width;
    f.b = rayo_vec3_add(rayo_vec3_scale(camera->up, -y), plan->ahead);
    f.a2 = plan->a2;
    f.ab = rayo_vec3_dot(camera->right, f.b);
    f.b2 = rayo_vec3_dot(f.b, f.b);
    target.bits = out;
    target.runs = runs;
    f.target = &target;
    if (runs != NULL)
        runs->count = 0;
    else
        memset(out, 0, ((size_t)camera->width + 7) / 8);
    for (i = 0; i < plan->count; i++) {
        none.first = 1;
        none.last = 0;
        if (trace_sphere(&f, &plan->spheres[i],
                         hints != NULL ? &hints[i] : &none)) {
            /* The row is full: the spheres after have no span to track. */
            for (i++; hints != NULL && i < plan->count; i++) {
                hints[i].first = 1;
                hints[i].last = 0;
            }
            break;
        }
    }
    if (target.runs != NULL && target.runs->count > 1)
        rayo_row_runs_normalize(target.runs);
}

void rayo_hit_spans_render(const rayo_hit_spans *plan, uint32_t row,
                           unsigned char *out)
{
    render_row(plan, row, out, NULL, NULL);
}

void rayo_hit_spans_render_rows(const rayo_hit_spans *plan, uint32_t first,
                                uint32_t count, unsigned char *out,
                                size_t stride, rayo_row_runs *runs)
{
    span_hint hints[TRACK_SPHERES];
    uint32_t r;
    size_t i;
    int tracking = plan->count <= TRACK_SPHERES;
    for (i = 0; tracking && i < plan->count; i++) {
        hints[i].first = 1;
        hints[i].last = 0;
    }
    for (r = 0; r < count; r++)
        render_row(plan, first + r, out + (size_t)r * stride,
                   runs != NULL ? runs + r : NULL, tracking ? hints : NULL);
}
