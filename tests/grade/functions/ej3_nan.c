/*
 * ej3_nan.c - exercise 3's types and functions: the ones that compute a
 * number return (or fill in) NaN, as 0/0 gives it, and color_imprimir
 * prints (int) of 255 NaN; the ones that keep or allocate are right.
 * Every comparison of the functions criterion must say "nan (not a
 * number)" with a likely cause, computar_intensidad's colour included.
 * With BAD_VALUE defined first (ej3_inf.c) they return that instead.
 */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

static volatile float zero;

#ifndef BAD_VALUE
#define BAD_VALUE (zero / zero)
#endif

typedef struct {
    float x, y, z;
} vector_t;

typedef struct {
    float r, g, b;
} color_t;

typedef struct {
    vector_t centro;
    float radio;
    color_t color;
    float ka, kd;
} esfera_t;

typedef struct {
    vector_t posicion;
    color_t color;
    bool es_puntual;
} luz_t;

typedef struct {
    void **v;
    size_t n;
} arreglo_t;

static vector_t bad_vector(void)
{
    vector_t v;
    v.x = v.y = v.z = BAD_VALUE;
    return v;
}

static color_t bad_color(void)
{
    color_t c;
    c.r = c.g = c.b = BAD_VALUE;
    return c;
}

float vector_producto_interno(vector_t a, vector_t b)
{
    (void)a;
    (void)b;
    return BAD_VALUE;
}

float vector_norma(vector_t a)
{
    (void)a;
    return BAD_VALUE;
}

vector_t vector_resta(vector_t a, vector_t b)
{
    (void)a;
    (void)b;
    return bad_vector();
}

vector_t vector_interpolar_recta(vector_t o, vector_t d, float t)
{
    (void)o;
    (void)d;
    (void)t;
    return bad_vector();
}

vector_t vector_normalizar(vector_t a)
{
    (void)a;
    return bad_vector();
}

color_t color_sumar(color_t c, color_t m, float p)
{
    (void)c;
    (void)m;
    (void)p;
    return bad_color();
}

color_t color_absorber(color_t b, color_t c)
{
    (void)b;
    (void)c;
    return bad_color();
}

void color_imprimir(color_t c)
{
    float bad = BAD_VALUE;
    (void)c;
    printf("%d %d %d", (int)(255 * bad), (int)(255 * bad),
           (int)(255 * bad));
}

esfera_t *esfera_crear(vector_t centro, float radio, color_t color,
                       float ka, float kd)
{
    esfera_t *e = malloc(sizeof *e);
    if (e == NULL)
        return NULL;
    e->centro = centro;
    e->radio = radio;
    e->color = color;
    e->ka = ka;
    e->kd = kd;
    return e;
}

void esfera_destruir(esfera_t *esfera)
{
    free(esfera);
}

luz_t *luz_crear(vector_t posicion, color_t color, bool es_puntual)
{
    luz_t *l = malloc(sizeof *l);
    if (l == NULL)
        return NULL;
    l->posicion = posicion;
    l->color = color;
    l->es_puntual = es_puntual;
    return l;
}

void luz_destruir(luz_t *luz)
{
    free(luz);
}

float esfera_distancia(const esfera_t *esfera, vector_t o, vector_t d,
                       vector_t *punto, vector_t *normal)
{
    (void)esfera;
    (void)o;
    (void)d;
    *punto = bad_vector();
    *normal = bad_vector();
    return BAD_VALUE;
}

bool arreglo_agregar(arreglo_t *a, void *e)
{
    void **v = realloc(a->v, (a->n + 1) * sizeof *v);
    if (v == NULL)
        return false;
    a->v = v;
    a->v[a->n++] = e;
    return true;
}

color_t computar_intensidad(const arreglo_t *esferas,
                            const arreglo_t *luces, color_t ambiente,
                            vector_t o, vector_t d)
{
    (void)esferas;
    (void)luces;
    (void)ambiente;
    (void)o;
    (void)d;
    return bad_color();
}

int main(void)
{
    return 0;
}
