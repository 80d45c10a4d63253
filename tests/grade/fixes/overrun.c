/*
 * overrun.c - an arreglo_agregar that grows v to n elements, not n + 1,
 * and then writes v[n]: one element past the end.  Everything is freed.
 */
#define OWN_ARREGLO_AGREGAR
#include "escena.c"

bool arreglo_agregar(arreglo_t *a, void *e)
{
    void **v = realloc(a->v, (a->n + 1) * sizeof *v - sizeof *v);
    if (v == NULL && a->n > 0)
        return false;
    a->v = v;
    a->v[a->n++] = e;
    return true;
}

int main(void)
{
    arreglo_t esferas = {NULL, 0};
    vector_t o = {0, 0, 1};
    color_t c = {1, 1, 1};
    esfera_t *e = esfera_crear(o, 1, c, 0.2f, 0.8f);
    if (e == NULL)
        return 1;
    if (!arreglo_agregar(&esferas, e)) {
        esfera_destruir(e);
        return 1;
    }
    esfera_destruir(e);
    free(esferas.v);
    return 0;
}
