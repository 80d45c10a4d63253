/*
 * scene.c - the scene's storage: adding objects, materials and lights
 * (each validated, with one-line messages), and reading them back.
 *
 * The queries the renderer asks are in query.c, the hierarchy's
 * construction in prepare.c.  Any add drops a built hierarchy, so a
 * stale tree is never consulted; the scene must not be modified while
 * other threads query it.
 */
#include "scene_impl.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/limits.h"

/*
 * Makes room for `wanted` elements in all in the array whose pointer is
 * at array_ptr (a T **, handled through memcpy so that no pointer is
 * accessed as another type): at least 8, and at least double the room it
 * had, so one more element at a time (GROW), or a batch of spheres at
 * a time (rayo_scene_add_spheres), costs amortised constant time an
 * element.
 */
static rayo_status reserve(void *array_ptr, size_t *capacity, size_t wanted,
                           size_t elem, rayo_error *err)
{
    size_t doubled = *capacity <= SIZE_MAX / 2 ? 2 * *capacity : SIZE_MAX;
    void *array, *grown;
    if (wanted <= *capacity)
        return RAYO_OK;
    if (doubled > wanted)
        wanted = doubled;
    if (wanted < 8)
        wanted = 8;
    if (wanted > SIZE_MAX / elem)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    memcpy(&array, array_ptr, sizeof array);
    grown = realloc(array, wanted * elem);
    if (grown == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    memcpy(array_ptr, &grown, sizeof grown);
    *capacity = wanted;
    return RAYO_OK;
}

/* Room for one more element of the scene's array of `name`s. */
#define GROW(scene, name, err)                                               \
    reserve(&(scene)->name##s, &(scene)->name##_capacity,                    \
            (scene)->name##_count + 1, sizeof *(scene)->name##s, (err))

static const rayo_material default_material = {{1.0, 1.0, 1.0},
                                               1.0, 1.0, 0.0, 0.0, 0.0};

rayo_status rayo_scene_create(rayo_scene **result, rayo_error *err)
{
    rayo_scene *scene = calloc(1, sizeof *scene);
    *result = NULL;
    if (scene == NULL)
        return rayo_error_set(err, RAYO_ERR_NOMEM, "out of memory");
    if (GROW(scene, material, err) != RAYO_OK) {
        free(scene);
        return RAYO_ERR_NOMEM;
    }
    scene->materials[0] = default_material;
    scene->material_count = 1;
    *result = scene;
    return RAYO_OK;
}

void rayo_scene_free(rayo_scene *scene)
{
    if (scene == NULL)
        return;
    rayo_bvh_free(scene->bvh);
    free(scene->objects);
    free(scene->spheres);
    free(scene->planes);
    free(scene->triangles);
    free(scene->materials);
    free(scene->lights);
    free(scene);
}

static int unit_range(double v)
{
    return v >= 0.0 && v <= 1.0;
}

static int non_negative(double v)
{
    return v >= 0.0 && isfinite(v);
}

static rayo_status check_material(const rayo_material *m, rayo_error *err)
{
    const char *bad = NULL;
    double value = 0.0;
    if (!unit_range(m->color.x) || !unit_range(m->color.y) ||
        !unit_range(m->color.z))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "material colour (%g, %g, %g) is not "
                              "accepted; expected each component in [0, 1]",
                              m->color.x, m->color.y, m->color.z);
    if (!non_negative(m->ka))
        bad = "ka", value = m->ka;
    else if (!non_negative(m->kd))
        bad = "kd", value = m->kd;
    else if (!non_negative(m->ks))
        bad = "ks", value = m->ks;
    else if (!non_negative(m->shininess))
        bad = "shininess", value = m->shininess;
    if (bad != NULL)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "material %s %g is not accepted; expected a "
                              "finite number >= 0",
                              bad, value);
    if (!unit_range(m->reflectivity))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "material reflectivity %g is not accepted; "
                              "expected a number in [0, 1]",
                              m->reflectivity);
    return RAYO_OK;
}

rayo_status rayo_scene_add_material(rayo_scene *scene,
                                    const rayo_material *material,
                                    unsigned *id, rayo_error *err)
{
    rayo_status status = check_material(material, err);
    if (status != RAYO_OK)
        return status;
    if (scene->material_count >= RAYO_MAX_MATERIALS)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "more than %lu materials in one scene",
                              RAYO_MAX_MATERIALS);
    status = GROW(scene, material, err);
    if (status != RAYO_OK)
        return status;
    scene->materials[scene->material_count] = *material;
    *id = (unsigned)scene->material_count++;
    return RAYO_OK;
}

/* The checks every object add shares, for the object that would come
 * `later` objects after the scene's last. */
static rayo_status check_object(const rayo_scene *scene, unsigned material,
                                size_t later, rayo_error *err)
{
    if (material >= scene->material_count)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "material %u does not exist; expected a "
                              "number below %lu",
                              material,
                              (unsigned long)scene->material_count);
    if (later >= RAYO_MAX_OBJECTS - scene->object_count)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "more than %lu objects in one scene",
                              RAYO_MAX_OBJECTS);
    return RAYO_OK;
}

/* Checks what every object add shares and makes room in `objects`. */
static rayo_status begin_object(rayo_scene *scene, unsigned material,
                                rayo_error *err)
{
    rayo_status status = check_object(scene, material, 0, err);
    if (status != RAYO_OK)
        return status;
    return GROW(scene, object, err);
}

/* Any add drops a built hierarchy. */
static void drop_hierarchy(rayo_scene *scene)
{
    rayo_bvh_free(scene->bvh);
    scene->bvh = NULL;
    scene->prepared = 0;
}

/* Records the object once its kind's array holds it; drops the tree. */
static void end_object(rayo_scene *scene, rayo_object_kind kind,
                       size_t index)
{
    scene->objects[scene->object_count].kind = (uint32_t)kind;
    scene->objects[scene->object_count].index = (uint32_t)index;
    scene->object_count++;
    drop_hierarchy(scene);
}

/* The checks of a sphere's shape, as rayo_scene_add_sphere_material
 * makes them first. */
static rayo_status check_sphere(rayo_vec3 center, double radius,
                                rayo_error *err)
{
    if (!rayo_vec3_is_finite(center))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "sphere centre is not finite");
    if (!(radius > 0.0) || !isfinite(radius))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "sphere radius %g is not accepted; expected a "
                              "finite number > 0",
                              radius);
    return RAYO_OK;
}

/* Writes a sphere known good into room already made. */
static void put_sphere(rayo_scene *scene, const rayo_sphere *shape,
                       unsigned material)
{
    scene_sphere *s = &scene->spheres[scene->sphere_count];
    scene_object *o = &scene->objects[scene->object_count];
    s->shape = *shape;
    s->object = (uint32_t)scene->object_count;
    s->material = material;
    o->kind = (uint32_t)RAYO_OBJECT_SPHERE;
    o->index = (uint32_t)scene->sphere_count;
    scene->sphere_count++;
    scene->object_count++;
}

rayo_status rayo_scene_add_sphere_material(rayo_scene *scene,
                                           rayo_vec3 center, double radius,
                                           unsigned material,
                                           rayo_error *err)
{
    rayo_sphere shape;
    rayo_status status = check_sphere(center, radius, err);
    if (status == RAYO_OK)
        status = begin_object(scene, material, err);
    if (status == RAYO_OK)
        status = GROW(scene, sphere, err);
    if (status != RAYO_OK)
        return status;
    shape.center = center;
    shape.radius = radius;
    put_sphere(scene, &shape, material);
    drop_hierarchy(scene);
    return RAYO_OK;
}

/*
 * Every sphere is checked before any is added (the first refused, as
 * one add at a time would refuse it: its shape, its material, then the
 * object limit), then room is made for all, then they are written.
 */
rayo_status rayo_scene_add_spheres(rayo_scene *scene,
                                   const rayo_sphere *spheres,
                                   const unsigned *materials, size_t count,
                                   rayo_error *err)
{
    size_t i;
    rayo_status status;
    for (i = 0; i < count; i++) {
        unsigned material = materials != NULL ? materials[i] : 0;
        status = check_sphere(spheres[i].center, spheres[i].radius, err);
        if (status == RAYO_OK)
            status = check_object(scene, material, i, err);
        if (status != RAYO_OK)
            return status;
    }
    status = reserve(&scene->objects, &scene->object_capacity,
                     scene->object_count + count, sizeof *scene->objects, err);
    if (status == RAYO_OK)
        status = reserve(&scene->spheres, &scene->sphere_capacity,
                         scene->sphere_count + count, sizeof *scene->spheres,
                         err);
    if (status != RAYO_OK)
        return status;
    for (i = 0; i < count; i++)
        put_sphere(scene, &spheres[i], materials != NULL ? materials[i] : 0);
    if (count > 0)
        drop_hierarchy(scene);
    return RAYO_OK;
}

rayo_status rayo_scene_add_sphere(rayo_scene *scene, rayo_vec3 center,
                                  double radius, rayo_error *err)
{
    return rayo_scene_add_sphere_material(scene, center, radius, 0, err);
}

rayo_status rayo_scene_add_plane(rayo_scene *scene, rayo_vec3 point,
                                 rayo_vec3 normal, unsigned material,
                                 rayo_error *err)
{
    rayo_status status;
    scene_plane *p;
    double length = rayo_vec3_length(normal);
    if (!rayo_vec3_is_finite(point))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "plane point is not finite");
    if (!rayo_vec3_is_finite(normal) || !(length > 0.0) || !isfinite(length))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "plane normal (%g, %g, %g) is not accepted; "
                              "expected a finite, non-zero vector",
                              normal.x, normal.y, normal.z);
    status = begin_object(scene, material, err);
    if (status == RAYO_OK)
        status = GROW(scene, plane, err);
    if (status != RAYO_OK)
        return status;
    p = &scene->planes[scene->plane_count];
    p->shape.point = point;
    p->shape.normal = rayo_vec3_scale(normal, 1.0 / length);
    p->object = (uint32_t)scene->object_count;
    p->material = material;
    end_object(scene, RAYO_OBJECT_PLANE, scene->plane_count++);
    return RAYO_OK;
}

rayo_status rayo_scene_add_triangle(rayo_scene *scene, rayo_vec3 a,
                                    rayo_vec3 b, rayo_vec3 c,
                                    unsigned material, rayo_error *err)
{
    rayo_vec3 none = {0.0, 0.0, 0.0};
    return rayo_scene_add_triangle_normal(scene, a, b, c, none, material,
                                          err);
}

rayo_status rayo_scene_add_triangle_normal(rayo_scene *scene, rayo_vec3 a,
                                           rayo_vec3 b, rayo_vec3 c,
                                           rayo_vec3 normal,
                                           unsigned material, rayo_error *err)
{
    rayo_status status;
    scene_triangle *t;
    rayo_triangle shape;
    shape.a = a;
    shape.b = b;
    shape.c = c;
    if (!rayo_vec3_is_finite(a) || !rayo_vec3_is_finite(b) ||
        !rayo_vec3_is_finite(c))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "triangle corner is not finite");
    if (!rayo_vec3_is_finite(normal))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "triangle normal is not finite");
    if (!rayo_triangle_is_valid(&shape))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "triangle (%g, %g, %g) (%g, %g, %g) "
                              "(%g, %g, %g) is degenerate; expected three "
                              "corners not on one line",
                              a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z);
    status = begin_object(scene, material, err);
    if (status == RAYO_OK)
        status = GROW(scene, triangle, err);
    if (status != RAYO_OK)
        return status;
    t = &scene->triangles[scene->triangle_count];
    scene_triangle_set(t, &shape, normal);
    t->object = (uint32_t)scene->object_count;
    t->material = material;
    end_object(scene, RAYO_OBJECT_TRIANGLE, scene->triangle_count++);
    return RAYO_OK;
}

void scene_triangle_set(scene_triangle *t, const rayo_triangle *shape,
                        rayo_vec3 normal)
{
    double length = rayo_vec3_length(normal);
    t->shape = *shape;
    t->normal = length > 0.0 ? rayo_vec3_scale(normal, 1.0 / length)
                             : rayo_triangle_normal(shape);
}

rayo_status scene_reserve_triangles(rayo_scene *scene, unsigned material,
                                    size_t more, rayo_error *err)
{
    rayo_status status;
    if (more == 0)
        return RAYO_OK;
    status = check_object(scene, material, more - 1, err);
    if (status == RAYO_OK)
        status = reserve(&scene->objects, &scene->object_capacity,
                         scene->object_count + more,
                         sizeof *scene->objects, err);
    if (status == RAYO_OK)
        status = reserve(&scene->triangles, &scene->triangle_capacity,
                         scene->triangle_count + more,
                         sizeof *scene->triangles, err);
    return status;
}

void scene_triangles_added(rayo_scene *scene, size_t added,
                           unsigned material)
{
    size_t i;
    if (added == 0)
        return;
    for (i = 0; i < added; i++) {
        scene_triangle *t = &scene->triangles[scene->triangle_count + i];
        scene_object *o = &scene->objects[scene->object_count + i];
        t->object = (uint32_t)(scene->object_count + i);
        t->material = material;
        o->kind = (uint32_t)RAYO_OBJECT_TRIANGLE;
        o->index = (uint32_t)(scene->triangle_count + i);
    }
    scene->triangle_count += added;
    scene->object_count += added;
    drop_hierarchy(scene);
}

static rayo_status check_light(const rayo_light *light, rayo_error *err)
{
    double length = rayo_vec3_length(light->vector);
    if (light->kind != RAYO_LIGHT_DIRECTIONAL &&
        light->kind != RAYO_LIGHT_POINT)
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "light kind %d is not accepted; expected "
                              "directional or point",
                              (int)light->kind);
    if (!rayo_vec3_is_finite(light->vector))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "light %s is not finite",
                              light->kind == RAYO_LIGHT_POINT ? "position"
                                                              : "direction");
    if (light->kind == RAYO_LIGHT_DIRECTIONAL &&
        (!(length > 0.0) || !isfinite(length)))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "light direction (%g, %g, %g) is not "
                              "accepted; expected a non-zero vector",
                              light->vector.x, light->vector.y,
                              light->vector.z);
    if (!non_negative(light->color.x) || !non_negative(light->color.y) ||
        !non_negative(light->color.z))
        return rayo_error_set(err, RAYO_ERR_INVALID,
                              "light colour (%g, %g, %g) is not accepted; "
                              "expected finite numbers >= 0",
                              light->color.x, light->color.y,
                              light->color.z);
    return RAYO_OK;
}

rayo_status rayo_scene_add_light(rayo_scene *scene, const rayo_light *light,
                                 rayo_error *err)
{
    rayo_status status = check_light(light, err);
    rayo_light *l;
    if (status != RAYO_OK)
        return status;
    if (scene->light_count >= RAYO_MAX_LIGHTS)
        return rayo_error_set(err, RAYO_ERR_LIMIT,
                              "more than %lu lights in one scene",
                              RAYO_MAX_LIGHTS);
    status = GROW(scene, light, err);
    if (status != RAYO_OK)
        return status;
    l = &scene->lights[scene->light_count++];
    *l = *light;
    if (l->kind == RAYO_LIGHT_DIRECTIONAL)
        l->vector = rayo_vec3_normalize(l->vector);
    return RAYO_OK;
}

void rayo_scene_set_ambient(rayo_scene *scene, rayo_vec3 ambient)
{
    scene->ambient = ambient;
}

rayo_vec3 rayo_scene_ambient(const rayo_scene *scene)
{
    return scene->ambient;
}

void rayo_scene_set_background(rayo_scene *scene, rayo_vec3 colour)
{
    scene->background = colour;
}

rayo_vec3 rayo_scene_background(const rayo_scene *scene)
{
    return scene->background;
}

size_t rayo_scene_object_count(const rayo_scene *scene)
{
    return scene->object_count;
}

rayo_object_kind rayo_scene_object_kind(const rayo_scene *scene, size_t i)
{
    return (rayo_object_kind)scene->objects[i].kind;
}

size_t rayo_scene_sphere_count(const rayo_scene *scene)
{
    return scene->sphere_count;
}

const rayo_sphere *rayo_scene_sphere(const rayo_scene *scene, size_t i)
{
    return &scene->spheres[i].shape;
}

size_t rayo_scene_light_count(const rayo_scene *scene)
{
    return scene->light_count;
}

const rayo_light *rayo_scene_light(const rayo_scene *scene, size_t i)
{
    return &scene->lights[i];
}

size_t rayo_scene_material_count(const rayo_scene *scene)
{
    return scene->material_count;
}

const rayo_material *rayo_scene_material(const rayo_scene *scene,
                                         unsigned id)
{
    if (id >= scene->material_count)
        return NULL;
    return &scene->materials[id];
}
