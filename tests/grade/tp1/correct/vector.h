#ifndef VECTOR_H
#define VECTOR_H

/* Vectores de R3 (de EJ3). */
typedef struct {
    double x, y, z;
} vector_t;

vector_t vector_crear(double x, double y, double z);
vector_t vector_suma(vector_t a, vector_t b);
vector_t vector_resta(vector_t a, vector_t b);
vector_t vector_escalar(vector_t a, double k);
double vector_producto_interno(vector_t a, vector_t b);
vector_t vector_producto_vectorial(vector_t a, vector_t b);
double vector_norma(vector_t a);
vector_t vector_normalizar(vector_t a);
/* Refleja d respecto de la normal n: d - 2 n (d.n). */
vector_t vector_reflejar(vector_t d, vector_t n);

#endif
