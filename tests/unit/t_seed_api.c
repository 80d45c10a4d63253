/*
 * t_seed_api.c - the assignment's three functions against values worked
 * out by hand, and the assignment's constants against seed.h.
 */
#include <math.h>

#include "rayo/ejercicio1.h"
#include "rayo/seed.h"
#include "tap.h"

/* The unit vector towards (x, y, z), in float as a student computes it. */
static int hits_towards(double x, double y, double z)
{
    double n = sqrt(x * x + y * y + z * z);
    return intersecta_esfera((float)(x / n), (float)(y / n), (float)(z / n));
}

int main(void)
{
    /* producto_interno: (1,2,3).(4,5,6) = 4 + 10 + 18 = 32. */
    is_double(producto_interno(1, 2, 3, 4, 5, 6), 32.0, 0,
              "producto_interno (1,2,3).(4,5,6) = 32");
    is_double(producto_interno(1, 0, 0, 0, 1, 0), 0.0, 0,
              "producto_interno of perpendicular axes = 0");
    is_double(producto_interno(-1.5f, 2, 0.5f, 2, -1, 4), -3.0, 0,
              "producto_interno (-1.5,2,0.5).(2,-1,4) = -3");
    /* C.C = 0.25 + 0.5625 + 3.61 = 4.4225 */
    is_double(producto_interno(0.5f, 0.75f, 1.9f, 0.5f, 0.75f, 1.9f), 4.4225,
              1e-6, "producto_interno C.C = 4.4225");

    is_double(norma(3, 4, 0), 5.0, 0, "norma (3,4,0) = 5");
    is_double(norma(1, 2, 2), 3.0, 0, "norma (1,2,2) = 3");
    is_double(norma(0, 0, 0), 0.0, 0, "norma of the zero vector = 0");
    is_double(norma(-2, -3, -6), 7.0, 0, "norma (-2,-3,-6) = 7");
    is_double(norma(320, 240, 320), 512.2499389946279, 1e-4,
              "norma (320,240,320) = sqrt(262400)");

    /* Straight ahead: (C.d)^2 - C.C + R^2 = 3.61 - 4.4225 + 0.64 < 0. */
    is_int(intersecta_esfera(0, 0, 1), 0, "intersecta_esfera (0,0,1): miss");
    /* Towards the centre: delta = R^2 > 0. */
    is_int(hits_towards(0.5, 0.75, 1.9), 1, "towards the centre: hit");
    /* Away from the centre: delta = R^2 > 0 but both roots are behind. */
    is_int(hits_towards(-0.5, -0.75, -1.9), 0,
           "away from the centre: the sphere is behind, no hit");
    /* Up and right past the top-right: d = (1,1,1)/sqrt3: C.d = 3.15/sqrt3,
       (C.d)^2 = 3.3075; 3.3075 - 4.4225 + 0.64 = -0.475 < 0. */
    is_int(hits_towards(1, 1, 1), 0, "towards (1,1,1): miss");
    /* d = (0.3,0.5,1)/|.|: C.d = 2.425/1.1576, squared 4.3883; +0.64-4.4225
       = 0.606 > 0: hit. */
    is_int(hits_towards(0.3, 0.5, 1), 1, "towards (0.3,0.5,1): hit");
    /* Just inside and just outside the silhouette: a ray at angle a from
       the centre's direction C^ meets the sphere when sin a <= R/|C|.  Tilt
       C^ towards P^ = (C^ x y^)/|C^ x y^|, a unit vector perpendicular to it,
       by the tangent angle times (1 -+ 1e-3). */
    {
        double c = sqrt(4.4225), tangent = asin(0.8 / c);
        double cx = 0.5 / c, cy = 0.75 / c, cz = 1.9 / c;
        double p = sqrt(cx * cx + cz * cz), px = -cz / p, pz = cx / p;
        int k;
        for (k = -1; k <= 1; k += 2) {
            double a = tangent * (1.0 + k * 1e-3);
            is_int(hits_towards(cx * cos(a) + px * sin(a), cy * cos(a),
                                cz * cos(a) + pz * sin(a)),
                   k < 0, "%s the silhouette by 0.1%% of the tangent angle",
                   k < 0 ? "inside" : "outside");
        }
    }

    is_double(CX, RAYO_SEED_CENTER_X, 0, "CX = 0.5");
    is_double(CY, RAYO_SEED_CENTER_Y, 0, "CY = 0.75");
    is_double(CZ, RAYO_SEED_CENTER_Z, 0, "CZ = 1.9");
    is_double(R, RAYO_SEED_RADIUS, 0, "R = 0.8");
    is_int(ANCHO, RAYO_SEED_WIDTH, "ANCHO = 640");
    is_int(ALTO, RAYO_SEED_HEIGHT, "ALTO = 480");
    is_int(FOV, RAYO_SEED_FOV, "FOV = 90");
    return tap_done();
}
