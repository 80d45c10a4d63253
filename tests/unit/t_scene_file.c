/*
 * t_scene_file.c - what a scene file turns into: every statement's
 * values as the scene, the camera description and the settings hold
 * them, the defaults of an empty file, line endings and comments, and
 * the position an error names when parsing from memory.  The command's
 * messages for each error class are tests/cli/scene_errors.t.
 */
#include <math.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

static const char full[] =
    "# every statement once\r\n"
    "shade course-color\r\n"
    "samples 2   # trailing comment\r\n"
    "depth 3\n"
    "camera size 320 200 fov 60 origin 1 2 3 look-at 1 2 10 up 0 1 0\n"
    "background 0.1 0.2 0.3\n"
    "ambient 0.5\n"
    "\tlight directional 0 2 0 color 0.2 0.3 0.4\n"
    "light point 1 2 3\n"
    "material red color 1 0 0 ka 0.1 kd 0.7 ks 0.5 shininess 20 "
    "reflect 0.25\n"
    "sphere 0 0 5 1 material red\n"
    "plane 0 -1 0 0 1 0\n"
    "triangle -1 -1 3.5 1 -1 3.5 0 1 3.5 material red"; /* no final newline */

static void check_full(void)
{
    rayo_scene_file f;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    const rayo_light *l;
    const rayo_material *m;
    rayo_ray ray;
    rayo_hit hit;
    rayo_vec3 v;
    if (rayo_scene_file_parse(&f, "full.scene", full, strlen(full), &err) !=
        RAYO_OK) {
        printf("# %s\n", err.message);
        ok(0, "full scene parses");
        return;
    }
    ok(1, "full scene parses (CRLF, tabs, comments, no final newline)");
    is_int(f.shade, RAYO_SHADE_COURSE_COLOR, "shade course-color");
    is_int(f.shade_given, 1, "shade given");
    is_int(f.samples, 2, "samples 2");
    is_int(f.depth, 3, "depth 3");
    is_int(f.camera_given, 1, "camera given");
    is_int(f.camera.width, 320, "camera width");
    is_int(f.camera.height, 200, "camera height");
    is_double(f.camera.fov_degrees, 60, 0, "camera fov");
    is_double(f.camera.origin.z, 3, 0, "camera origin z");
    is_int(f.camera.aimed, 1, "look-at aims the camera");
    is_double(f.camera.look_at.z, 10, 0, "look-at z");
    v = rayo_scene_background(f.scene);
    is_double(v.y, 0.2, 0, "background green");
    v = rayo_scene_ambient(f.scene);
    ok(v.x == 0.5 && v.y == 0.5 && v.z == 0.5, "one number is a gray");
    is_int(rayo_scene_light_count(f.scene), 2, "two lights");
    l = rayo_scene_light(f.scene, 0);
    is_int(l->kind, RAYO_LIGHT_DIRECTIONAL, "first light directional");
    is_double(l->vector.y, 1, 0, "its direction is normalised");
    is_double(l->color.z, 0.4, 0, "its colour");
    l = rayo_scene_light(f.scene, 1);
    is_int(l->kind, RAYO_LIGHT_POINT, "second light a point");
    is_double(l->vector.x, 1, 0, "its position");
    ok(l->color.x == 1 && l->color.y == 1 && l->color.z == 1,
       "a light's colour defaults to white");
    is_int(rayo_scene_material_count(f.scene), 2, "material 0 and red");
    m = rayo_scene_material(f.scene, 1);
    ok(m != NULL && m->color.x == 1 && m->color.y == 0 && m->ka == 0.1 &&
           m->kd == 0.7 && m->ks == 0.5 && m->shininess == 20 &&
           m->reflectivity == 0.25,
       "red has every value given");
    is_int(rayo_scene_object_count(f.scene), 3, "three objects");
    is_int(rayo_scene_object_kind(f.scene, 1), RAYO_OBJECT_PLANE,
           "object 1 is the plane");
    ray.origin = rayo_vec3_make(0, 0, 0);
    ray.direction = rayo_vec3_make(0, 0, 1);
    ok(rayo_scene_intersect(f.scene, &ray, 0, INFINITY, &hit) &&
           hit.object == 2 && hit.material == 1 && hit.t == 3.5,
       "the triangle at z = 3.5 comes first along +z, in red");
    ray.direction = rayo_vec3_make(0, -1, 0);
    ok(rayo_scene_intersect(f.scene, &ray, 0, INFINITY, &hit) &&
           hit.object == 1 && hit.material == 0 && hit.t == 1,
       "the plane y = -1 is below, in material 0");
    rayo_scene_file_free(&f);
}

static void check_defaults(void)
{
    rayo_scene_file f;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    if (rayo_scene_file_parse(&f, "empty.scene", "", 0, &err) != RAYO_OK) {
        printf("# %s\n", err.message);
        ok(0, "empty scene parses");
        return;
    }
    is_int(f.shade, RAYO_SHADE_PHONG, "no shade line: phong");
    is_int(f.shade_given, 0, "shade not given");
    is_int(f.samples, 1, "samples default 1");
    is_int(f.depth, 5, "depth default 5");
    ok(f.camera.width == 640 && f.camera.height == 480 &&
           f.camera.fov_degrees == 90 && !f.camera.aimed,
       "the assignment's camera by default");
    is_int(rayo_scene_object_count(f.scene), 0, "no objects");
    rayo_scene_file_free(&f);
    ok(f.scene == NULL, "a freed scene file holds no scene");
    rayo_scene_file_free(&f);
    ok(f.scene == NULL, "and freeing it again changes nothing");
}

static void check_error(const char *text, rayo_status want_status,
                        const char *want_prefix)
{
    rayo_scene_file f;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_status status =
        rayo_scene_file_parse(&f, "mem.scene", text, strlen(text), &err);
    is_int(status, want_status, "status for %s", want_prefix);
    printf("# %s\n", err.message);
    ok(strncmp(err.message, want_prefix, strlen(want_prefix)) == 0,
       "message starts '%s'", want_prefix);
    ok(f.scene == NULL, "nothing to free after a failure");
    is_int(rayo_scene_file_parse(&f, "mem.scene", text, strlen(text), NULL),
           want_status, "a NULL error slot is allowed");
}

int main(void)
{
    check_full();
    check_defaults();
    check_error("sphere 0 0 1 1\n\n   bogus", RAYO_ERR_FORMAT,
                "mem.scene:3:4: unknown keyword 'bogus'");
    check_error("sphere 0 0 1 -2", RAYO_ERR_INVALID,
                "mem.scene:1:14: radius -2");
    check_error("camera width 70000", RAYO_ERR_LIMIT,
                "mem.scene:1:14: the image width 70000 is out of range");
    check_error("material a kd 0\nsphere 0 0 1 1 material b\n",
                RAYO_ERR_INVALID, "mem.scene:2:25: unknown material 'b'");
    return tap_done();
}
