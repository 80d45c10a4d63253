/*
 * ej2_light_moved/main.c - a student-style submission for Ejercicio
 * obligatorio 2, written for rayo's grade tests.
 * Mistake: the light vector's x has lost its sign: (-0.287, 0.958, 0).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define ANCHO 640
#define ALTO 480
#define FOV 90

#define PI 3.14159265358979323846

#define INFINITO FLT_MAX
#define IA 5
#define II 255

const float luz[3] = {-0.2873478855663454, 0.9578262852211513, 0};

const float centros[][3] = {
    {-0.4, 0.75, 1.55},
    {-0.55, -0.4, 2},
    {3, 1.5, 4},
    {3, 1.5, 5},
    {3, -1.5, 4},
    {3, -1.5, 5},
};

const float radios[] = {0.3, 0.85, 0.4, 0.4, 0.4, 0.4};

float producto_interno(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

float norma(const float a[3])
{
    return sqrt(producto_interno(a, a));
}

void normalizar(float a[3])
{
    float n = norma(a);
    a[0] /= n;
    a[1] /= n;
    a[2] /= n;
}

/* r = a - b */
void resta(float r[3], const float a[3], const float b[3])
{
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
}

/* p = o + t d */
void interpolar_recta(float p[3], const float o[3], const float d[3], float t)
{
    p[0] = o[0] + t * d[0];
    p[1] = o[1] + t * d[1];
    p[2] = o[2] + t * d[2];
}

/* Devuelve la menor t positiva, o INFINITO si el rayo no toca la esfera. */
float distancia_esfera(const float c[3], float r, const float o[3],
                       const float d[3])
{
    float oc[3];
    resta(oc, c, o);
    float beta = producto_interno(oc, d);
    float delta = beta * beta - producto_interno(oc, oc) + r * r;
    if (delta < 0)
        return INFINITO;
    float raiz = sqrt(delta);
    if (beta - raiz > 0)
        return beta - raiz;
    if (beta + raiz > 0)
        return beta + raiz;
    return INFINITO;
}

void normal_esfera(float normal[3], const float c[3], float r,
                   const float p[3])
{
    resta(normal, p, c);
    normal[0] /= r;
    normal[1] /= r;
    normal[2] /= r;
}

int computar_intensidad(const float cs[][3], const float rs[],
                        size_t n_esferas, const float luz[3],
                        const float o[3], const float d[3])
{
    float t_min = INFINITO;
    size_t i_min = 0;

    /* La esfera mas cercana */
    for (size_t i = 0; i < n_esferas; i++) {
        float t = distancia_esfera(cs[i], rs[i], o, d);
        if (t < t_min) {
            t_min = t;
            i_min = i;
        }
    }
    if (t_min == INFINITO)
        return 0;

    float p[3], normal[3];
    interpolar_recta(p, o, d, t_min);
    normal_esfera(normal, cs[i_min], rs[i_min], p);

    float ln = producto_interno(luz, normal);
    if (ln <= 0)
        return IA;

    /* Sombras: si otra esfera tapa la luz solo queda la ambiente */
    for (size_t i = 0; i < n_esferas; i++) {
        if (i == i_min)
            continue;
        if (distancia_esfera(cs[i], rs[i], p, luz) < INFINITO)
            return IA;
    }

    float intensidad = IA + II * ln;
    if (intensidad > 255)
        return 255;
    return intensidad;
}

int main(void)
{
    const float origen[3] = {0, 0, 0};
    size_t n_esferas = sizeof(radios) / sizeof(radios[0]);
    float z = ANCHO / 2 / tan(FOV / 2 * PI / 180);

    printf("P2\n%d %d\n255\n", ANCHO, ALTO);
    for (int vy = ALTO / 2; vy > -ALTO / 2; vy--) {
        for (int vx = -ANCHO / 2; vx < ANCHO / 2; vx++) {
            float d[3] = {vx, vy, z};
            normalizar(d);
            printf("%d\n", computar_intensidad(centros, radios, n_esferas,
                                               luz, origen, d));
        }
    }
    return 0;
}
