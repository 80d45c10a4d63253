/* CORPUS: a whole TP1 submission (20212_tp1) written in rayo's test tree
   as a careful student of the course would: modules for vectors, colours,
   the four geometries, objeto_t with lookup tables, lights, arreglo_t and
   the course's imagen_t with its PPM and BMP writers. Its hard-coded scene
   is exactly examples/tp1.scene (the mesh read from "gema.stl" in the
   current folder), so tests/cli/tp1_student.t can check rayo's course-tp1
   mode against an independent program. It is not a grading fixture: it
   lives one folder below tests/grade/tp1/, where grade_reports.t does not
   look. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "arreglo.h"
#include "color.h"
#include "imagen.h"
#include "luz.h"
#include "objeto.h"
#include "vector.h"

#define FOV 90
#define EPSILON 1e-6
#define EXPONENTE 10
#define ARCHIVO_MALLA "gema.stl"

/* El objeto mas cercano a lo largo de o + t d, o NULL. */
static const objeto_t *mas_cercano(const arreglo_t *objetos, vector_t o,
                                   vector_t d, vector_t *punto,
                                   vector_t *normal)
{
    const objeto_t *cercano = NULL;
    float minima = INFINITY;
    size_t i;
    for (i = 0; i < objetos->n; i++) {
        vector_t p, n;
        float t = objeto_distancia(objetos->v[i], o, d, &p, &n);
        if (t < minima) {
            minima = t;
            cercano = objetos->v[i];
            *punto = p;
            *normal = n;
        }
    }
    return cercano;
}

color_t computar_intensidad(int profundidad, const arreglo_t *objetos,
                            const arreglo_t *luces, color_t ambiente,
                            vector_t o, vector_t d)
{
    vector_t p, n, r;
    color_t c;
    size_t i;
    const objeto_t *objeto = mas_cercano(objetos, o, d, &p, &n);
    if (objeto == NULL)
        return color_crear(0, 0, 0);
    r = vector_reflejar(d, n);
    c = color_sumar(color_crear(0, 0, 0), ambiente, objeto_ka(objeto));
    for (i = 0; i < luces->n; i++) {
        const luz_t *luz = luces->v[i];
        vector_t l = luz_direccion(luz, p);
        vector_t ps, ns;
        double ln, lr, factor = 0;
        if (mas_cercano(objetos, vector_suma(p, vector_escalar(l, EPSILON)),
                        l, &ps, &ns) != NULL)
            continue; /* sombra */
        ln = vector_producto_interno(l, n);
        lr = vector_producto_interno(l, r);
        if (ln > 0)
            factor += objeto_kd(objeto) * ln;
        if (lr > 0)
            factor += objeto_ks(objeto) * pow(lr, EXPONENTE);
        c = color_sumar(c, luz->color, factor);
    }
    c = color_absorber(c, objeto_color(objeto));
    if (profundidad > 0 && objeto_kr(objeto) > 0) {
        color_t reflejado = computar_intensidad(profundidad - 1, objetos, luces,
            ambiente, vector_suma(p, vector_escalar(r, EPSILON)), r);
        c = color_sumar(c, reflejado, objeto_kr(objeto));
    }
    return c;
}

static void destruir_objeto(void *objeto)
{
    objeto_destruir(objeto);
}

static bool agregar(arreglo_t *objetos, geometria_t tipo, void *g, color_t color,
                    float ka, float kd, float ks, float kr)
{
    objeto_t *o;
    if (g == NULL)
        return false;
    o = objeto_crear(tipo, g, color, ka, kd, ks, kr);
    if (o == NULL)
        return false;
    if (!arreglo_agregar(objetos, o)) {
        objeto_destruir(o);
        return false;
    }
    return true;
}

/* La escena: la de examples/tp1.scene de rayo. */
static bool armar_escena(arreglo_t *objetos, arreglo_t *luces)
{
    luz_t *l;
    l = luz_crear(vector_crear(-2, 4, 1), color_crear(.7f, .7f, .7f), true);
    if (l == NULL || !arreglo_agregar(luces, l)) {
        free(l);
        return false;
    }
    l = luz_crear(vector_crear(1, 1, -1), color_crear(.4f, .4f, .4f), false);
    if (l == NULL || !arreglo_agregar(luces, l)) {
        free(l);
        return false;
    }
    return agregar(objetos, PLANO,
                   plano_crear(vector_crear(0, -1, 0), vector_crear(0, 1, 0)),
                   color_crear(.9f, .9f, .9f), 1, .6f, .2f, .35f)
        && agregar(objetos, ESFERA,
                   esfera_crear(vector_crear(-1.4, -.2, 4.2), .8),
                   color_crear(.9f, .2f, .15f), 1, .9f, .6f, .1f)
        && agregar(objetos, TRIANGULO,
                   triangulo_crear(vector_crear(-.6, -1, 6.5),
                                   vector_crear(1.2, -1, 7),
                                   vector_crear(.1, 1.6, 7.2)),
                   color_crear(.2f, .35f, .9f), 1, .8f, .5f, 0)
        && agregar(objetos, MALLA,
                   malla_crear_desde_stl(ARCHIVO_MALLA, .42,
                                         vector_crear(15, 30, 0),
                                         vector_crear(1.7, -.2, 3.9)),
                   color_crear(.95f, .75f, .2f), 1, .8f, .8f, .2f);
}

static bool termina_en(const char *s, const char *sufijo)
{
    size_t n = strlen(s), m = strlen(sufijo);
    return n >= m && strcmp(s + n - m, sufijo) == 0;
}

int main(int argc, char *argv[])
{
    int ancho, alto, profundidad, x, y;
    double z;
    arreglo_t *objetos, *luces;
    imagen_t *im;
    FILE *f;
    bool ppm;
    int estado = 0;

    if (argc != 5) {
        fprintf(stderr, "Uso: %s [ancho] [alto] [profundidad] [nombrearchivo]\n",
                argv[0]);
        return 1;
    }
    ancho = atoi(argv[1]);
    alto = atoi(argv[2]);
    profundidad = atoi(argv[3]);
    if (ancho <= 0 || alto <= 0 || profundidad < 0) {
        fprintf(stderr, "Ancho y alto deben ser positivos y la profundidad no negativa\n");
        return 1;
    }
    ppm = termina_en(argv[4], ".ppm");
    if (!ppm && !termina_en(argv[4], ".bmp")) {
        fprintf(stderr, "El archivo debe terminar en .ppm o .bmp\n");
        return 1;
    }

    objetos = arreglo_crear();
    luces = arreglo_crear();
    if (objetos == NULL || luces == NULL || !armar_escena(objetos, luces)) {
        fprintf(stderr, "No se pudo armar la escena (falta %s?)\n", ARCHIVO_MALLA);
        if (objetos != NULL)
            arreglo_destruir(objetos, destruir_objeto);
        if (luces != NULL)
            arreglo_destruir(luces, luz_destruir);
        return 1;
    }

    im = imagen_crear(ancho, alto);
    if (im == NULL) {
        arreglo_destruir(objetos, destruir_objeto);
        arreglo_destruir(luces, luz_destruir);
        return 1;
    }
    z = ancho / 2 / tan(FOV / 2.0 * 3.14159265358979323846 / 180);
    for (y = alto / 2; y > -alto / 2; y--)
        for (x = -ancho / 2; x < ancho / 2; x++) {
            vector_t d = vector_normalizar(vector_crear(x, y, z));
            color_t c = computar_intensidad(profundidad, objetos, luces,
                color_crear(.05f, .05f, .05f), vector_crear(0, 0, 0), d);
            imagen_set_pixel(im, x + ancho / 2, alto / 2 - y, c);
        }

    f = fopen(argv[4], ppm ? "w" : "wb");
    if (f == NULL) {
        fprintf(stderr, "No se pudo abrir %s\n", argv[4]);
        estado = 1;
    } else {
        if (ppm)
            escribir_PPM(im, f);
        else
            escribir_BMP(im, f);
        if (fclose(f) != 0)
            estado = 1;
    }
    imagen_destruir(im);
    arreglo_destruir(objetos, destruir_objeto);
    arreglo_destruir(luces, luz_destruir);
    return estado;
}
