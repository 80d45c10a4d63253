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

/* m = Rz Ry Rx */
static void rotacion(vector_t grados, double m[3][3])
{
    double cx = cos(grados.x * PI / 180), sx = sin(grados.x * PI / 180);
    double cy = cos(grados.y * PI / 180), sy = sin(grados.y * PI / 180);
    double cz = cos(grados.z * PI / 180), sz = sin(grados.z * PI / 180);
    m[0][0] = cz * cy;
    m[0][1] = cz * sy * sx - sz * cx;
    m[0][2] = cz * sy * cx + sz * sx;
    m[1][0] = sz * cy;
    m[1][1] = sz * sy * sx + cz * cx;
    m[1][2] = sz * sy * cx - cz * sx;
    m[2][0] = -sy;
    m[2][1] = cy * sx;
    m[2][2] = cy * cx;
}

static vector_t rotar(double m[3][3], const float v[3])
{
    return vector_crear(m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
                        m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
                        m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]);
}

malla_t *malla_crear_desde_stl(const char *archivo, double s, vector_t grados,
                               vector_t t)
{
    char encabezado[80];
    uint32_t n, i;
    double m[3][3];
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
    rotacion(grados, m);
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
            p[k] = vector_suma(vector_escalar(rotar(m, datos + 3 + 3 * k), s), t);
        calculada = vector_producto_vectorial(vector_resta(p[1], p[0]),
                                              vector_resta(p[2], p[0]));
        if (vector_norma(calculada) == 0)
            continue; /* degenerado: se descarta */
        normal = rotar(m, datos);
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
