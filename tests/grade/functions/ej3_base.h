/*
 * ej3_base.h - exercise 3's types and fifteen functions, right, for the
 * fixtures of tests/cli/grade_functions.t and
 * tests/unit/t_grade_functions.c: each fixture defines one MISTAKE_* and
 * includes this file, so that it has exactly one mistake.  main does
 * nothing: only the functions criterion is under test.
 */
#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

#define INFINITO FLT_MAX

#ifdef MISTAKE_NO_TYPEDEF
/* The struct without its typedef: the name below is struct vector_t
   (the macro stands for it in this file only; it is undefined at the
   end, as if every use had been written struct vector_t). */
struct vector_t {
    float x, y, z;
};
#define vector_t struct vector_t
#elif defined(MISTAKE_DOUBLE_VECTOR)
typedef struct {
    double x, y, z;
} vector_t;
#else
typedef struct {
    float x, y, z;
} vector_t;
#endif

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

float vector_producto_interno(vector_t a, vector_t b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

float vector_norma(vector_t a)
{
    return sqrt(vector_producto_interno(a, a));
}

vector_t vector_resta(vector_t a, vector_t b)
{
    return (vector_t){a.x - b.x, a.y - b.y, a.z - b.z};
}

vector_t vector_interpolar_recta(vector_t o, vector_t d, float t)
{
    return (vector_t){o.x + t * d.x, o.y + t * d.y, o.z + t * d.z};
}

vector_t vector_normalizar(vector_t a)
{
    float n = vector_norma(a);
    return (vector_t){a.x / n, a.y / n, a.z / n};
}

#ifdef MISTAKE_SUMAR_DOUBLE
color_t color_sumar(color_t c, color_t m, double p)
#else
color_t color_sumar(color_t c, color_t m, float p)
#endif
{
    return (color_t){c.r + p * m.r, c.g + p * m.g, c.b + p * m.b};
}

color_t color_absorber(color_t b, color_t c)
{
    return (color_t){b.r * c.r, b.g * c.g, b.b * c.b};
}

static int byte(float c)
{
#ifdef MISTAKE_IMPRIMIR_ROUNDS
    return c > 1 ? 255 : (int)(255 * c + 0.5);
#else
    return c > 1 ? 255 : (int)(255 * c);
#endif
}

void color_imprimir(color_t c)
{
    printf("%d %d %d", byte(c.r), byte(c.g), byte(c.b));
}

esfera_t *esfera_crear(vector_t centro, float radio, color_t color, float ka,
                       float kd)
{
    esfera_t *e = malloc(sizeof(esfera_t));
    if (e == NULL)
        return NULL;
    e->centro = centro;
    e->radio = radio;
    e->color = color;
#ifdef MISTAKE_CREAR_SWAPS
    e->ka = kd;
    e->kd = ka;
#else
    e->ka = ka;
    e->kd = kd;
#endif
    return e;
}

void esfera_destruir(esfera_t *esfera)
{
    free(esfera);
}

luz_t *luz_crear(vector_t posicion, color_t color, bool es_puntual)
{
    luz_t *l = malloc(sizeof(luz_t));
    if (l == NULL)
        return NULL;
    l->posicion = posicion;
    l->color = color;
#ifdef MISTAKE_LUZ_ALWAYS_POINT
    (void)es_puntual;
    l->es_puntual = true;
#else
    l->es_puntual = es_puntual;
#endif
    return l;
}

void luz_destruir(luz_t *luz)
{
    free(luz);
}

float esfera_distancia(const esfera_t *esfera, vector_t o, vector_t d,
                       vector_t *punto, vector_t *normal)
{
    vector_t oc = vector_resta(esfera->centro, o);
    float beta = vector_producto_interno(oc, d);
    float delta = beta * beta - vector_producto_interno(oc, oc) +
                  esfera->radio * esfera->radio;
    float t;
    if (delta < 0)
        return INFINITO;
    if (beta - sqrt(delta) > 0)
        t = beta - sqrt(delta);
    else if (beta + sqrt(delta) > 0)
        t = beta + sqrt(delta);
    else
        return INFINITO;
    *punto = vector_interpolar_recta(o, d, t);
#ifdef MISTAKE_NORMAL_UNNORMALISED
    *normal = vector_resta(*punto, esfera->centro);
#else
    *normal = vector_normalizar(vector_resta(*punto, esfera->centro));
#endif
    return t;
}

bool arreglo_agregar(arreglo_t *a, void *e)
{
#ifdef MISTAKE_REALLOC_DIRECT
    a->v = realloc(a->v, (a->n + 1) * sizeof(void *));
    if (a->v == NULL)
        return false;
    a->v[a->n++] = e;
    return true;
#elif defined(MISTAKE_WRITE_PAST_END)
    void **aux = realloc(a->v, a->n * sizeof(void *));
    if (aux == NULL)
        return false;
    a->v = aux;
    a->v[a->n++] = e;
    return true;
#elif defined(MISTAKE_N_FIRST)
    a->n++;
    void **aux = realloc(a->v, a->n * sizeof(void *));
    if (aux == NULL)
        return false;
    a->v = aux;
    a->v[a->n - 1] = e;
    return true;
#else
    void **aux = realloc(a->v, (a->n + 1) * sizeof(void *));
    if (aux == NULL)
        return false;
    a->v = aux;
    a->v[a->n++] = e;
    return true;
#endif
}

/* Whether another sphere lies between p and the light (at most limit
   away along l). */
static bool sombra(const arreglo_t *esferas, const esfera_t *propia,
                   vector_t p, vector_t l, float limite)
{
    for (size_t j = 0; j < esferas->n; j++) {
        vector_t q, n;
        float t;
        if (esferas->v[j] == propia)
            continue;
        t = esfera_distancia(esferas->v[j], p, l, &q, &n);
#ifdef MISTAKE_BEYOND_LIGHT
        (void)limite;
        if (t < INFINITO)
            return true;
#else
        if (t < limite)
            return true;
#endif
    }
    return false;
}

color_t computar_intensidad(const arreglo_t *esferas, const arreglo_t *luces,
                            color_t ambiente, vector_t o, vector_t d)
{
    float t_min = INFINITO;
    esfera_t *cercana = NULL;
    vector_t punto = {0, 0, 0}, normal = {0, 0, 0};
    for (size_t i = 0; i < esferas->n; i++) {
        vector_t p, n;
        float t = esfera_distancia(esferas->v[i], o, d, &p, &n);
        if (t < t_min) {
            t_min = t;
            cercana = esferas->v[i];
            punto = p;
            normal = n;
        }
    }
    if (cercana == NULL)
        return (color_t){0, 0, 0};
    color_t c = color_sumar((color_t){0, 0, 0}, ambiente, cercana->ka);
    for (size_t i = 0; i < luces->n; i++) {
        luz_t *luz = luces->v[i];
        vector_t l = luz->posicion;
        float limite = INFINITO;
        if (luz->es_puntual) {
            l = vector_resta(luz->posicion, punto);
            limite = vector_norma(l);
            l = vector_normalizar(l);
        }
        float ln = vector_producto_interno(l, normal);
        if (ln > 0 && !sombra(esferas, cercana, punto, l, limite))
            c = color_sumar(c, luz->color, cercana->kd * ln);
    }
    return color_absorber(c, cercana->color);
}

#ifdef MISTAKE_NO_TYPEDEF
#undef vector_t
#endif

int main(void)
{
    return 0;
}
