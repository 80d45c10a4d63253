/*
 * leak_lights.c - destroys the spheres but never the lights: the lights
 * made by luz_crear leak.
 */
#include "escena.c"

int main(void)
{
    arreglo_t esferas = {NULL, 0}, luces = {NULL, 0};
    size_t i;
    vector_t o = {0, 0, 1};
    color_t c = {1, 1, 1};
    if (!arreglo_agregar(&esferas, esfera_crear(o, 1, c, 0.2f, 0.8f)) ||
        !arreglo_agregar(&luces, luz_crear(o, c, true)))
        return 1;
    for (i = 0; i < esferas.n; i++)
        esfera_destruir(esferas.v[i]);
    free(esferas.v);
    free(luces.v);
    return 0;
}
