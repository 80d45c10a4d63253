/*
 * random.c - the seeded generator of many-sphere scenes (scene_random.h).
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

static rayo_status add_palette(rayo_scene *scene, unsigned first[1],
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
            first[0] = id;
    }
    return RAYO_OK;
}

rayo_status rayo_scene_random_spheres(rayo_scene *scene, size_t count,
                                      uint64_t seed, rayo_error *err)
{
    rayo_lcg lcg;
    unsigned first = 0;
    double scale;
    size_t i;
    rayo_status status;
    if (count > RAYO_MAX_OBJECTS ||
        rayo_scene_object_count(scene) > RAYO_MAX_OBJECTS - count)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "%lu random spheres would pass the limit of "
                              "%lu objects in one scene",
                              (unsigned long)count, RAYO_MAX_OBJECTS);
    status = add_palette(scene, &first, err);
    if (status != RAYO_OK)
        return status;
    rayo_lcg_seed(&lcg, seed);
    scale = count ? sqrt(100000.0 / (double)count) : 1.0;
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
