#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "malla.h"
#include "triangulo.h"

#define PI 3.14159265358979323846

struct malla {
    triangulo_t **triangulos;
    size_t n;
};

/* Gira v alrededor de x, luego de y, luego de z, por los angulos en grados
   (regla de la mano derecha), un giro por vez. */
static vector_t rotar(vector_t grados, const float v[3])
{
    double ax = grados.x * PI / 180, ay = grados.y * PI / 180;
    double az = grados.z * PI / 180;
    double x = v[0], y = v[1], z = v[2], aux;
    aux = y * cos(ax) - z * sin(ax); /* alrededor de x */
    z = y * sin(ax) + z * cos(ax);
    y = aux;
    aux = z * sin(ay) + x * cos(ay); /* alrededor de y */
    z = z * cos(ay) - x * sin(ay);
    x = aux;
    aux = x * cos(az) - y * sin(az); /* alrededor de z */
    y = x * sin(az) + y * cos(az);
    x = aux;
    return vector_crear(x, y, z);
}

malla_t *malla_crear_desde_stl(const char *archivo, double s, vector_t grados,
                               vector_t t)
{
    char encabezado[80];
    uint32_t n, i;
    malla_t *malla;
    FILE *f = fopen(archivo, "rb");
    if (f == NULL)
        return NULL;
    if (fread(encabezado, 1, 80, f) != 80 || fread(&n, sizeof(n), 1, f) != 1) {
        fclose(f);
        return NULL;
    }
    malla = malloc(sizeof(malla_t));
    if (malla == NULL) {
        fclose(f);
        return NULL;
    }
    malla->triangulos = malloc(n * sizeof(triangulo_t *) + 1);
    malla->n = 0;
    if (malla->triangulos == NULL) {
        free(malla);
        fclose(f);
        return NULL;
    }
    for (i = 0; i < n; i++) {
        float datos[12];
        uint16_t atributo;
        vector_t p[3], normal, calculada;
        triangulo_t *tr;
        int k;
        if (fread(datos, sizeof(float), 12, f) != 12
            || fread(&atributo, sizeof(atributo), 1, f) != 1) {
            malla_destruir(malla);
            fclose(f);
            return NULL;
        }
        for (k = 0; k < 3; k++)
            p[k] = vector_suma(vector_escalar(rotar(grados, datos + 3 + 3 * k), s), t);
        calculada = vector_producto_vectorial(vector_resta(p[1], p[0]),
                                              vector_resta(p[2], p[0]));
        if (vector_norma(calculada) == 0)
            continue; /* degenerado: se descarta */
        normal = rotar(grados, datos);
        if (vector_norma(normal) == 0)
            normal = calculada;
        tr = triangulo_crear_con_normal(p[0], p[1], p[2], normal);
        if (tr == NULL) {
            malla_destruir(malla);
            fclose(f);
            return NULL;
        }
        malla->triangulos[malla->n++] = tr;
    }
    fclose(f);
    return malla;
}

void malla_destruir(malla_t *malla)
{
    size_t i;
    for (i = 0; i < malla->n; i++)
        triangulo_destruir(malla->triangulos[i]);
    free(malla->triangulos);
    free(malla);
}

float malla_distancia(const malla_t *malla, vector_t o, vector_t d,
                      vector_t *punto, vector_t *normal)
{
    float minima = INFINITY;
    size_t i;
    for (i = 0; i < malla->n; i++) {
        vector_t p, n;
        float t = triangulo_distancia(malla->triangulos[i], o, d, &p, &n);
        if (t < minima) {
            minima = t;
            *punto = p;
            *normal = n;
        }
    }
    return minima;
}
