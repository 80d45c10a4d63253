#include "color.h"

color_t color_crear(float r, float g, float b)
{
    color_t c;
    c.r = r;
    c.g = g;
    c.b = b;
    return c;
}

/* c + p m */
color_t color_sumar(color_t c, color_t m, float p)
{
    return color_crear(c.r + p * m.r, c.g + p * m.g, c.b + p * m.b);
}

color_t color_absorber(color_t b, color_t c)
{
    return color_crear(b.r * c.r, b.g * c.g, b.b * c.b);
}

unsigned char color_byte(float c)
{
    if (c > 1)
        return 255;
    if (c < 0)
        return 0;
    return (unsigned char)(255 * c);
}

void color_imprimir(color_t c, FILE *f)
{
    fprintf(f, "%d %d %d", color_byte(c.r), color_byte(c.g), color_byte(c.b));
}
