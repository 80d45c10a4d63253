#include <math.h>
#include "vector.h"

vector_t vector_crear(double x, double y, double z)
{
    vector_t v;
    v.x = x;
    v.y = y;
    v.z = z;
    return v;
}

vector_t vector_suma(vector_t a, vector_t b)
{
    return vector_crear(a.x + b.x, a.y + b.y, a.z + b.z);
}

vector_t vector_resta(vector_t a, vector_t b)
{
    return vector_crear(a.x - b.x, a.y - b.y, a.z - b.z);
}

vector_t vector_escalar(vector_t a, double k)
{
    return vector_crear(a.x * k, a.y * k, a.z * k);
}

double vector_producto_interno(vector_t a, vector_t b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

vector_t vector_producto_vectorial(vector_t a, vector_t b)
{
    return vector_crear(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z,
                        a.x * b.y - a.y * b.x);
}

double vector_norma(vector_t a)
{
    return sqrt(vector_producto_interno(a, a));
}

vector_t vector_normalizar(vector_t a)
{
    return vector_escalar(a, 1 / vector_norma(a));
}

vector_t vector_reflejar(vector_t d, vector_t n)
{
    return vector_resta(d, vector_escalar(n, 2 * vector_producto_interno(d, n)));
}
