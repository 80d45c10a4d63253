/*
 * ej3_directional_moved/main.c - a student-style submission for Ejercicio
 * obligatorio 3, written for rayo's grade tests.
 * Mistake: the directional light typed (1, 1, 0), not (0, 1, 0).
 */
#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

#define ANCHO 640
#define ALTO 480
#define FOV 90

#define PI 3.14159265358979323846

#define INFINITO FLT_MAX

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
    vector_t posicion; /* un punto si es puntual, si no una direccion */
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

/* c + p m */
color_t color_sumar(color_t c, color_t m, float p)
{
    return (color_t){c.r + p * m.r, c.g + p * m.g, c.b + p * m.b};
}

color_t color_absorber(color_t b, color_t c)
{
    return (color_t){b.r * c.r, b.g * c.g, b.b * c.b};
}

void color_imprimir(color_t c)
{
    printf("%d %d %d", c.r > 1 ? 255 : (int)(255 * c.r),
           c.g > 1 ? 255 : (int)(255 * c.g),
           c.b > 1 ? 255 : (int)(255 * c.b));
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
    luz_t *l = malloc(sizeof(luz_t));
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

/* La menor t positiva (y el punto y la normal ahi), o INFINITO */
float esfera_distancia(const esfera_t *esfera, vector_t o, vector_t d,
                       vector_t *punto, vector_t *normal)
{
    vector_t oc = vector_resta(esfera->centro, o);
    float beta = vector_producto_interno(oc, d);
    float delta = beta * beta - vector_producto_interno(oc, oc) +
                  esfera->radio * esfera->radio;
    if (delta < 0)
        return INFINITO;

    float raiz = sqrt(delta);
    float t;
    if (beta - raiz > 0)
        t = beta - raiz;
    else if (beta + raiz > 0)
        t = beta + raiz;
    else
        return INFINITO;

    *punto = vector_interpolar_recta(o, d, t);
    *normal = vector_normalizar(vector_resta(*punto, esfera->centro));
    return t;
}

bool arreglo_agregar(arreglo_t *a, void *e)
{
    void **aux = realloc(a->v, (a->n + 1) * sizeof(void *));
    if (aux == NULL)
        return false;
    a->v = aux;
    a->v[a->n] = e;
    a->n++;
    return true;
}

color_t computar_intensidad(const arreglo_t *esferas, const arreglo_t *luces,
                            color_t ambiente, vector_t o, vector_t d)
{
    float t_min = INFINITO;
    esfera_t *cercana = NULL;
    vector_t punto = {0, 0, 0}, normal = {0, 0, 0};

    /* La esfera mas cercana */
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
        vector_t l;
        if (luz->es_puntual)
            l = vector_normalizar(vector_resta(luz->posicion, punto));
        else
            l = luz->posicion;

        float ln = vector_producto_interno(l, normal);
        if (ln <= 0)
            continue;

        /* Sombra: otra esfera entre el punto y la luz */
        /* Una luz puntual solo la tapa una esfera antes de llegar a ella */
        float distancia_luz = luz->es_puntual
            ? vector_norma(vector_resta(luz->posicion, punto)) : INFINITO;
        bool sombra = false;
        for (size_t j = 0; j < esferas->n; j++) {
            vector_t p, n;
            if (esferas->v[j] == cercana)
                continue;
            if (esfera_distancia(esferas->v[j], punto, l, &p, &n) < distancia_luz) {
                sombra = true;
                break;
            }
        }
        if (!sombra)
            c = color_sumar(c, luz->color, cercana->kd * ln);
    }

    return color_absorber(c, cercana->color);
}

int main(void)
{
    arreglo_t luces = {NULL, 0};
    arreglo_t esferas = {NULL, 0};

    color_t ambiente = {.05, .05, .05};

    assert(arreglo_agregar(&luces, luz_crear(vector_normalizar((vector_t){1, 1, 0}), (color_t){.2, .2, .2}, false)));
    assert(arreglo_agregar(&luces, luz_crear((vector_t){-2, 10, 2.5}, (color_t){.9, 0, 0}, true)));
    assert(arreglo_agregar(&luces, luz_crear((vector_t){2, 10, 2.5}, (color_t){0, .9, 0}, true)));
    assert(arreglo_agregar(&luces, luz_crear((vector_t){0, 10, 5}, (color_t){0, 0, .9}, true)));

    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){0, 1, 2.4}, .3, (color_t){1, 1, 1}, 1, 1)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){0, -.4, 3}, 1, (color_t){1, 1, 1}, 1, 1)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){-2, -.6, 3}, .3, (color_t){1, 0, 0}, 1, .8)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){-1.73, -.6, 2}, .3, (color_t){1, 1, 0}, 1, 1)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){-1, -.6, 1.26}, .3, (color_t){0, 1, 0}, 1, 1)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){0, -.6, 1}, .3, (color_t){1, 1, 1}, 1, 1)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){1, -.6, 1.26}, .3, (color_t){0, 1, 1}, 1, 1)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){1.73, -.6, 2}, .3, (color_t){0, 0, 1}, 1, 1)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){2, -.6, 3}, .3, (color_t){1, 0, 1}, 1, 1)));

    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){-3, 2.5, 4.3}, .3, (color_t){1, 1, 1}, 1, 0)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){-2, 2.5, 4.3}, .3, (color_t){1, 1, 1}, 1, .16)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){-1, 2.5, 4.3}, .3, (color_t){1, 1, 1}, 1, .33)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){0, 2.5, 4.3}, .3, (color_t){1, 1, 1}, 1, .5)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){1, 2.5, 4.3}, .3, (color_t){1, 1, 1}, 1, .66)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){2, 2.5, 4.3}, .3, (color_t){1, 1, 1}, 1, .83)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){3, 2.5, 4.3}, .3, (color_t){1, 1, 1}, 1, 1)));

    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){-3, 1.5, 4}, .3, (color_t){1, 1, 1}, 0, 1)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){-2, 1.5, 4}, .3, (color_t){1, 1, 1}, .16, 1)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){-1, 1.5, 4}, .3, (color_t){1, 1, 1}, .33, 1)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){0, 1.5, 4}, .3, (color_t){1, 1, 1}, .5, 1)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){1, 1.5, 4}, .3, (color_t){1, 1, 1}, .66, 1)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){2, 1.5, 4}, .3, (color_t){1, 1, 1}, .83, 1)));
    assert(arreglo_agregar(&esferas, esfera_crear((vector_t){3, 1.5, 4}, .3, (color_t){1, 1, 1}, 1, 1)));

    printf("P3\n");
    printf("%d %d\n", ANCHO, ALTO);
    printf("255\n");

    float vz = ANCHO / 2 / tan(FOV / 2 * PI / 180);

    for (int vy = ALTO / 2; vy > - ALTO / 2; vy--)
        for (int vx = - ANCHO / 2; vx < ANCHO / 2; vx++) {
            color_imprimir(computar_intensidad(&esferas, &luces, ambiente, (vector_t){0, 0, 0}, vector_normalizar((vector_t){vx, vy, vz})));
            putchar('\n');
        }

    for (size_t i = 0; i < esferas.n; i++)
        esfera_destruir(esferas.v[i]);
    free(esferas.v);

    for (size_t i = 0; i < luces.n; i++)
        luz_destruir(luces.v[i]);
    free(luces.v);

    return 0;
}
