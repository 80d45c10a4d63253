/*
 * leak_all.c - frees nothing: neither the spheres nor the arrays' v.  The
 * array is definitely lost and the spheres it points to indirectly lost;
 * both mistakes are to be named.
 */
#include "escena.c"

int main(void)
{
    arreglo_t esferas = {NULL, 0};
    vector_t o = {0, 0, 1};
    color_t c = {1, 1, 1};
    if (!arreglo_agregar(&esferas, esfera_crear(o, 1, c, 0.2f, 0.8f)))
        return 1;
    esferas.v = NULL;
    return 0;
}
