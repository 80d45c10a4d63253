/*
 * course_scenes.c - the numbers of the course's three scenes, as the
 * statements give them (seed.h for EJ1, escenas-del-curso.md for EJ2 and
 * EJ3, the same as examples/ej2.scene and examples/ej3.scene), and rayo
 * scenes built from them for the exact render.
 *
 * The data is in the statements' array order: the student model loops
 * over it in that order, and FIRST_SPHERE depends on it.
 */
#include "rayo/seed.h"

#include "course_impl.h"

#define WHITE {1, 1, 1}

static const rayo_course_ball ej1_balls[] = {
    {{RAYO_SEED_CENTER_X, RAYO_SEED_CENTER_Y, RAYO_SEED_CENTER_Z},
     RAYO_SEED_RADIUS, WHITE, 1, 1},
};

static const rayo_course_ball ej2_balls[] = {
    {{-0.4, 0.75, 1.55}, 0.3, WHITE, 1, 1},
    {{-0.55, -0.4, 2}, 0.85, WHITE, 1, 1},
    {{3, 1.5, 4}, 0.4, WHITE, 1, 1},
    {{3, 1.5, 5}, 0.4, WHITE, 1, 1},
    {{3, -1.5, 4}, 0.4, WHITE, 1, 1},
    {{3, -1.5, 5}, 0.4, WHITE, 1, 1},
};

static const rayo_course_lamp ej2_lamps[] = {
    {0, {0.2873478855663454, 0.9578262852211513, 0}, {255, 255, 255}},
};

static const rayo_course_ball ej3_balls[] = {
    {{0, 1, 2.4}, 0.3, WHITE, 1, 1},
    {{0, -0.4, 3}, 1, WHITE, 1, 1},
    {{-2, -0.6, 3}, 0.3, {1, 0, 0}, 1, 0.8},
    {{-1.73, -0.6, 2}, 0.3, {1, 1, 0}, 1, 1},
    {{-1, -0.6, 1.26}, 0.3, {0, 1, 0}, 1, 1},
    {{0, -0.6, 1}, 0.3, WHITE, 1, 1},
    {{1, -0.6, 1.26}, 0.3, {0, 1, 1}, 1, 1},
    {{1.73, -0.6, 2}, 0.3, {0, 0, 1}, 1, 1},
    {{2, -0.6, 3}, 0.3, {1, 0, 1}, 1, 1},
    /* back row: ka = 1, kd rising left to right */
    {{-3, 2.5, 4.3}, 0.3, WHITE, 1, 0},
    {{-2, 2.5, 4.3}, 0.3, WHITE, 1, 0.16},
    {{-1, 2.5, 4.3}, 0.3, WHITE, 1, 0.33},
    {{0, 2.5, 4.3}, 0.3, WHITE, 1, 0.5},
    {{1, 2.5, 4.3}, 0.3, WHITE, 1, 0.66},
    {{2, 2.5, 4.3}, 0.3, WHITE, 1, 0.83},
    {{3, 2.5, 4.3}, 0.3, WHITE, 1, 1},
    /* middle row: kd = 1, ka rising left to right */
    {{-3, 1.5, 4}, 0.3, WHITE, 0, 1},
    {{-2, 1.5, 4}, 0.3, WHITE, 0.16, 1},
    {{-1, 1.5, 4}, 0.3, WHITE, 0.33, 1},
    {{0, 1.5, 4}, 0.3, WHITE, 0.5, 1},
    {{1, 1.5, 4}, 0.3, WHITE, 0.66, 1},
    {{2, 1.5, 4}, 0.3, WHITE, 0.83, 1},
    {{3, 1.5, 4}, 0.3, WHITE, 1, 1},
};

static const rayo_course_lamp ej3_lamps[] = {
    {0, {0, 1, 0}, {0.2, 0.2, 0.2}},
    {1, {-2, 10, 2.5}, {0.9, 0, 0}},
    {1, {2, 10, 2.5}, {0, 0.9, 0}},
    {1, {0, 10, 5}, {0, 0, 0.9}},
};

#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

const rayo_course_data course_scene_data[RAYO_COURSE_EXERCISES] = {
    {ej1_balls, COUNT(ej1_balls), NULL, 0, {0, 0, 0}, RAYO_SHADE_HIT},
    {ej2_balls, COUNT(ej2_balls), ej2_lamps, COUNT(ej2_lamps), {5, 5, 5},
     RAYO_SHADE_COURSE_GRAY},
    {ej3_balls, COUNT(ej3_balls), ej3_lamps, COUNT(ej3_lamps),
     {0.05, 0.05, 0.05}, RAYO_SHADE_COURSE_COLOR},
};

const rayo_course_data *rayo_course_data_of(rayo_course_exercise exercise)
{
    if ((unsigned)exercise >= RAYO_COURSE_EXERCISES)
        return NULL;
    return &course_scene_data[exercise];
}

static rayo_vec3 vec_of(const double v[3])
{
    return rayo_vec3_make(v[0], v[1], v[2]);
}

/* Ball b with its centre and radius from at[4] when at is not NULL. */
static rayo_status add_ball(rayo_scene *scene, const rayo_course_ball *b,
                            const double *at, rayo_error *err)
{
    rayo_material material;
    unsigned id;
    rayo_status status;
    material.color = vec_of(b->color);
    material.ka = b->ka;
    material.kd = b->kd;
    material.ks = 0;
    material.shininess = 0;
    material.reflectivity = 0;
    status = rayo_scene_add_material(scene, &material, &id, err);
    if (status != RAYO_OK)
        return status;
    return rayo_scene_add_sphere_material(
        scene, vec_of(at != NULL ? at : b->center),
        at != NULL ? at[3] : b->radius, id, err);
}

static rayo_status add_lamp(rayo_scene *scene, const rayo_course_lamp *l,
                            rayo_error *err)
{
    rayo_light light;
    light.kind = l->point ? RAYO_LIGHT_POINT : RAYO_LIGHT_DIRECTIONAL;
    light.vector = vec_of(l->vector);
    light.color = vec_of(l->color);
    return rayo_scene_add_light(scene, &light, err);
}

static rayo_status fill(rayo_scene *scene, const rayo_course_data *data,
                        const double *spheres, size_t count, rayo_error *err)
{
    rayo_status status = RAYO_OK;
    size_t i;
    rayo_scene_set_ambient(scene, vec_of(data->ambient));
    for (i = 0; status == RAYO_OK && i < data->ball_count; i++)
        status = add_ball(scene, &data->balls[i],
                          i < count ? spheres + 4 * i : NULL, err);
    for (i = 0; status == RAYO_OK && i < data->lamp_count; i++)
        status = add_lamp(scene, &data->lamps[i], err);
    if (status == RAYO_OK)
        status = rayo_scene_prepare(scene, err);
    return status;
}

rayo_status rayo_course_scene_build(rayo_course_exercise exercise,
                                    rayo_scene **scene, rayo_error *err)
{
    return rayo_course_scene_build_moved(exercise, NULL, 0, scene, err);
}

rayo_status rayo_course_scene_build_moved(rayo_course_exercise exercise,
                                          const double *spheres, size_t count,
                                          rayo_scene **scene, rayo_error *err)
{
    const rayo_course_data *data = rayo_course_data_of(exercise);
    rayo_status status;
    *scene = NULL;
    if (data == NULL)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "course: no exercise number %d",
                              (int)exercise);
    status = rayo_scene_create(scene, err);
    if (status == RAYO_OK)
        status = fill(*scene, data, spheres, count, err);
    if (status != RAYO_OK) {
        rayo_scene_free(*scene);
        *scene = NULL;
    }
    return status;
}
