/*
 * stub_ej3.c - stand-ins for a student's Ejercicio 3 types and
 * functions, so that `make check` compiles and links the harness
 * (src/grade/functions/harness/ej3.c, with its allocation wraps) with
 * the course's flags: a typo there fails the build's checks, not a
 * student's grade.  Not a model solution: most return a zero value.
 */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

typedef struct { float x, y, z; } vector_t;
typedef struct { float r, g, b; } color_t;
typedef struct { vector_t centro; float radio; color_t color;
    float ka, kd; } esfera_t;
typedef struct { vector_t posicion; color_t color; bool es_puntual; } luz_t;
typedef struct { void **v; size_t n; } arreglo_t;

float vector_producto_interno(vector_t a, vector_t b);
float vector_norma(vector_t a);
vector_t vector_resta(vector_t a, vector_t b);
vector_t vector_interpolar_recta(vector_t o, vector_t d, float t);
vector_t vector_normalizar(vector_t a);
color_t color_sumar(color_t c, color_t m, float p);
color_t color_absorber(color_t b, color_t c);
void color_imprimir(color_t c);
esfera_t *esfera_crear(vector_t centro, float radio, color_t color, float ka,
                       float kd);
void esfera_destruir(esfera_t *esfera);
luz_t *luz_crear(vector_t posicion, color_t color, bool es_puntual);
void luz_destruir(luz_t *luz);
float esfera_distancia(const esfera_t *esfera, vector_t o, vector_t d,
                       vector_t *punto, vector_t *normal);
bool arreglo_agregar(arreglo_t *a, void *e);
color_t computar_intensidad(const arreglo_t *esferas, const arreglo_t *luces,
                            color_t ambiente, vector_t o, vector_t d);
int rayo_student_main(void);

float vector_producto_interno(vector_t a, vector_t b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

float vector_norma(vector_t a)
{
    (void)a;
    return 0;
}

vector_t vector_resta(vector_t a, vector_t b)
{
    vector_t r;
    r.x = a.x - b.x, r.y = a.y - b.y, r.z = a.z - b.z;
    return r;
}

vector_t vector_interpolar_recta(vector_t o, vector_t d, float t)
{
    (void)d, (void)t;
    return o;
}

vector_t vector_normalizar(vector_t a)
{
    return a;
}

color_t color_sumar(color_t c, color_t m, float p)
{
    (void)m, (void)p;
    return c;
}

color_t color_absorber(color_t b, color_t c)
{
    (void)c;
    return b;
}

void color_imprimir(color_t c)
{
    printf("%d %d %d", (int)(255 * c.r), (int)(255 * c.g), (int)(255 * c.b));
}

esfera_t *esfera_crear(vector_t centro, float radio, color_t color, float ka,
                       float kd)
{
    esfera_t *e = malloc(sizeof *e);
    if (e == NULL)
        return NULL;
    e->centro = centro, e->radio = radio, e->color = color;
    e->ka = ka, e->kd = kd;
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
    l->posicion = posicion, l->color = color, l->es_puntual = es_puntual;
    return l;
}

void luz_destruir(luz_t *luz)
{
    free(luz);
}

float esfera_distancia(const esfera_t *esfera, vector_t o, vector_t d,
                       vector_t *punto, vector_t *normal)
{
    (void)esfera, (void)d;
    *punto = *normal = o;
    return 0;
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

color_t computar_intensidad(const arreglo_t *esferas, const arreglo_t *luces,
                            color_t ambiente, vector_t o, vector_t d)
{
    (void)esferas, (void)luces, (void)o, (void)d;
    return ambiente;
}

int rayo_student_main(void)
{
    return 0;
}
