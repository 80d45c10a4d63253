/*
 * trace.c - the rays the Embree program casts (trace.h): rayo's primary
 * rays through Embree's scene, as occlusion queries or as nearest hits
 * with one shadow ray towards the light from each lit side, one at a time
 * or sixteen in a packet, the planes in Embree's scene or tested first.
 * Not where anything is read, built or timed (embree_rays.c).
 */
#define _POSIX_C_SOURCE 200809L

#include "trace.h"

#include <math.h>

/* rayo_camera_ray: the direction through pixel (i, j). */
rayo_vec3 pixel_direction(const camera *c, const scene *s, unsigned i,
                          unsigned j)
{
    double x = (double)i - (double)(s->width / 2);
    double y = (double)j - (double)(s->height / 2);
    return rayo_vec3_normalize(rayo_vec3_add(rayo_vec3_add(rayo_vec3_scale(c->right, x), rayo_vec3_scale(c->up, -y)),
                         rayo_vec3_scale(c->forward, c->focal)));
}

/* The shadow ray's start past the hit point, against self-hits: rayo
 * skips the object hit itself; with floats, an offset relative to the
 * point's size does that. */
static float shadow_offset(float x, float y, float z)
{
    float m = fabsf(x);
    if (fabsf(y) > m)
        m = fabsf(y);
    if (fabsf(z) > m)
        m = fabsf(z);
    return 1e-4f * (1.0f + m);
}

/* --planes first: the nearest plane along the ray within (tnear, tfar),
 * tested before Embree's hierarchy, as rayo tests its unbounded planes
 * before its own: 1 with *t and *k, or 0. */
static int nearest_plane(const job *jb, const float o[3], const float d[3],
                         float tnear, float tfar, float *t, size_t *k)
{
    size_t i;
    int found = 0;
    for (i = 0; i < jb->s->plane_count; i++) {
        const float *n = jb->plane_n[i];
        float den = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
        float ti =
            (jb->plane_d[i] - (n[0] * o[0] + n[1] * o[1] + n[2] * o[2])) / den;
        if (den != 0 && ti > tnear && ti < tfar) {
            tfar = ti;
            *t = ti;
            *k = i;
            found = 1;
        }
    }
    return found;
}

/* Where a hit (primary direction d, geometric normal ng, point p) sends a
 * shadow ray: 1 and the ray's direction and length, or 0 when the lit
 * side faces away (rayo's Li.N <= 0 test). */
static int shadow_ray(const job *jb, const float p[3], const float d[3],
                      const float ng[3], float dir[3], float *length)
{
    float n[3], l[3], len, facing;
    int c;
    facing = ng[0] * d[0] + ng[1] * d[1] + ng[2] * d[2];
    for (c = 0; c < 3; c++)
        n[c] = facing > 0 ? -ng[c] : ng[c];
    l[0] = (float)jb->s->light.x - p[0];
    l[1] = (float)jb->s->light.y - p[1];
    l[2] = (float)jb->s->light.z - p[2];
    len = sqrtf(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
    if (!(len > 0))
        return 0;
    for (c = 0; c < 3; c++)
        dir[c] = l[c] / len;
    if (!(dir[0] * n[0] + dir[1] * n[1] + dir[2] * n[2] > 0))
        return 0;
    *length = len;
    return 1;
}

void trace_single(const job *jb, pass *out)
{
    const scene *s = jb->s;
    struct RTCIntersectContext context;
    unsigned i, j;
    rtcInitIntersectContext(&context);
    for (j = 0; j < s->height; j++)
        for (i = 0; i < s->width; i++) {
            rayo_vec3 d = pixel_direction(&jb->cam, s, i, j);
            struct RTCRayHit rh;
            int hit, plane;
            float plane_t = 0;
            size_t plane_k = 0;
            rh.ray.org_x = (float)jb->cam.origin.x;
            rh.ray.org_y = (float)jb->cam.origin.y;
            rh.ray.org_z = (float)jb->cam.origin.z;
            rh.ray.dir_x = (float)d.x;
            rh.ray.dir_y = (float)d.y;
            rh.ray.dir_z = (float)d.z;
            rh.ray.tnear = 0.0f;
            rh.ray.tfar = INFINITY;
            rh.ray.time = 0.0f;
            rh.ray.mask = 0xFFFFFFFFu;
            rh.ray.id = 0;
            rh.ray.flags = 0;
            out->rays++;
            plane = 0;
            if (jb->planes_first) {
                float o[3], dd[3];
                o[0] = rh.ray.org_x;
                o[1] = rh.ray.org_y;
                o[2] = rh.ray.org_z;
                dd[0] = rh.ray.dir_x;
                dd[1] = rh.ray.dir_y;
                dd[2] = rh.ray.dir_z;
                plane = nearest_plane(jb, o, dd, 0.0f, INFINITY, &plane_t,
                                      &plane_k);
                if (plane)
                    rh.ray.tfar = plane_t;
            }
            if (!jb->shadow) {
                if (plane) {
                    hit = 1;
                } else {
                    rtcOccluded1(jb->es, &context, &rh.ray);
                    hit = rh.ray.tfar < 0;
                }
            } else {
                rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(jb->es, &context, &rh);
                hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
                if (!hit && plane) {
                    hit = 1;
                    rh.hit.Ng_x = jb->plane_n[plane_k][0];
                    rh.hit.Ng_y = jb->plane_n[plane_k][1];
                    rh.hit.Ng_z = jb->plane_n[plane_k][2];
                }
            }
            if (jb->mask != NULL)
                jb->mask[(size_t)j * s->width + i] = (unsigned char)hit;
            if (!hit)
                continue;
            out->hits++;
            if (jb->shadow && jb->s->has_light) {
                float p[3], dir[3], ng[3], len;
                float dd[3];
                dd[0] = rh.ray.dir_x;
                dd[1] = rh.ray.dir_y;
                dd[2] = rh.ray.dir_z;
                p[0] = rh.ray.org_x + rh.ray.tfar * dd[0];
                p[1] = rh.ray.org_y + rh.ray.tfar * dd[1];
                p[2] = rh.ray.org_z + rh.ray.tfar * dd[2];
                ng[0] = rh.hit.Ng_x;
                ng[1] = rh.hit.Ng_y;
                ng[2] = rh.hit.Ng_z;
                if (shadow_ray(jb, p, dd, ng, dir, &len)) {
                    struct RTCRay sr;
                    sr.org_x = p[0];
                    sr.org_y = p[1];
                    sr.org_z = p[2];
                    sr.dir_x = dir[0];
                    sr.dir_y = dir[1];
                    sr.dir_z = dir[2];
                    sr.tnear = shadow_offset(p[0], p[1], p[2]);
                    sr.tfar = len;
                    sr.time = 0.0f;
                    sr.mask = 0xFFFFFFFFu;
                    sr.id = 0;
                    sr.flags = 0;
                    out->rays++;
                    if (jb->planes_first &&
                        nearest_plane(jb, p, dir, sr.tnear, sr.tfar, &plane_t,
                                      &plane_k))
                        continue;
                    rtcOccluded1(jb->es, &context, &sr);
                    if (sr.tfar >= 0)
                        out->lit++;
                }
            }
        }
}

/* 4x4 tiles of pixels, one 16-ray packet each (lanes off past the edge). */
void trace_packets(const job *jb, pass *out)
{
    const scene *s = jb->s;
    struct RTCIntersectContext coherent, incoherent;
    unsigned ti, tj;
    rtcInitIntersectContext(&coherent);
    coherent.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    rtcInitIntersectContext(&incoherent);
    for (tj = 0; tj < s->height; tj += 4)
        for (ti = 0; ti < s->width; ti += 4) {
            struct RTCRayHit16 rh;
            struct RTCRay16 sr;
            /* The valid masks must be aligned like the packets. */
            _Alignas(64) int valid[16];
            _Alignas(64) int svalid[16];
            _Alignas(64) int query[16];
            int k, any_shadow = 0, any_query = 0, plane[16];
            size_t plane_k[16];
            float plane_t = 0;
            for (k = 0; k < 16; k++) {
                unsigned i = ti + (unsigned)(k & 3),
                         j = tj + (unsigned)(k >> 2);
                rayo_vec3 d;
                valid[k] = i < s->width && j < s->height ? -1 : 0;
                d = valid[k] ? pixel_direction(&jb->cam, s, i, j)
                             : rayo_vec3_make(0, 0, 1);
                rh.ray.org_x[k] = (float)jb->cam.origin.x;
                rh.ray.org_y[k] = (float)jb->cam.origin.y;
                rh.ray.org_z[k] = (float)jb->cam.origin.z;
                rh.ray.dir_x[k] = (float)d.x;
                rh.ray.dir_y[k] = (float)d.y;
                rh.ray.dir_z[k] = (float)d.z;
                rh.ray.tnear[k] = 0.0f;
                rh.ray.tfar[k] = INFINITY;
                rh.ray.time[k] = 0.0f;
                rh.ray.mask[k] = 0xFFFFFFFFu;
                rh.ray.id[k] = (unsigned)k;
                rh.ray.flags[k] = 0;
                rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
                if (valid[k])
                    out->rays++;
                plane[k] = 0;
                query[k] = valid[k];
                if (valid[k] && jb->planes_first) {
                    float o[3], dd[3];
                    o[0] = rh.ray.org_x[k];
                    o[1] = rh.ray.org_y[k];
                    o[2] = rh.ray.org_z[k];
                    dd[0] = rh.ray.dir_x[k];
                    dd[1] = rh.ray.dir_y[k];
                    dd[2] = rh.ray.dir_z[k];
                    plane[k] = nearest_plane(jb, o, dd, 0.0f, INFINITY,
                                             &plane_t, &plane_k[k]);
                    if (plane[k]) {
                        rh.ray.tfar[k] = plane_t;
                        if (!jb->shadow)
                            query[k] = 0;
                    }
                }
                any_query |= query[k];
            }
            if (any_query && !jb->shadow)
                rtcOccluded16(query, jb->es, &coherent, &rh.ray);
            else if (any_query)
                rtcIntersect16(query, jb->es, &coherent, &rh);
            for (k = 0; k < 16; k++) {
                int hit;
                svalid[k] = 0;
                if (!valid[k])
                    continue;
                hit = jb->shadow ? rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID
                                 : rh.ray.tfar[k] < 0;
                if (!hit && plane[k]) {
                    hit = 1;
                    rh.hit.Ng_x[k] = jb->plane_n[plane_k[k]][0];
                    rh.hit.Ng_y[k] = jb->plane_n[plane_k[k]][1];
                    rh.hit.Ng_z[k] = jb->plane_n[plane_k[k]][2];
                }
                if (jb->mask != NULL)
                    jb->mask[(size_t)(tj + (unsigned)(k >> 2)) * s->width +
                             ti + (unsigned)(k & 3)] = (unsigned char)hit;
                if (!hit)
                    continue;
                out->hits++;
                if (jb->shadow && s->has_light) {
                    float p[3], dd[3], ng[3], dir[3], len;
                    dd[0] = rh.ray.dir_x[k];
                    dd[1] = rh.ray.dir_y[k];
                    dd[2] = rh.ray.dir_z[k];
                    p[0] = rh.ray.org_x[k] + rh.ray.tfar[k] * dd[0];
                    p[1] = rh.ray.org_y[k] + rh.ray.tfar[k] * dd[1];
                    p[2] = rh.ray.org_z[k] + rh.ray.tfar[k] * dd[2];
                    ng[0] = rh.hit.Ng_x[k];
                    ng[1] = rh.hit.Ng_y[k];
                    ng[2] = rh.hit.Ng_z[k];
                    if (shadow_ray(jb, p, dd, ng, dir, &len)) {
                        svalid[k] = -1;
                        sr.org_x[k] = p[0];
                        sr.org_y[k] = p[1];
                        sr.org_z[k] = p[2];
                        sr.dir_x[k] = dir[0];
                        sr.dir_y[k] = dir[1];
                        sr.dir_z[k] = dir[2];
                        sr.tnear[k] = shadow_offset(p[0], p[1], p[2]);
                        sr.tfar[k] = len;
                        sr.time[k] = 0.0f;
                        sr.mask[k] = 0xFFFFFFFFu;
                        sr.id[k] = (unsigned)k;
                        sr.flags[k] = 0;
                        out->rays++;
                        if (jb->planes_first &&
                            nearest_plane(jb, p, dir, sr.tnear[k], len,
                                          &plane_t, &plane_k[k])) {
                            svalid[k] = 0; /* in the plane's shadow */
                            continue;
                        }
                        any_shadow = 1;
                    }
                }
            }
            if (!any_shadow)
                continue;
            rtcOccluded16(svalid, jb->es, &incoherent, &sr);
            for (k = 0; k < 16; k++)
                if (svalid[k] && sr.tfar[k] >= 0)
                    out->lit++;
        }
}
