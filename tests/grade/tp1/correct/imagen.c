#include <stdint.h>
#include <stdlib.h>
#include "imagen.h"

struct imagen {
    color_t **lienzo;
    size_t ancho, alto;
};

imagen_t *imagen_crear(size_t ancho, size_t alto)
{
    size_t i;
    imagen_t *im = malloc(sizeof(imagen_t));
    if (im == NULL)
        return NULL;
    im->lienzo = malloc(alto * sizeof(color_t *));
    if (im->lienzo == NULL) {
        free(im);
        return NULL;
    }
    for (i = 0; i < alto; i++) {
        im->lienzo[i] = calloc(ancho, sizeof(color_t));
        if (im->lienzo[i] == NULL) {
            im->alto = i;
            imagen_destruir(im);
            return NULL;
        }
    }
    im->ancho = ancho;
    im->alto = alto;
    return im;
}

void imagen_destruir(imagen_t *im)
{
    size_t i;
    for (i = 0; i < im->alto; i++)
        free(im->lienzo[i]);
    free(im->lienzo);
    free(im);
}

void imagen_dimensiones(const imagen_t *im, size_t *ancho, size_t *alto)
{
    *ancho = im->ancho;
    *alto = im->alto;
}

bool imagen_set_pixel(imagen_t *im, size_t x, size_t y, color_t color)
{
    if (x >= im->ancho || y >= im->alto)
        return false;
    im->lienzo[y][x] = color;
    return true;
}

color_t imagen_get_pixel(const imagen_t *im, size_t x, size_t y)
{
    return im->lienzo[y][x];
}

void escribir_int16_little_endian(FILE *f, int16_t v)
{
    uint16_t u = (uint16_t)v;
    fputc(u & 0xff, f);
    fputc(u >> 8, f);
}

void escribir_int32_little_endian(FILE *f, int32_t v)
{
    uint32_t u = (uint32_t)v;
    int i;
    for (i = 0; i < 4; i++)
        fputc((u >> (8 * i)) & 0xff, f);
}

void escribir_PPM(const imagen_t *im, FILE *f)
{
    size_t x, y;
    fprintf(f, "P3\n%zu %zu\n255\n", im->ancho, im->alto);
    for (y = 0; y < im->alto; y++)
        for (x = 0; x < im->ancho; x++) {
            color_imprimir(im->lienzo[y][x], f);
            fputc('\n', f);
        }
}

void escribir_BMP(const imagen_t *im, FILE *f)
{
    size_t fila = (3 * im->ancho + 3) / 4 * 4;
    size_t x, y, k;
    fputc('B', f);
    fputc('M', f);
    escribir_int32_little_endian(f, (int32_t)(54 + im->alto * fila));
    escribir_int16_little_endian(f, 0);
    escribir_int16_little_endian(f, 0);
    escribir_int32_little_endian(f, 54);
    escribir_int32_little_endian(f, 40);
    escribir_int32_little_endian(f, (int32_t)im->ancho);
    escribir_int32_little_endian(f, (int32_t)im->alto);
    escribir_int16_little_endian(f, 1);
    escribir_int16_little_endian(f, 24);
    for (k = 0; k < 6; k++)
        escribir_int32_little_endian(f, 0);
    for (y = im->alto; y-- > 0;) {
        for (x = 0; x < im->ancho; x++) {
            color_t c = im->lienzo[y][x];
            fputc(color_byte(c.b), f);
            fputc(color_byte(c.g), f);
            fputc(color_byte(c.r), f);
        }
        for (k = 3 * im->ancho; k < fila; k++)
            fputc(0, f);
    }
}
