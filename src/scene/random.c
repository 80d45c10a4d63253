/*
 * random.c - the seeded generators of many-sphere scenes
 * (scene_random.h): the field of spheres on a ground plane that the
 * benchmark renders, and the cloud that is the hierarchy's worst case.
 *
 * A 64-bit linear congruential generator: cheap, the same on every
 * platform, and plenty for spreading spheres about.  Not for statistics
 * or anything secret.
 */
#include "rayo/scene_random.h"

#include "rayo/limits.h"

void rayo_lcg_seed(rayo_lcg *lcg, uint64_t seed)
{
    lcg->state = seed;
}

double rayo_lcg_next(rayo_lcg *lcg)
{
    lcg->state = lcg->state * 6364136223846793005u + 1442695040888963407u;
    return (double)(lcg->state >> 11) * (1.0 / 9007199254740992.0);
}

static double uniform(rayo_lcg *lcg, double lo, double hi)
{
    return lo + (hi - lo) * rayo_lcg_next(lcg);
}

/* Adds 8 coloured materials; *first receives the first one's id. */
static rayo_status add_palette(rayo_scene *scene, unsigned *first,
                               rayo_error *err)
{
    static const double colours[8][3] = {
        {0.9, 0.2, 0.2}, {0.2, 0.8, 0.3}, {0.2, 0.4, 0.9}, {0.9, 0.8, 0.2},
        {0.8, 0.3, 0.8}, {0.2, 0.8, 0.8}, {0.9, 0.9, 0.9}, {0.9, 0.5, 0.1}};
    size_t i;
    for (i = 0; i < 8; i++) {
        rayo_material m;
        unsigned id;
        rayo_status status;
        m.color = rayo_vec3_make(colours[i][0], colours[i][1], colours[i][2]);
        m.ka = 0.1;
        m.kd = 0.8;
        m.ks = 0.3;
        m.shininess = 32.0;
        m.reflectivity = i == 6 ? 0.5 : 0.0;
        status = rayo_scene_add_material(scene, &m, &id, err);
        if (status != RAYO_OK)
            return status;
        if (i == 0)
            *first = id;
    }
    return RAYO_OK;
}

/* Refuses a count of 0 or one that would pass the object limit. */
static rayo_status check_count(const rayo_scene *scene, size_t count,
                               size_t extra, rayo_error *err)
{
    size_t have = rayo_scene_object_count(scene);
    if (count == 0)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "random scene of 0 spheres; expected at "
                              "least 1");
    if (count > RAYO_MAX_OBJECTS || extra > RAYO_MAX_OBJECTS - count ||
        have > RAYO_MAX_OBJECTS - count - extra)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "%lu random spheres would pass the limit of "
                              "%lu objects in one scene",
                              (unsigned long)count, RAYO_MAX_OBJECTS);
    return RAYO_OK;
}

static rayo_status add_ground(rayo_scene *scene, rayo_error *err)
{
    rayo_material m = {{0.6, 0.6, 0.6}, 0.1, 0.8, 0.0, 0.0, 0.0};
    unsigned id;
    rayo_status status = rayo_scene_add_material(scene, &m, &id, err);
    if (status != RAYO_OK)
        return status;
    return rayo_scene_add_plane(scene, rayo_vec3_make(0, -1, 0),
                                rayo_vec3_make(0, 1, 0), id, err);
}

rayo_status rayo_scene_random_spheres(rayo_scene *scene, size_t count,
                                      uint64_t seed, rayo_error *err)
{
    rayo_lcg lcg;
    unsigned first = 0;
    double spacing;
    size_t i;
    rayo_status status = check_count(scene, count, 1, err);
    if (status == RAYO_OK)
        status = add_ground(scene, err);
    if (status == RAYO_OK)
        status = add_palette(scene, &first, err);
    if (status != RAYO_OK)
        return status;
    rayo_lcg_seed(&lcg, seed);
    spacing = sqrt(10000.0 / (double)count);
    for (i = 0; i < count; i++) {
        double x = uniform(&lcg, -50.0, 50.0);
        double z = uniform(&lcg, 5.0, 105.0);
        double r = 0.3 * spacing * (0.5 + 0.5 * rayo_lcg_next(&lcg));
        status = rayo_scene_add_sphere_material(
            scene, rayo_vec3_make(x, r - 1.0, z), r,
            first + (unsigned)(i % 8), err);
        if (status != RAYO_OK)
            return status;
    }
    return RAYO_OK;
}

rayo_status rayo_scene_random_cloud(rayo_scene *scene, size_t count,
                                    uint64_t seed, rayo_error *err)
{
    rayo_lcg lcg;
    unsigned first = 0;
    double scale;
    size_t i;
    rayo_status status = check_count(scene, count, 0, err);
    if (status == RAYO_OK)
        status = add_palette(scene, &first, err);
    if (status != RAYO_OK)
        return status;
    rayo_lcg_seed(&lcg, seed);
    scale = sqrt(100000.0 / (double)count);
    for (i = 0; i < count; i++) {
        double z = uniform(&lcg, 10.0, 100.0);
        double x = uniform(&lcg, -z, z);
        double y = uniform(&lcg, -0.5625 * z, 0.5625 * z);
        double r = z * scale * uniform(&lcg, 0.001, 0.0035);
        status = rayo_scene_add_sphere_material(
            scene, rayo_vec3_make(x, y, z), r, first + (unsigned)(i % 8),
            err);
        if (status != RAYO_OK)
            return status;
    }
    return RAYO_OK;
}
