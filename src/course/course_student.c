/*
 * course_student.c - the main and the sphere loops of the student's
 * program of exercises 2 and 3: the scene's constants as float, the pixel
 * loop of the statement, and the two loops over the spheres array in
 * order (the sphere a ray shows, and the shadow test).  The shading is
 * course_student_gray.c and course_student_color.c.
 *
 * The pixel loop is the statement's main: vz = ANCHO / 2 / tan(FOV / 2)
 * as a float (rayo_camera_init's focal times focal_scale, rounded), rows
 * for vy = ALTO / 2 down to -ALTO / 2 + 1 (with literal_rows from
 * ALTO / 2 - 1 down to -ALTO / 2), columns vx = -ANCHO / 2 .. ANCHO / 2 - 1,
 * direction normalizar(vx, vy, vz).  That is the project's convention
 * (x = i - w/2, y = j - h/2 from the top, direction (x, -y, f)): the top
 * row's direction has y component +240.
 */
#include <string.h>

#include "course_student.h"

static course_fvec fvec_of(const double v[3])
{
    return course_fvec_make((float)v[0], (float)v[1], (float)v[2]);
}

/* The program's constants: the statement's numbers written as float. */
void rayo_course_student_init(course_student *s, const rayo_course_data *data,
                              rayo_course_mistake mistake)
{
    size_t i;
    s->ball_count = data->ball_count;
    for (i = 0; i < data->ball_count; i++) {
        const rayo_course_ball *b = &data->balls[i];
        s->balls[i].center = fvec_of(b->center);
        s->balls[i].color = fvec_of(b->color);
        s->balls[i].radius = (float)b->radius;
        s->balls[i].ka = (float)b->ka;
        s->balls[i].kd = (float)b->kd;
    }
    s->lamp_count = data->lamp_count;
    for (i = 0; i < data->lamp_count; i++) {
        s->lamps[i].point = data->lamps[i].point;
        s->lamps[i].vector = fvec_of(data->lamps[i].vector);
        s->lamps[i].color = fvec_of(data->lamps[i].color);
    }
    s->ambient = fvec_of(data->ambient);
    s->mistake = mistake;
    s->pixel = -1;
}

size_t rayo_course_student_nearest(const course_student *s, course_fvec o,
                                   course_fvec d, float *t)
{
    int far_root = s->mistake == RAYO_MISTAKE_FAR_ROOT;
    float tmin = RAYO_COURSE_INFINITO;
    size_t i, imin = s->ball_count;
    for (i = 0; i < s->ball_count; i++) {
        float ti;
        if (s->pixel >= 0 &&
            (s->pixel < s->span_lo[i] || s->pixel > s->span_hi[i]))
            continue; /* course_fdistance would say INFINITO */
        ti = course_fdistance(&s->balls[i], o, d, far_root);
        if (ti < tmin) {
            tmin = ti;
            imin = i;
            /* FIRST_SPHERE: `if (t < INFINITO) { ...; break; }` */
            if (s->mistake == RAYO_MISTAKE_FIRST_SPHERE)
                break;
        }
    }
    *t = tmin;
    return imin;
}

int rayo_course_student_shadowed(const course_student *s, course_fvec p,
                                 course_fvec l, float limit, size_t self)
{
    int far_root = s->mistake == RAYO_MISTAKE_FAR_ROOT;
    size_t i;
    if (s->mistake == RAYO_MISTAKE_NO_SHADOWS)
        return 0;
    for (i = 0; i < s->ball_count; i++) {
        /* SELF_SHADOW: the `if (i == imin) continue;` left out.  From P
           on its own sphere the roots are about 2 beta < 0 and 0, and
           whether the float root near 0 comes out > 0 is rounding's
           choice: a deterministic speckle over some 60% of the lit
           side, as real student programs show, not a lit side wholly
           in shadow. */
        if (i == self && s->mistake != RAYO_MISTAKE_SELF_SHADOW)
            continue;
        if (course_fdistance(&s->balls[i], p, l, far_root) < limit)
            return 1;
    }
    return 0;
}

/*
 * Marks in maybe[] the pixels of the row at height vy whose ray may meet
 * some sphere, and sets each sphere's span of them (s->span_lo,
 * span_hi; empty when lo > hi); outside its span a sphere's delta is
 * negative, and outside them all the student's program finds no sphere
 * and prints black, whatever its mistake.  A ray (vx, vy, vz) from the eye meets a sphere of centre C
 * and radius r when (d.C)^2 >= |d|^2 (|C|^2 - r^2): along the row a
 * quadratic in vx, solved in double for a sphere 5% larger plus 0.01
 * (a margin hundreds of times the float model's rounding of delta), and
 * widened by a pixel on each side.  A sphere around the eye, or one
 * whose cone of rays is not bounded along the row, marks the whole row.
 */
void rayo_course_student_row_may_hit(course_student *s, double vy, double vz,
                                     int half_w, unsigned char *maybe)
{
    size_t b;
    int w = (int)RAYO_COURSE_WIDTH;
    memset(maybe, 0, RAYO_COURSE_WIDTH);
    for (b = 0; b < s->ball_count; b++) {
        s->span_lo[b] = 0;
        s->span_hi[b] = w - 1;
    }
    for (b = 0; b < s->ball_count; b++) {
        const course_fball *ball = &s->balls[b];
        double cx = ball->center.x, cy = ball->center.y, cz = ball->center.z;
        double r = 1.05 * (double)ball->radius + 0.01;
        double k = cx * cx + cy * cy + cz * cz - r * r;
        double bb = vy * cy + vz * cz, e = vy * vy + vz * vz;
        double qa = cx * cx - k, qb = 2 * cx * bb, qc = bb * bb - e * k;
        double disc = qb * qb - 4 * qa * qc, x0, x1, root;
        int i0, i1, i;
        if (k <= 0 || qa >= 0) {
            /* this and the spheres after it: the whole row */
            memset(maybe, 1, RAYO_COURSE_WIDTH);
            return;
        }
        s->span_lo[b] = w;
        s->span_hi[b] = -1;
        if (disc < 0)
            continue;
        root = sqrt(disc);
        /* qa < 0: between the roots */
        x0 = (-qb + root) / (2 * qa);
        x1 = (-qb - root) / (2 * qa);
        if (x0 > x1) {
            double swap = x0;
            x0 = x1;
            x1 = swap;
        }
        x0 = floor(x0) + half_w - 1;
        x1 = ceil(x1) + half_w + 1;
        if (x1 < 0 || x0 >= w)
            continue;
        i0 = x0 < 0 ? 0 : (int)x0;
        i1 = x1 >= w ? w - 1 : (int)x1;
        s->span_lo[b] = i0;
        s->span_hi[b] = i1;
        for (i = i0; i <= i1; i++)
            maybe[i] = 1;
    }
}

rayo_status rayo_course_render_student(rayo_course_exercise exercise,
                                       const rayo_course_options *options,
                                       rayo_image *image, rayo_error *err)
{
    return rayo_course_render_student_rows(exercise, options, image, 0,
                                           RAYO_COURSE_HEIGHT, err);
}

rayo_status rayo_course_render_student_rows(rayo_course_exercise exercise,
                                            const rayo_course_options *options,
                                            rayo_image *image, uint32_t first,
                                            uint32_t end, rayo_error *err)
{
    const rayo_course_data *data = rayo_course_data_of(exercise);
    course_student student;
    rayo_camera camera;
    rayo_image_info info;
    rayo_status status;
    float vz;
    int gray = exercise == RAYO_COURSE_EJ2;
    int top = (int)(RAYO_COURSE_HEIGHT / 2) - (options->literal_rows ? 1 : 0);
    int half_w = (int)(RAYO_COURSE_WIDTH / 2);
    uint32_t i, j;
    if (data == NULL || exercise == RAYO_COURSE_EJ1 ||
        data->ball_count > COURSE_MAX_BALLS ||
        data->lamp_count > COURSE_MAX_LAMPS)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "course: no student model of exercise %d",
                              (int)exercise);
    status = rayo_camera_init(&camera, RAYO_COURSE_WIDTH, RAYO_COURSE_HEIGHT,
                              RAYO_COURSE_FOV, rayo_vec3_make(0, 0, 0), err);
    if (status != RAYO_OK)
        return status;
    vz = (float)(camera.focal * options->focal_scale);
    rayo_course_student_init(&student, data, options->mistake);
    info = gray ? rayo_image_info_gray8(RAYO_COURSE_WIDTH, RAYO_COURSE_HEIGHT)
                : rayo_image_info_rgb8(RAYO_COURSE_WIDTH, RAYO_COURSE_HEIGHT);
    if (first == 0) {
        status = rayo_image_create(image, &info, err);
        if (status != RAYO_OK)
            return status;
    }
    if (end > RAYO_COURSE_HEIGHT)
        end = RAYO_COURSE_HEIGHT;
    for (j = first; j < end; j++) {
        unsigned char *row = rayo_image_row(image, j);
        unsigned char maybe[RAYO_COURSE_WIDTH];
        float vy = (float)(top - (int)j);
        rayo_course_student_row_may_hit(&student, vy, vz, half_w, maybe);
        for (i = 0; i < RAYO_COURSE_WIDTH; i++) {
            float vx = (float)((int)i - half_w);
            course_fvec d;
            if (!maybe[i]) {
                memset(row + (gray ? i : 3 * (size_t)i), 0, gray ? 1 : 3);
                continue;
            }
            d = course_fnormalize(course_fvec_make(vx, vy, vz));
            student.pixel = (int)i;
            if (gray)
                row[i] = rayo_course_student_gray(&student, d);
            else
                rayo_course_student_color(&student, d, row + 3 * (size_t)i);
        }
    }
    return RAYO_OK;
}
