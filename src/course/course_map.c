/*
 * course_map.c - the course's correct image of EJ2 or EJ3 taken apart:
 * for each pixel, the sphere its ray shows (or none) and, for each
 * light, L.N at the point and whether another sphere shadows it.
 *
 * It walks the student model's main (course_student.c: the same rays,
 * the same float arithmetic, the same sphere loops), so a pixel's sphere
 * is the one a correct program draws there.  The tone comparison reads a
 * student's image against it (tone_scene.c) to say what differs from
 * the scene in the statement's terms; it is not an image, and no mistake
 * is modelled here.
 */
#include <stdlib.h>
#include <string.h>

#include "course_student.h"

void rayo_course_map_free(rayo_course_map *map)
{
    free(map->ball);
    free(map->core);
    free(map->light);
    memset(map, 0, sizeof *map);
}

void rayo_course_ball_pixel(const rayo_course_map *map,
                            const rayo_course_ball *ball, double *x,
                            double *y)
{
    *x = map->width / 2.0 + map->focal * ball->center[0] / ball->center[2];
    *y = map->height / 2.0 - map->focal * ball->center[1] / ball->center[2];
}

/* One pixel: the sphere d shows and each light's term (the map's
   convention). */
static void take_apart(const course_student *s, course_fvec d,
                       signed char *ball, float *light)
{
    course_fvec o = course_fvec_make(0, 0, 0);
    const course_fball *b;
    course_fvec p, n;
    float t;
    size_t i, hit = rayo_course_student_nearest(s, o, d, &t);
    *ball = -1;
    for (i = 0; i < s->lamp_count; i++)
        light[i] = 0;
    if (hit == s->ball_count)
        return;
    *ball = (signed char)hit;
    b = &s->balls[hit];
    p = course_fpoint(o, d, t);
    n = course_fnormalize(course_fsub(p, b->center));
    for (i = 0; i < s->lamp_count; i++) {
        const course_flamp *lamp = &s->lamps[i];
        float limit = RAYO_COURSE_INFINITO, ln;
        course_fvec l = lamp->vector;
        if (lamp->point) {
            l = course_fsub(lamp->vector, p);
            limit = course_fnorm(l);
            l = course_fnormalize(l);
        }
        ln = course_fdot(l, n);
        if (!(ln > 0))
            continue;
        light[i] = rayo_course_student_shadowed(s, p, l, limit, hit) ? -ln
                                                                     : ln;
    }
}

/* core: the square of RAYO_COURSE_MAP_CORE around each pixel shows one
   sphere (or none); rows first, then columns. */
static void find_core(rayo_course_map *map, unsigned char *row_same)
{
    int w = (int)map->width, h = (int)map->height, k = RAYO_COURSE_MAP_CORE;
    int x, y, i;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            const signed char *b = map->ball + (size_t)y * w;
            int same = 1;
            for (i = x - k; same && i <= x + k; i++)
                if (i >= 0 && i < w && b[i] != b[x])
                    same = 0;
            row_same[(size_t)y * w + x] = (unsigned char)same;
        }
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            size_t at = (size_t)y * w + x;
            int same = 1;
            for (i = y - k; same && i <= y + k; i++)
                if (i >= 0 && i < h &&
                    (!row_same[(size_t)i * w + x] ||
                     map->ball[(size_t)i * w + x] != map->ball[at]))
                    same = 0;
            map->core[at] = (unsigned char)same;
        }
}

rayo_status rayo_course_map_make(rayo_course_exercise exercise,
                                 rayo_course_map *map, rayo_error *err)
{
    const rayo_course_data *data = rayo_course_data_of(exercise);
    course_student student;
    rayo_camera camera;
    rayo_status status;
    size_t pixels = (size_t)RAYO_COURSE_WIDTH * RAYO_COURSE_HEIGHT;
    int half_w = (int)(RAYO_COURSE_WIDTH / 2);
    int top = (int)(RAYO_COURSE_HEIGHT / 2);
    uint32_t i, j;
    float vz;
    memset(map, 0, sizeof *map);
    if (data == NULL || exercise == RAYO_COURSE_EJ1 ||
        data->ball_count > COURSE_MAX_BALLS ||
        data->lamp_count > COURSE_MAX_LAMPS)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "course: no map of exercise %d",
                              (int)exercise);
    status = rayo_camera_init(&camera, RAYO_COURSE_WIDTH, RAYO_COURSE_HEIGHT,
                              RAYO_COURSE_FOV, rayo_vec3_make(0, 0, 0), err);
    if (status != RAYO_OK)
        return status;
    map->exercise = exercise;
    map->width = RAYO_COURSE_WIDTH;
    map->height = RAYO_COURSE_HEIGHT;
    map->lamp_count = data->lamp_count;
    map->focal = camera.focal;
    map->ball = malloc(pixels);
    map->core = malloc(pixels);
    map->light = malloc(pixels * data->lamp_count * sizeof *map->light);
    if (map->ball == NULL || map->core == NULL || map->light == NULL) {
        rayo_course_map_free(map);
        return rayo_error_set(err, RAYO_ERR_NOMEM,
                              "course: out of memory for the scene's map");
    }
    vz = (float)camera.focal;
    rayo_course_student_init(&student, data, RAYO_MISTAKE_NONE);
    for (j = 0; j < RAYO_COURSE_HEIGHT; j++) {
        unsigned char maybe[RAYO_COURSE_WIDTH];
        float vy = (float)(top - (int)j);
        rayo_course_student_row_may_hit(&student, vy, vz, half_w, maybe);
        for (i = 0; i < RAYO_COURSE_WIDTH; i++) {
            size_t at = (size_t)j * RAYO_COURSE_WIDTH + i;
            float *light = map->light + at * data->lamp_count;
            float vx = (float)((int)i - half_w);
            student.pixel = (int)i;
            if (!maybe[i]) {
                size_t l;
                map->ball[at] = -1;
                for (l = 0; l < data->lamp_count; l++)
                    light[l] = 0;
                continue;
            }
            take_apart(&student,
                       course_fnormalize(course_fvec_make(vx, vy, vz)),
                       map->ball + at, light);
        }
    }
    /* the map's core is made with the lights' memory free of use yet */
    {
        unsigned char *row_same = malloc(pixels);
        if (row_same == NULL) {
            rayo_course_map_free(map);
            return rayo_error_set(err, RAYO_ERR_NOMEM,
                                  "course: out of memory for the scene's "
                                  "map");
        }
        find_core(map, row_same);
        free(row_same);
    }
    return RAYO_OK;
}
