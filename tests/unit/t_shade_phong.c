/*
 * t_shade_phong.c - the phong model on scenes small enough to work out by
 * hand, and where it parts from the course's models.
 *
 * Every scene is a 33 x 33 image whose centre pixel (16, 16) looks
 * straight down +z from the origin, so its hit point and normal are known
 * exactly and the expected colour is a line of arithmetic written in the
 * test: diffuse, specular, a point light blocked only between the point
 * and the light (the course's models too; a directional light is
 * blocked along the whole half-line),
 * mirror reflections to a depth limit, the background, and triangles.
 */
#include <math.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

#define SIZE 33
#define MID 16

typedef struct rgb {
    int r, g, b;
} rgb;

/* Renders text as a scene (33x33 camera) and returns pixel (i, j). */
static rgb pixel(const char *text, rayo_shade_mode mode, unsigned depth,
                 unsigned i, unsigned j)
{
    rgb out = {-1, -1, -1};
    rayo_scene_file file;
    rayo_camera camera;
    rayo_render_options options;
    rayo_image image;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    const unsigned char *p;
    if (rayo_scene_file_parse(&file, "test.scene", text, strlen(text),
                              &err) != RAYO_OK) {
        printf("# %s\n", err.message);
        return out;
    }
    file.camera.width = file.camera.height = SIZE;
    rayo_render_options_init(&options);
    options.shade = mode;
    options.depth = depth;
    options.threads = 1;
    if (rayo_camera_spec_build(&file.camera, &camera, &err) == RAYO_OK &&
        rayo_render_image(&camera, file.scene, &options, &image, &err) ==
            RAYO_OK) {
        p = rayo_image_row(&image, j) + 3 * (size_t)i;
        out.r = p[0], out.g = p[1], out.b = p[2];
        rayo_image_free(&image);
    } else {
        printf("# %s\n", err.message);
    }
    rayo_scene_file_free(&file);
    return out;
}

#define is_rgb(got, R, G, B, ...)                                            \
    do {                                                                     \
        rgb g_ = (got);                                                      \
        char n_[200];                                                        \
        snprintf(n_, sizeof n_, __VA_ARGS__);                                \
        if (!tap_ok(g_.r == (R) && g_.g == (G) && g_.b == (B), n_))          \
            printf("#   got %d %d %d, expected %d %d %d\n", g_.r, g_.g,     \
                   g_.b, (R), (G), (B));                                     \
    } while (0)

static void diffuse_and_specular(void)
{
    /* P = (0,0,2), N = (0,0,-1), L = (0,0,-1): L.N = 1. */
    const char *matte = "light directional 0 0 -1\n"
                        "material m color 1 0.5 0.25 ka 0 kd 1\n"
                        "sphere 0 0 3 1 material m\n";
    /* R = 2(L.N)N - L = (0,0,-1) = V: specular ks * 1^n = 0.5 white. */
    const char *shiny = "light directional 0 0 -1\n"
                        "material m color 1 0.5 0.25 ka 0 kd 1 ks 0.5 "
                        "shininess 10\n"
                        "sphere 0 0 3 1 material m\n";
    /* Half the light: kd 0.5; ambient 0.2 with ka 0.5 adds 0.1 M. */
    const char *mixed = "ambient 0.2\nlight directional 0 0 -1 color 0.5\n"
                        "material m color 1 0.5 0.25 ka 0.5 kd 1\n"
                        "sphere 0 0 3 1 material m\n";
    /* 255 * 0.5 = 127.5 and 255 * 0.25 = 63.75 round to 128 and 64. */
    is_rgb(pixel(matte, RAYO_SHADE_PHONG, 5, MID, MID), 255, 128, 64,
           "phong diffuse: M (L.N) rounded to the nearest level");
    /* 0.5 + 0.5 = 1, 0.25 + 0.5 = 0.75 -> 191.25 -> 191. */
    is_rgb(pixel(shiny, RAYO_SHADE_PHONG, 5, MID, MID), 255, 255, 191,
           "phong specular: ks (R.V)^n added in white, clamped to 1");
    /* (0.1 + 0.5) M = 0.6, 0.3, 0.15 -> 153, 76.5 -> 77, 38.25 -> 38. */
    is_rgb(pixel(mixed, RAYO_SHADE_PHONG, 5, MID, MID), 153, 77, 38,
           "phong ambient ka Ia M plus diffuse kd Ii M (L.N)");
    /* The course's model truncates: 127.5 -> 127, 63.75 -> 63. */
    is_rgb(pixel(matte, RAYO_SHADE_COURSE_COLOR, 5, MID, MID), 255, 127, 63,
           "course-color on the same scene: the integer part of 255 c");
}

static void shadows(void)
{
    /* P = (0,0,2); the light at (0,2,0) is 2 sqrt 2 away along (0,1,-1)/
     * sqrt 2, L.N = 1/sqrt 2.  A ball at (0,1,1) lies between; one at
     * (0,3,-1) lies beyond the light on the same line. */
    const char *between = "light point 0 2 0\n"
                          "material m ka 0 kd 1\n"
                          "sphere 0 0 3 1 material m\n"
                          "sphere 0 1 1 0.2 material m\n";
    const char *beyond = "light point 0 2 0\n"
                         "material m ka 0 kd 1\n"
                         "sphere 0 0 3 1 material m\n"
                         "sphere 0 3 -1 0.2 material m\n";
    int lit = (int)floor(255.0 / sqrt(2.0) + 0.5);
    is_rgb(pixel(between, RAYO_SHADE_PHONG, 5, MID, MID), 0, 0, 0,
           "phong: a ball between the point and the light casts a shadow");
    is_rgb(pixel(beyond, RAYO_SHADE_PHONG, 5, MID, MID), lit, lit, lit,
           "phong: a ball beyond the light does not (%d = 255/sqrt 2)", lit);
    is_rgb(pixel(beyond, RAYO_SHADE_COURSE_COLOR, 5, MID, MID), 180, 180,
           180, "course-color: nor in the course's model (the integer part "
                "of 255/sqrt 2)");
    is_rgb(pixel(between, RAYO_SHADE_COURSE_COLOR, 5, MID, MID), 0, 0, 0,
           "course-color: a ball between the point and the light does");
}

static void reflections(void)
{
    /* The centre ray meets the mirror z = 5 at (0,0,5) and comes back
     * along -z to the red ball behind the camera, lit by ambient only. */
    const char *mirror = "ambient 1\nbackground 0 0 1\n"
                         "material glass color 1 1 1 ka 0 kd 0 reflect 1\n"
                         "material red color 1 0 0 ka 1 kd 0\n"
                         "plane 0 0 5 0 0 -1 material glass\n"
                         "sphere 0 0 -5 1 material red\n";
    /* Pixel (0, 0): a ray up and left whose reflection misses the ball
     * and brings back the background. */
    is_rgb(pixel(mirror, RAYO_SHADE_PHONG, 1, MID, MID), 255, 0, 0,
           "a mirror shows the ball behind the camera (depth 1)");
    is_rgb(pixel(mirror, RAYO_SHADE_PHONG, 0, MID, MID), 0, 0, 0,
           "depth 0: the reflection is not followed");
    is_rgb(pixel(mirror, RAYO_SHADE_PHONG, 1, 0, 0), 0, 0, 255,
           "a reflection that meets nothing brings back the background");
}

static void triangles(void)
{
    const char *tri = "ambient 1\nbackground 0.2\n"
                      "material green color 0 1 0 ka 1 kd 0\n"
                      "triangle -1 -1 3  1 -1 3  0 1 3 material green\n";
    /* 255 * 0.2 = 51 exactly. */
    is_rgb(pixel(tri, RAYO_SHADE_PHONG, 5, MID, MID), 0, 255, 0,
           "a triangle covers the centre");
    is_rgb(pixel(tri, RAYO_SHADE_PHONG, 5, 0, 0), 51, 51, 51,
           "the corner pixel misses it: background");
}

int main(void)
{
    diffuse_and_specular();
    shadows();
    reflections();
    triangles();
    return tap_done();
}
