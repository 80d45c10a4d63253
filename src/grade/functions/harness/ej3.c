/*
 * ej3.c - the harness of Ejercicio obligatorio 3's functions (colour,
 * structs, dynamic memory): the statement's types, here with the
 * student's layout once the grader's probes found it the statement's,
 * and its functions declared weak, each called on a record's numbers.
 * esfera_crear's and luz_crear's results are read member by member and
 * handed to their destructors; computar_intensidad gets arrays of
 * pointers to spheres and lights built here; arreglo_agregar runs with
 * malloc, calloc and realloc wrapped (the grader links with
 * -Wl,--wrap=...): after three additions allocation fails, and the
 * array must stay as it was.  The cases and their expected values are
 * the grader's table (../ej3.c); the channel and main rayo_harness.h's.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdbool.h>
#include <stddef.h>

#include "rayo_harness.h"

#define RAYO_SPHERES 64
#define RAYO_LIGHTS 16

typedef struct rayo_vector_t { float x, y, z; } vector_t;
typedef struct rayo_color_t { float r, g, b; } color_t;
typedef struct rayo_esfera_t { vector_t centro; float radio;
    color_t color; float ka, kd; } esfera_t;
typedef struct rayo_luz_t { vector_t posicion; color_t color;
    bool es_puntual; } luz_t;
typedef struct rayo_arreglo_t { void **v; size_t n; } arreglo_t;

float vector_producto_interno(vector_t a, vector_t b) __attribute__((weak));
float vector_norma(vector_t a) __attribute__((weak));
vector_t vector_resta(vector_t a, vector_t b) __attribute__((weak));
vector_t vector_interpolar_recta(vector_t o, vector_t d, float t)
    __attribute__((weak));
vector_t vector_normalizar(vector_t a) __attribute__((weak));
color_t color_sumar(color_t c, color_t m, float p) __attribute__((weak));
color_t color_absorber(color_t b, color_t c) __attribute__((weak));
void color_imprimir(color_t c) __attribute__((weak));
esfera_t *esfera_crear(vector_t centro, float radio, color_t color, float ka,
                       float kd) __attribute__((weak));
void esfera_destruir(esfera_t *esfera) __attribute__((weak));
luz_t *luz_crear(vector_t posicion, color_t color, bool es_puntual)
    __attribute__((weak));
void luz_destruir(luz_t *luz) __attribute__((weak));
float esfera_distancia(const esfera_t *esfera, vector_t o, vector_t d,
                       vector_t *punto, vector_t *normal)
    __attribute__((weak));
bool arreglo_agregar(arreglo_t *a, void *e) __attribute__((weak));
color_t computar_intensidad(const arreglo_t *esferas, const arreglo_t *luces,
                            color_t ambiente, vector_t o, vector_t d)
    __attribute__((weak));

/* The allocation functions as the student's objects see them: made to
   fail while rayo_fail_alloc is set; otherwise each block has 32 guard
   bytes past the size asked for, so that a write past its end is seen
   (the last block and its size are kept). */
#define RAYO_GUARD 32
static int rayo_fail_alloc;
static unsigned rayo_alloc_tries;
static unsigned char *rayo_last_block;
static size_t rayo_last_size;
void *__real_malloc(size_t);
void *__real_calloc(size_t, size_t);
void *__real_realloc(void *, size_t);
void *__wrap_malloc(size_t n);
void *__wrap_calloc(size_t n, size_t m);
void *__wrap_realloc(void *p, size_t n);

static void *rayo_guard(void *p, size_t n)
{
    if (p != NULL) {
        memset((unsigned char *)p + n, 0xa5, RAYO_GUARD);
        rayo_last_block = p;
        rayo_last_size = n;
    }
    return p;
}

static int rayo_guard_intact(void)
{
    size_t i;
    for (i = 0; i < RAYO_GUARD; i++)
        if (rayo_last_block[rayo_last_size + i] != 0xa5)
            return 0;
    return 1;
}

void *__wrap_malloc(size_t n)
{
    if (rayo_fail_alloc) {
        rayo_alloc_tries++;
        return NULL;
    }
    if (n > (size_t)-1 - RAYO_GUARD)
        return NULL;
    return rayo_guard(__real_malloc(n + RAYO_GUARD), n);
}

void *__wrap_calloc(size_t n, size_t m)
{
    if (rayo_fail_alloc) {
        rayo_alloc_tries++;
        return NULL;
    }
    if (m != 0 && n > ((size_t)-1 - RAYO_GUARD) / m)
        return NULL;
    return rayo_guard(__real_calloc(n * m + RAYO_GUARD, 1), n * m);
}

void *__wrap_realloc(void *p, size_t n)
{
    if (rayo_fail_alloc) {
        rayo_alloc_tries++;
        return NULL;
    }
    if (n > (size_t)-1 - RAYO_GUARD)
        return NULL;
    return rayo_guard(__real_realloc(p, n + RAYO_GUARD), n);
}

static int rayo_present(const char *name)
{
    if (strcmp(name, "vector_producto_interno") == 0)
        return vector_producto_interno != 0;
    if (strcmp(name, "vector_norma") == 0)
        return vector_norma != 0;
    if (strcmp(name, "vector_resta") == 0)
        return vector_resta != 0;
    if (strcmp(name, "vector_interpolar_recta") == 0)
        return vector_interpolar_recta != 0;
    if (strcmp(name, "vector_normalizar") == 0)
        return vector_normalizar != 0;
    if (strcmp(name, "color_sumar") == 0)
        return color_sumar != 0;
    if (strcmp(name, "color_absorber") == 0)
        return color_absorber != 0;
    if (strcmp(name, "color_imprimir") == 0)
        return color_imprimir != 0;
    if (strcmp(name, "esfera_crear") == 0)
        return esfera_crear != 0;
    if (strcmp(name, "esfera_destruir") == 0)
        return esfera_destruir != 0;
    if (strcmp(name, "luz_crear") == 0)
        return luz_crear != 0;
    if (strcmp(name, "luz_destruir") == 0)
        return luz_destruir != 0;
    if (strcmp(name, "esfera_distancia") == 0)
        return esfera_distancia != 0;
    if (strcmp(name, "arreglo_agregar") == 0)
        return arreglo_agregar != 0;
    if (strcmp(name, "computar_intensidad") == 0)
        return computar_intensidad != 0;
    return 0;
}

static vector_t rayo_vector(void)
{
    vector_t v;
    v.x = rayo_float();
    v.y = rayo_float();
    v.z = rayo_float();
    return v;
}

static color_t rayo_color(void)
{
    color_t c;
    c.r = rayo_float();
    c.g = rayo_float();
    c.b = rayo_float();
    return c;
}

static void rayo_result3(const char *name, unsigned k, double first,
                         float x, float y, float z)
{
    rayo_say("result %s %u %.9g %.9g %.9g %.9g", name, k, first, x, y, z);
}

static void rayo_crear(unsigned k, vector_t a, color_t b, float s, float ka,
                       float kd)
{
    esfera_t *e = esfera_crear(a, s, b, ka, kd);
    if (e == NULL) {
        rayo_say("result esfera_crear %u null", k);
        return;
    }
    rayo_say("result esfera_crear %u %.9g %.9g %.9g %.9g %.9g %.9g %.9g "
             "%.9g %.9g", k, e->centro.x, e->centro.y, e->centro.z,
             e->radio, e->color.r, e->color.g, e->color.b, e->ka, e->kd);
    if (rayo_usable("esfera_destruir") && esfera_destruir != 0) {
        rayo_say("call esfera_destruir %u", k);
        esfera_destruir(e);
        rayo_say("result esfera_destruir %u 0", k);
    }
}

static void rayo_luz(unsigned k, vector_t a, color_t b, bool point)
{
    luz_t *l = luz_crear(a, b, point);
    if (l == NULL) {
        rayo_say("result luz_crear %u null", k);
        return;
    }
    rayo_say("result luz_crear %u %.9g %.9g %.9g %.9g %.9g %.9g %d", k,
             l->posicion.x, l->posicion.y, l->posicion.z, l->color.r,
             l->color.g, l->color.b, (int)l->es_puntual);
    if (rayo_usable("luz_destruir") && luz_destruir != 0) {
        rayo_say("call luz_destruir %u", k);
        luz_destruir(l);
        rayo_say("result luz_destruir %u 0", k);
    }
}

/* A value case's record: a, b, c (vectors or colours) and s. */
static void rayo_value(const char *name, unsigned k)
{
    vector_t a = rayo_vector(), b = rayo_vector(), c = rayo_vector(), r;
    color_t ca, cb, cc;
    float s = rayo_float();
    ca.r = a.x, ca.g = a.y, ca.b = a.z;
    cb.r = b.x, cb.g = b.y, cb.b = b.z;
    if (strcmp(name, "vector_producto_interno") == 0) {
        rayo_result3(name, k, vector_producto_interno(a, b), 0, 0, 0);
    } else if (strcmp(name, "vector_norma") == 0) {
        rayo_result3(name, k, vector_norma(a), 0, 0, 0);
    } else if (strcmp(name, "vector_resta") == 0) {
        r = vector_resta(a, b);
        rayo_result3(name, k, 0, r.x, r.y, r.z);
    } else if (strcmp(name, "vector_interpolar_recta") == 0) {
        r = vector_interpolar_recta(a, b, s);
        rayo_result3(name, k, 0, r.x, r.y, r.z);
    } else if (strcmp(name, "vector_normalizar") == 0) {
        r = vector_normalizar(a);
        rayo_result3(name, k, 0, r.x, r.y, r.z);
    } else if (strcmp(name, "color_sumar") == 0) {
        cc = color_sumar(ca, cb, s);
        rayo_result3(name, k, 0, cc.r, cc.g, cc.b);
    } else if (strcmp(name, "color_absorber") == 0) {
        cc = color_absorber(ca, cb);
        rayo_result3(name, k, 0, cc.r, cc.g, cc.b);
    } else if (strcmp(name, "color_imprimir") == 0) {
        rayo_say("out color_imprimir %u", k);
        color_imprimir(ca);
        fflush(stdout);
        rayo_say("end color_imprimir %u", k);
        rayo_say("result color_imprimir %u 0", k);
    } else if (strcmp(name, "esfera_crear") == 0) {
        rayo_crear(k, a, cb, s, c.x, c.y);
    } else if (strcmp(name, "luz_crear") == 0) {
        rayo_luz(k, a, cb, s != 0);
    } else {
        esfera_t e;
        vector_t p = {12345, 12345, 12345}, n = {12345, 12345, 12345};
        double v;
        e.centro = a;
        e.radio = s;
        e.color.r = e.color.g = e.color.b = 1;
        e.ka = e.kd = 1;
        v = esfera_distancia(&e, b, c, &p, &n);
        rayo_say("result esfera_distancia %u %.9g %.9g %.9g %.9g %.9g %.9g "
                 "%.9g", k, v, p.x, p.y, p.z, n.x, n.y, n.z);
    }
}

/* computar_intensidad's record: the counts of spheres and lights, each
   sphere (centre, radius, colour, ka, kd), each light (position or
   direction, colour, 1 when a point), the ambient colour, o and d. */
static void rayo_scene(unsigned k)
{
    static esfera_t es[RAYO_SPHERES];
    static luz_t ls[RAYO_LIGHTS];
    void *ev[RAYO_SPHERES], *lv[RAYO_LIGHTS];
    size_t ns = (size_t)rayo_number(), nl = (size_t)rayo_number(), i;
    arreglo_t esferas, luces;
    color_t ambiente, c;
    vector_t o, d;
    if (ns > RAYO_SPHERES)
        ns = RAYO_SPHERES;
    if (nl > RAYO_LIGHTS)
        nl = RAYO_LIGHTS;
    for (i = 0; i < ns; i++) {
        es[i].centro = rayo_vector();
        es[i].radio = rayo_float();
        es[i].color = rayo_color();
        es[i].ka = rayo_float();
        es[i].kd = rayo_float();
        ev[i] = &es[i];
    }
    for (i = 0; i < nl; i++) {
        ls[i].posicion = rayo_vector();
        ls[i].color = rayo_color();
        ls[i].es_puntual = rayo_number() != 0;
        lv[i] = &ls[i];
    }
    ambiente = rayo_color();
    o = rayo_vector();
    d = rayo_vector();
    esferas.v = ev;
    esferas.n = ns;
    luces.v = lv;
    luces.n = nl;
    c = computar_intensidad(&esferas, &luces, ambiente, o, d);
    rayo_result3("computar_intensidad", k, 0, c.r, c.g, c.b);
}

/* arreglo_agregar: three additions, then one with allocation failing
   (after as many more as it makes without asking for memory). */
static void rayo_agregar(void)
{
    static int x[70];
    arreglo_t a = {NULL, 0};
    void *saved[70];
    void **before = NULL;
    size_t n = 0, i;
    int r0, r1, r2, r = 0, same = 1, guard;
    r0 = arreglo_agregar(&a, &x[0]);
    r1 = arreglo_agregar(&a, &x[1]);
    r2 = arreglo_agregar(&a, &x[2]);
    guard = (void *)a.v != (void *)rayo_last_block || rayo_guard_intact();
    for (i = 0; i < 3 && a.v != NULL && a.n == 3; i++)
        same &= a.v[i] == (void *)&x[i];
    rayo_say("result arreglo_agregar 0 %d %d %d %lu %d %d %d %lu", r0, r1,
             r2, (unsigned long)a.n, a.v != NULL, same, guard,
             (unsigned long)rayo_last_size);
    if (a.v == NULL || a.n != 3 || !same)
        return;
    rayo_say("call arreglo_agregar 1");
    for (i = 3; i < 67; i++) {
        before = a.v;
        n = a.n;
        memcpy(saved, a.v, n * sizeof *saved);
        rayo_alloc_tries = 0;
        rayo_fail_alloc = 1;
        r = arreglo_agregar(&a, &x[i]);
        rayo_fail_alloc = 0;
        if (rayo_alloc_tries > 0 || !r || a.n != n + 1)
            break;
    }
    same = a.v == before && a.v != NULL &&
           memcmp(saved, a.v, n * sizeof *saved) == 0;
    rayo_say("result arreglo_agregar 1 %u %d %lu %lu %d %d %d",
             rayo_alloc_tries, r, (unsigned long)n, (unsigned long)a.n,
             a.v == NULL, a.v == before, same);
}

static void rayo_call(const char *name, unsigned k)
{
    if (strcmp(name, "computar_intensidad") == 0)
        rayo_scene(k);
    else if (strcmp(name, "arreglo_agregar") == 0)
        rayo_agregar();
    else
        rayo_value(name, k);
}
