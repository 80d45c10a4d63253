#include <math.h>
#include <stdlib.h>
#include "objeto.h"

struct objeto {
    geometria_t geometria;
    void *g;
    color_t color;
    float ka, kd, ks, kr;
};

typedef float (*distancia_t)(const void *, vector_t, vector_t, vector_t *,
                             vector_t *);
typedef void (*destruir_t)(void *);

static float distancia_esfera(const void *g, vector_t o, vector_t d,
                              vector_t *p, vector_t *n)
{
    return esfera_distancia(g, o, d, p, n);
}

static float distancia_plano(const void *g, vector_t o, vector_t d,
                             vector_t *p, vector_t *n)
{
    return plano_distancia(g, o, d, p, n);
}

static float distancia_triangulo(const void *g, vector_t o, vector_t d,
                                 vector_t *p, vector_t *n)
{
    return triangulo_distancia(g, o, d, p, n);
}

static float distancia_malla(const void *g, vector_t o, vector_t d,
                             vector_t *p, vector_t *n)
{
    return malla_distancia(g, o, d, p, n);
}

static void destruir_esfera(void *g) { esfera_destruir(g); }
static void destruir_plano(void *g) { plano_destruir(g); }
static void destruir_triangulo(void *g) { triangulo_destruir(g); }
static void destruir_malla(void *g) { malla_destruir(g); }

/* Tablas de busqueda, indexadas por geometria_t: sin condicionales. */
static const distancia_t distancias[] = {
    distancia_esfera, distancia_plano, distancia_triangulo, distancia_malla
};

static const destruir_t destructores[] = {
    destruir_esfera, destruir_plano, destruir_triangulo, destruir_malla
};

objeto_t *objeto_crear(geometria_t geometria, void *g, color_t color,
                       float ka, float kd, float ks, float kr)
{
    objeto_t *o = malloc(sizeof(objeto_t));
    if (o == NULL) {
        destructores[geometria](g);
        return NULL;
    }
    o->geometria = geometria;
    o->g = g;
    o->color = color;
    o->ka = ka;
    o->kd = kd;
    o->ks = ks;
    o->kr = kr;
    return o;
}

void objeto_destruir(objeto_t *objeto)
{
    destructores[objeto->geometria](objeto->g);
    free(objeto);
}

color_t objeto_color(const objeto_t *objeto) { return objeto->color; }
float objeto_ka(const objeto_t *objeto) { return objeto->ka; }
float objeto_kd(const objeto_t *objeto) { return objeto->kd; }
float objeto_ks(const objeto_t *objeto) { return objeto->ks; }
float objeto_kr(const objeto_t *objeto) { return objeto->kr; }

/* La normal devuelta mira hacia el rayo. */
float objeto_distancia(const objeto_t *objeto, vector_t o, vector_t d,
                       vector_t *punto, vector_t *normal)
{
    float t = distancias[objeto->geometria](objeto->g, o, d, punto, normal);
    if (isinf(t))
        return t;
    if (vector_producto_interno(*normal, d) > 0)
        *normal = vector_escalar(*normal, -1);
    return t;
}
