/*
 * tone_undo.c - a candidate mistake undone on the image, one pixel of
 * the reference's frame at a time: the image's pixel that should hold
 * the reference's value there, once the flip, shift, scale, channel
 * order, inversion, offset or wrap is taken back.
 *
 * The image is laid on the reference's frame centred, as the whole tone
 * comparison lays it; a scale reads between pixels (bilinear), so the
 * scale search sees gradients move smoothly.  Not a resampler for
 * display: the measuring pass (tone_measure.c) reads through it.
 */
#include <math.h>
#include <string.h>

#include "tone_impl.h"

tone_xform tone_identity(void)
{
    tone_xform t;
    memset(&t, 0, sizeof t);
    t.kind = TONE_IDENTITY;
    t.scale = 1;
    t.perm[0] = 0;
    t.perm[1] = 1;
    t.perm[2] = 2;
    t.step = 1;
    t.max_squares = UINT64_MAX;
    return t;
}

static unsigned char clamp_level(int v)
{
    return (unsigned char)(v < 0 ? 0 : v > 255 ? 255 : v);
}

/* The image read at reference pixel (x, y) scaled by s about the
   optical centre, between pixels by bilinear interpolation (so the
   scale search sees gradients move smoothly); 0 outside the image. */
static int undo_scaled(const tone_image *ref, const tone_image *image,
                       double s, uint32_t x, uint32_t y, unsigned char *u)
{
    double fx = s * ((double)x - ref->width / 2) + image->width / 2;
    double fy = s * ((double)y - ref->height / 2) + image->height / 2;
    double x0 = floor(fx), y0 = floor(fy), ax = fx - x0, ay = fy - y0;
    int64_t ix = (int64_t)x0, iy = (int64_t)y0, jx, jy;
    unsigned c;
    if (ix < 0 || iy < 0 || ix >= image->width || iy >= image->height)
        return 0;
    jx = ix + 1 < image->width ? ix + 1 : ix;
    jy = iy + 1 < image->height ? iy + 1 : iy;
    for (c = 0; c < ref->channels; c++) {
        double a = tone_pixel(image, (uint32_t)ix, (uint32_t)iy)[c];
        double b = tone_pixel(image, (uint32_t)jx, (uint32_t)iy)[c];
        double d = tone_pixel(image, (uint32_t)ix, (uint32_t)jy)[c];
        double e = tone_pixel(image, (uint32_t)jx, (uint32_t)jy)[c];
        double v = (a * (1 - ax) + b * ax) * (1 - ay) +
                   (d * (1 - ax) + e * ax) * ay;
        u[c] = (unsigned char)floor(v + 0.5);
    }
    return 1;
}

int tone_undo(const tone_image *ref, const tone_image *image,
              const tone_xform *t, uint32_t x, uint32_t y, unsigned char *u)
{
    int64_t rx = x, ry = y, ix, iy;
    int64_t ox = (int64_t)(image->width / 2) - (int64_t)(ref->width / 2);
    int64_t oy = (int64_t)(image->height / 2) - (int64_t)(ref->height / 2);
    const unsigned char *p, *r = tone_pixel(ref, x, y);
    unsigned c, n = ref->channels;
    switch (t->kind) {
    case TONE_FLIP_V:
        ry = (int64_t)ref->height - 1 - ry;
        break;
    case TONE_FLIP_H:
        rx = (int64_t)ref->width - 1 - rx;
        break;
    case TONE_FLIP_BOTH:
        rx = (int64_t)ref->width - 1 - rx;
        ry = (int64_t)ref->height - 1 - ry;
        break;
    case TONE_SHIFT:
        rx += t->dx;
        ry += t->dy;
        break;
    case TONE_SCALE:
        return undo_scaled(ref, image, t->scale, x, y, u);
    default:
        break;
    }
    ix = rx + ox;
    iy = ry + oy;
    if (ix < 0 || iy < 0 || ix >= image->width || iy >= image->height)
        return 0;
    p = tone_pixel(image, (uint32_t)ix, (uint32_t)iy);
    for (c = 0; c < n; c++)
        u[c] = p[c];
    switch (t->kind) {
    case TONE_PERMUTE:
        for (c = 0; c < n; c++)
            u[t->perm[c]] = p[c];
        break;
    case TONE_INVERT:
        for (c = 0; c < n; c++)
            u[c] = (unsigned char)(255 - p[c]);
        break;
    case TONE_OFFSET_ON_SHAPES:
        if (n == 1 ? r[0] == 0 : (r[0] | r[1] | r[2]) == 0)
            break;
        /* fall through */
    case TONE_OFFSET:
        for (c = 0; c < n; c++) {
            int moved = (int)r[c] + t->offset[c];
            /* A value the offset pushed past 0 or 255 was clamped there:
               it agrees with any reference value that would be. */
            if ((p[c] == 255 && moved >= 255) || (p[c] == 0 && moved <= 0))
                u[c] = r[c];
            else
                u[c] = clamp_level((int)p[c] - t->offset[c]);
        }
        break;
    case TONE_WRAPPED:
        for (c = 0; c < n; c++)
            if (r[c] == 255 && p[c] < 128)
                u[c] = 255;
        break;
    default:
        break;
    }
    return 1;
}
