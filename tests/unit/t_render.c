/*
 * t_render.c - rayo's hit-mode renders against an independent computation.
 *
 * The reference here shares no code with the library: it forms each
 * pixel's direction from the convention in the README (x = i - w/2,
 * y = j - h/2, d = (x, -y, w / (2 tan(fov/2))) normalised), solves the
 * quadratic of the assignment's note in double precision with its own
 * arithmetic, and counts a hit when a root t > 0 exists.  Every pixel of
 * every case must agree.
 */
#include <math.h>
#include <stdlib.h>

#include "rayo.h"
#include "tap.h"

typedef struct ball {
    double x, y, z, r;
} ball;

typedef struct view {
    unsigned width, height;
    double fov, ox, oy, oz;
} view;

static int reference_hit(const view *v, const ball *balls, size_t n,
                         unsigned i, unsigned j)
{
    const double pi = 3.14159265358979323846;
    double x = (double)i - (double)(v->width / 2);
    double y = (double)j - (double)(v->height / 2);
    double f = v->width / (2.0 * tan(v->fov * pi / 360.0));
    double len = sqrt(x * x + y * y + f * f);
    double dx = x / len, dy = -y / len, dz = f / len;
    size_t k;
    for (k = 0; k < n; k++) {
        double lx = balls[k].x - v->ox, ly = balls[k].y - v->oy,
               lz = balls[k].z - v->oz;
        double beta = lx * dx + ly * dy + lz * dz;
        double delta =
            beta * beta - (lx * lx + ly * ly + lz * lz) + balls[k].r * balls[k].r;
        if (delta >= 0 && (beta - sqrt(delta) > 0 || beta + sqrt(delta) > 0))
            return 1;
    }
    return 0;
}

/* Renders with rayo and returns the number of pixels that differ. */
static long differences(const view *v, const ball *balls, size_t n,
                        unsigned threads, long *black)
{
    rayo_camera camera;
    rayo_scene *scene;
    rayo_render_options options;
    rayo_image image;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    long wrong = 0;
    unsigned i, j;
    size_t k;
    if (rayo_camera_init(&camera, v->width, v->height, v->fov,
                         rayo_vec3_make(v->ox, v->oy, v->oz), &err) != RAYO_OK ||
        rayo_scene_create(&scene, &err) != RAYO_OK)
        return -1;
    for (k = 0; k < n; k++)
        if (rayo_scene_add_sphere(scene,
                                  rayo_vec3_make(balls[k].x, balls[k].y,
                                                 balls[k].z),
                                  balls[k].r, &err) != RAYO_OK)
            return -1;
    rayo_render_options_init(&options);
    options.threads = threads;
    if (rayo_render_image(&camera, scene, &options, &image, &err) != RAYO_OK) {
        rayo_scene_free(scene);
        return -1;
    }
    *black = 0;
    for (j = 0; j < v->height; j++)
        for (i = 0; i < v->width; i++) {
            int got = rayo_bit_get(rayo_image_row(&image, j), i);
            *black += got;
            wrong += got != reference_hit(v, balls, n, i, j);
        }
    rayo_image_free(&image);
    rayo_scene_free(scene);
    return wrong;
}

static void check(const char *name, view v, const ball *balls, size_t n,
                  long want_black_min, long want_black_max)
{
    long black = 0;
    long wrong = differences(&v, balls, n, 2, &black);
    is_int(wrong, 0, "%s: every pixel agrees with the independent computation",
           name);
    ok(black >= want_black_min && black <= want_black_max,
       "%s: %ld black pixels, expected %ld..%ld", name, black, want_black_min,
       want_black_max);
}

int main(void)
{
    const ball seed = {0.5, 0.75, 1.9, 0.8};
    const ball several[] = {{0.5, 0.75, 1.9, 0.8},
                            {-1.2, -0.5, 3, 0.5},
                            {2, -1, 5, 1.5},
                            {0, 0, 10, 0.1}};
    const ball behind[] = {{0, 0, -3, 1}};
    const ball around[] = {{0.1, -0.2, 0.3, 2}};
    const ball crossing[] = {{0, 0, 0.5, 1}};
    view v = {640, 480, 90, 0, 0, 0};

    /* The seed: 64503 black pixels, as the assignment's float functions
       give (checked when the test was written; see also student.t). */
    check("seed scene 640x480", v, &seed, 1, 64503, 64503);
    v.width = 641;
    v.height = 479;
    check("odd size 641x479", v, &seed, 1, 1, 641L * 479);
    v.width = 1;
    v.height = 1;
    check("1x1", v, &seed, 1, 0, 1);
    v.width = 7;
    v.height = 3;
    check("7x3", v, &seed, 1, 0, 21);
    v.width = 320;
    v.height = 240;
    v.fov = 30;
    check("fov 30", v, &seed, 1, 1, 320L * 240);
    v.fov = 150;
    check("fov 150", v, &seed, 1, 1, 320L * 240);
    v.fov = 90;
    check("several spheres", v, several, 4, 1, 320L * 240);
    check("a sphere behind the camera is not drawn", v, behind, 1, 0, 0);
    check("camera inside a sphere sees only sphere", v, around, 1,
          320L * 240, 320L * 240);
    check("a sphere crossing the camera plane", v, crossing, 1, 1,
          320L * 240);
    v.ox = 0.5;
    v.oy = 0.75;
    v.oz = -1;
    check("origin away from zero", v, &seed, 1, 1, 320L * 240);
    v.ox = 0;
    v.oy = 0;
    v.oz = 3;
    check("origin past the seed's sphere: it is behind", v, &seed, 1, 0, 0);

    /* The camera's rays by hand: pixel (0,0) of 640x480, fov 90 is the
       point (-320, -240), so d = (-320, 240, 320) / sqrt(262400). */
    {
        rayo_camera camera;
        rayo_ray ray;
        double n = sqrt(262400.0);
        rayo_camera_init(&camera, 640, 480, 90, rayo_vec3_make(0, 0, 0), NULL);
        is_double(camera.focal, 320.0, 1e-12, "fov 90: focal distance = w/2");
        ray = rayo_camera_ray(&camera, 0, 0);
        is_double(ray.direction.x, -320 / n, 1e-15, "pixel (0,0): dx");
        is_double(ray.direction.y, 240 / n, 1e-15, "pixel (0,0): dy (up)");
        is_double(ray.direction.z, 320 / n, 1e-15, "pixel (0,0): dz");
        ray = rayo_camera_ray(&camera, 320, 240);
        ok(ray.direction.x == 0 && ray.direction.y == 0 &&
               ray.direction.z == 1,
           "pixel (320,240) looks straight down +z");
    }
    return tap_done();
}
