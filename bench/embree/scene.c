/*
 * scene.c - reads the subset of the scene format that bench/field_scene.py
 * and bench/scan/scan_mesh.c write (scene.h), for the Embree program; a
 * `mesh` line's STL is read by mesh.c.  Its own small reader, not rayo's:
 * the program must not link rayo's library, and its time to read the
 * file is Embree's side of the setup figure.  Keywords it does not
 * need (shade, background, ambient, material, samples, depth) are read
 * past; anything else is an error with its line number.
 */
#define _POSIX_C_SOURCE 200809L

#include "mesh.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct reader {
    const char *path;
    char *p; /* the current position in the line */
    unsigned line;
} reader;

static void die_input(const reader *r, const char *what)
{
    fprintf(stderr, "embree-rays: %s:%u: %s\n", r->path, r->line, what);
    exit(2);
}

/* The next word of the line (NUL-terminated in place), or NULL. */
static char *word(reader *r)
{
    char *start;
    while (*r->p == ' ' || *r->p == '\t' || *r->p == '\r')
        r->p++;
    if (*r->p == '\0' || *r->p == '#')
        return NULL;
    start = r->p;
    while (*r->p != '\0' && *r->p != ' ' && *r->p != '\t' && *r->p != '\r')
        r->p++;
    if (*r->p != '\0')
        *r->p++ = '\0';
    return start;
}

static double number(reader *r, const char *what)
{
    char *w = word(r), *end;
    double value;
    char message[128];
    if (w == NULL) {
        snprintf(message, sizeof message,
                 "expected %s, found the end of "
                 "the line",
                 what);
        die_input(r, message);
    }
    errno = 0;
    value = strtod(w, &end);
    if (*end != '\0' || errno != 0 || !isfinite(value)) {
        snprintf(message, sizeof message, "expected %s, found '%.40s'", what,
                 w);
        die_input(r, message);
    }
    return value;
}

static rayo_vec3 vector(reader *r, const char *what)
{
    rayo_vec3 v;
    v.x = number(r, what);
    v.y = number(r, what);
    v.z = number(r, what);
    return v;
}

/* Skips "material NAME" (or nothing); anything else is an error. */
static void trailing_material(reader *r)
{
    char *w = word(r);
    if (w == NULL)
        return;
    if (strcmp(w, "material") != 0 || word(r) == NULL || word(r) != NULL)
        die_input(r, "expected 'material NAME' or the end of the line");
}

static void camera_line(reader *r, scene *s)
{
    char *w;
    while ((w = word(r)) != NULL) {
        if (strcmp(w, "size") == 0) {
            double width = number(r, "a width"),
                   height = number(r, "a height");
            if (!(width >= 1 && width <= 65536 && height >= 1 &&
                  height <= 65536) ||
                width != floor(width) || height != floor(height))
                die_input(r, "expected a size of 1 to 65536 pixels each way");
            s->width = (unsigned)width;
            s->height = (unsigned)height;
        } else if (strcmp(w, "fov") == 0) {
            s->fov = number(r, "a field of view in degrees");
            if (!(s->fov > 0 && s->fov < 180))
                die_input(r, "expected a field of view between 0 and 180");
        } else if (strcmp(w, "origin") == 0) {
            s->origin = vector(r, "the origin's coordinates");
        } else if (strcmp(w, "look-at") == 0) {
            s->look_at = vector(r, "the look-at point's coordinates");
            s->aimed = 1;
        } else if (strcmp(w, "up") == 0) {
            s->up = vector(r, "the up vector's coordinates");
        } else {
            die_input(r, "unknown camera setting; expected size, fov, "
                         "origin, look-at or up");
        }
    }
}

static void sphere_line(reader *r, scene *s)
{
    rayo_vec3 c = vector(r, "the centre's coordinates");
    double radius = number(r, "a radius");
    float *slot;
    if (!(radius > 0))
        die_input(r, "expected a radius greater than 0");
    trailing_material(r);
    if (s->sphere_count == s->sphere_cap) {
        size_t cap = s->sphere_cap ? 2 * s->sphere_cap : 1024;
        float *grown = realloc(s->spheres, cap * 4 * sizeof *grown);
        if (grown == NULL) {
            fprintf(stderr, "embree-rays: out of memory\n");
            exit(1);
        }
        s->spheres = grown;
        s->sphere_cap = cap;
    }
    slot = s->spheres + 4 * s->sphere_count++;
    slot[0] = (float)c.x;
    slot[1] = (float)c.y;
    slot[2] = (float)c.z;
    slot[3] = (float)radius;
}

static void plane_line(reader *r, scene *s)
{
    rayo_vec3 p = vector(r, "the plane's point"), n = vector(r, "its normal");
    if (rayo_vec3_dot(n, n) == 0)
        die_input(r, "expected a non-zero normal");
    if (s->plane_count == MAX_PLANES)
        die_input(r, "too many planes for this program (64)");
    trailing_material(r);
    s->plane_point[s->plane_count] = p;
    s->plane_normal[s->plane_count++] = rayo_vec3_normalize(n);
}

/* `mesh FILE [material NAME]`: FILE relative to the scene's folder. */
static void mesh_line(reader *r, scene *s)
{
    char *file = word(r), path[4096];
    const char *slash = strrchr(r->path, '/');
    if (file == NULL)
        die_input(r, "expected a mesh file");
    trailing_material(r);
    if (file[0] == '/' || slash == NULL)
        snprintf(path, sizeof path, "%s", file);
    else
        snprintf(path, sizeof path, "%.*s/%s", (int)(slash - r->path),
                 r->path, file);
    read_mesh(path, s);
}

static void light_line(reader *r, scene *s)
{
    char *w = word(r);
    if (w == NULL || strcmp(w, "point") != 0)
        die_input(r, "expected 'light point X Y Z' (this program reads only "
                     "point lights)");
    if (!s->has_light) {
        s->light = vector(r, "the light's position");
        s->has_light = 1;
    }
}

static char *read_whole(const char *path, size_t *size)
{
    FILE *in = fopen(path, "rb");
    char *text = NULL;
    size_t cap = 0, n = 0;
    if (in == NULL) {
        fprintf(stderr, "embree-rays: %s: %s\n", path, strerror(errno));
        exit(1);
    }
    for (;;) {
        size_t got;
        if (cap - n < 65536) {
            char *grown = realloc(text, cap = 2 * cap + 65536 + 1);
            if (grown == NULL) {
                fprintf(stderr, "embree-rays: out of memory\n");
                exit(1);
            }
            text = grown;
        }
        got = fread(text + n, 1, cap - n - 1, in);
        n += got;
        if (got == 0)
            break;
    }
    if (ferror(in)) {
        fprintf(stderr, "embree-rays: %s: %s\n", path, strerror(errno));
        exit(1);
    }
    fclose(in);
    text[n] = '\0';
    *size = n;
    return text;
}

void read_scene(const char *path, scene *s)
{
    size_t size;
    char *text = read_whole(path, &size), *line = text;
    reader r;
    r.path = path;
    r.line = 0;
    memset(s, 0, sizeof *s);
    s->width = 640;
    s->height = 480;
    s->fov = 90;
    s->look_at = rayo_vec3_make(0, 0, 1);
    s->up = rayo_vec3_make(0, 1, 0);
    while (line < text + size) {
        char *end = memchr(line, '\n', (size_t)(text + size - line)), *w;
        if (end == NULL)
            end = text + size;
        *end = '\0';
        r.line++;
        r.p = line;
        line = end + 1;
        if ((w = word(&r)) == NULL)
            continue;
        if (strcmp(w, "sphere") == 0)
            sphere_line(&r, s);
        else if (strcmp(w, "camera") == 0)
            camera_line(&r, s);
        else if (strcmp(w, "plane") == 0)
            plane_line(&r, s);
        else if (strcmp(w, "light") == 0)
            light_line(&r, s);
        else if (strcmp(w, "mesh") == 0)
            mesh_line(&r, s);
        else if (strcmp(w, "shade") != 0 && strcmp(w, "background") != 0 &&
                 strcmp(w, "ambient") != 0 && strcmp(w, "material") != 0 &&
                 strcmp(w, "samples") != 0 && strcmp(w, "depth") != 0)
            die_input(&r, "unknown keyword; expected camera, light, sphere, "
                          "plane, mesh (or shade, background, ambient, "
                          "material, samples, depth, which are read past)");
    }
    free(text);
}
