/*
 * t_course_map.c - the course's scenes taken apart (course_map.c)
 * against their correct images: a pixel shows no sphere exactly where
 * the image is black; EJ2's pixel is IA + II (L.N) where the map says
 * the light reaches, IA where it does not (within a level: the map's
 * normal is normalised, the model's divided by r); EJ3's is the
 * statement's sum over the lights the map says reach; the core is away
 * from every outline; a sphere's centre appears where the pinhole puts
 * it.  The images are rayo_course_render's (the renderer, in double),
 * not the map's own code.
 */
#include <math.h>
#include <stdlib.h>

#include "rayo.h"
#include "tap.h"

#include "../../src/course/course_impl.h"

static void check_ej2(void)
{
    rayo_course_map m;
    rayo_image image;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    const rayo_course_data *d = rayo_course_data_of(RAYO_COURSE_EJ2);
    uint32_t x, y;
    unsigned long bad_ball = 0, bad_level = 0, lit = 0, shadowed = 0;
    if (rayo_course_map_make(RAYO_COURSE_EJ2, &m, &err) != RAYO_OK ||
        rayo_course_render(RAYO_COURSE_EJ2, NULL, &image, &err) != RAYO_OK) {
        ok(0, "EJ2: the map and the image are made");
        return;
    }
    is_int(m.lamp_count, 1, "EJ2: one light");
    for (y = 0; y < m.height; y++)
        for (x = 0; x < m.width; x++) {
            size_t p = (size_t)y * m.width + x;
            int v = rayo_image_row(&image, y)[x], want;
            float f = m.light[p];
            if ((m.ball[p] < 0) != (v == 0))
                bad_ball++;
            if (m.ball[p] < 0)
                continue;
            lit += f > 0;
            shadowed += f < 0;
            want = f > 0 ? (int)fmin(255, d->ambient[0] +
                                              d->lamps[0].color[0] * f)
                         : (int)d->ambient[0];
            if (abs(v - want) > 1)
                bad_level++;
        }
    is_int(bad_ball, 0, "EJ2: no sphere exactly where the image is black");
    ok(bad_level <= 5,
       "EJ2: IA + II (L.N) where lit, IA elsewhere (%lu pixels off by more "
       "than a level, at most a few at shadow edges)",
       bad_level);
    ok(lit > 10000 && shadowed > 1000,
       "EJ2: lit (%lu) and shadowed by another sphere (%lu) pixels", lit,
       shadowed);
    rayo_image_free(&image);
    rayo_course_map_free(&m);
}

static void check_ej3(void)
{
    rayo_course_map m;
    rayo_image image;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    const rayo_course_data *d = rayo_course_data_of(RAYO_COURSE_EJ3);
    uint32_t x, y;
    unsigned long bad_ball = 0, bad_colour = 0, core = 0, core_edge = 0;
    double cx, cy;
    if (rayo_course_map_make(RAYO_COURSE_EJ3, &m, &err) != RAYO_OK ||
        rayo_course_render(RAYO_COURSE_EJ3, NULL, &image, &err) != RAYO_OK) {
        ok(0, "EJ3: the map and the image are made");
        return;
    }
    is_int(m.lamp_count, 4, "EJ3: four lights");
    for (y = 0; y < m.height; y++)
        for (x = 0; x < m.width; x++) {
            size_t p = (size_t)y * m.width + x, l;
            const unsigned char *v = rayo_image_row(&image, y) + 3 * x;
            const rayo_course_ball *b;
            unsigned c;
            int black = v[0] == 0 && v[1] == 0 && v[2] == 0;
            if (m.core[p]) {
                core++;
                /* a core pixel's four neighbours show its sphere too */
                if ((x > 0 && m.ball[p - 1] != m.ball[p]) ||
                    (x + 1 < m.width && m.ball[p + 1] != m.ball[p]) ||
                    (y > 0 && m.ball[p - m.width] != m.ball[p]) ||
                    (y + 1 < m.height && m.ball[p + m.width] != m.ball[p]))
                    core_edge++;
            }
            if (m.ball[p] < 0) {
                bad_ball += !black;
                continue;
            }
            b = &d->balls[m.ball[p]];
            for (c = 0; c < 3; c++) {
                double sum = d->ambient[c] * b->ka, byte;
                for (l = 0; l < m.lamp_count; l++) {
                    float f = m.light[p * m.lamp_count + l];
                    if (f > 0)
                        sum += d->lamps[l].color[c] * b->kd * f;
                }
                sum *= b->color[c];
                byte = sum > 1 ? 255 : floor(255 * sum);
                if (fabs(byte - v[c]) > 1)
                    bad_colour++;
            }
        }
    ok(bad_ball == 0, "EJ3: where no sphere is, the image is black (%lu "
                      "pixels not)", bad_ball);
    ok(bad_colour <= 5,
       "EJ3: Ia ka + the lights the map says reach, times M (%lu samples "
       "off by more than a level, at most a few at shadow edges)",
       bad_colour);
    ok(core > 200000 && core_edge == 0,
       "EJ3: %lu core pixels, none beside another sphere", core);
    /* the big sphere (0, -0.4, 3): the pinhole puts it at 320, 240 +
       320 * 0.4 / 3 */
    rayo_course_ball_pixel(&m, &d->balls[1], &cx, &cy);
    is_double(cx, 320.0, 1e-9, "EJ3: the big sphere's column");
    is_double(cy, 240.0 + 320.0 * 0.4 / 3.0, 1e-6, "EJ3: its row");
    is_int(m.ball[(size_t)(cy + 0.5) * m.width + 320], 1,
           "EJ3: and the map shows it there");
    rayo_image_free(&image);
    rayo_course_map_free(&m);
}

int main(void)
{
    rayo_course_map m;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    check_ej2();
    check_ej3();
    ok(rayo_course_map_make(RAYO_COURSE_EJ1, &m, &err) == RAYO_ERR_INVALID,
       "EJ1 has no map");
    return tap_done();
}
