/*
 * tone_scene_outline.c - where a sphere whose centre another sphere
 * hides (or the frame cuts) is drawn, read from the part of its outline
 * that shows: a circle is fitted (least squares, algebraic) to the
 * outline the scene gives it and to the one the image gives it, on the
 * same rays from where its centre would be, so the perspective's
 * stretch and the pixels' steps fall out of the difference.  A circle
 * of about the same size whose centre moved is a sphere moved, not
 * drawn another size.  Part of tone_scene_size.c's reading; not for a
 * sphere whose centre shows (tone_scene_objects.c finds it moved as a
 * sphere missing and an object of its size elsewhere).
 */
#include <math.h>

#include "tone_scene.h"

/* The fewest outline points, the fits' error at most this (px, RMS),
   the centre moved by at least this share of the radius and this many
   pixels, and the radii within this share of each other. */
#define OUTLINE_MIN 12
#define OUTLINE_RMS 1.5
#define OUTLINE_SHARE 0.15
#define OUTLINE_PIXELS 4.0
#define OUTLINE_SAME 0.1

/* The circle through the points (x, y) (least squares of x^2 + y^2 +
   D x + E y + F): its centre, radius and RMS distance; 0 when none. */
static int fit_circle(const double *x, const double *y, size_t n,
                      double *cx, double *cy, double *r, double *rms)
{
    double a[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, b[3] = {0, 0, 0};
    double s[3], e = 0;
    size_t i;
    for (i = 0; i < n; i++) {
        double row[3];
        double q = -(x[i] * x[i] + y[i] * y[i]);
        unsigned j, k;
        row[0] = x[i];
        row[1] = y[i];
        row[2] = 1;
        for (j = 0; j < 3; j++) {
            for (k = 0; k < 3; k++)
                a[j][k] += row[j] * row[k];
            b[j] += row[j] * q;
        }
    }
    if (!tone_scene_solve3(a, b, s))
        return 0;
    *cx = -s[0] / 2;
    *cy = -s[1] / 2;
    *r = *cx * *cx + *cy * *cy - s[2];
    if (*r <= 0)
        return 0;
    *r = sqrt(*r);
    for (i = 0; i < n; i++) {
        double d = hypot(x[i] - *cx, y[i] - *cy) - *r;
        e += d * d;
    }
    *rms = sqrt(e / (double)n);
    return 1;
}

int tone_scene_outline_moved(const double *sx, const double *sy,
                             const double *ix, const double *iy, size_t n,
                             double *shift)
{
    double scx, scy, sr, srms, icx, icy, ir, irms, moved;
    if (n < OUTLINE_MIN || !fit_circle(sx, sy, n, &scx, &scy, &sr, &srms) ||
        !fit_circle(ix, iy, n, &icx, &icy, &ir, &irms))
        return 0;
    shift[0] = icx - scx;
    shift[1] = icy - scy;
    moved = hypot(shift[0], shift[1]);
    return srms <= OUTLINE_RMS && irms <= OUTLINE_RMS &&
           fabs(ir - sr) <= OUTLINE_SAME * sr &&
           moved >= OUTLINE_SHARE * sr && moved >= OUTLINE_PIXELS;
}
