/*
 * main.c - a student's solution to Ejercicio obligatorio 1, written only
 * from the assignment's text: it declares nothing of rayo's but the
 * assignment's header, uses the three functions, and prints the image as
 * plain PBM, one pixel per line, rows from the top (y from ALTO/2 down).
 *
 * tests/cli/student.t compiles it with the course's flags
 * (-std=c99 -Wall -Werror -pedantic), links it to librayo, and checks
 * that its image equals rayo's, pixel for pixel.
 */
#include <math.h>
#include <stdio.h>

#include <rayo/ejercicio1.h>

#define PI 3.14159265358979323846

int main(void)
{
    float z = ANCHO / (2 * tan(FOV * PI / 180 / 2));
    int x, y;

    printf("P1\n%d %d\n", ANCHO, ALTO);
    for (y = ALTO / 2; y > -ALTO / 2; y--) {
        for (x = -ANCHO / 2; x < ANCHO / 2; x++) {
            float n = norma(x, y, z);
            printf("%d\n", intersecta_esfera(x / n, y / n, z / n));
        }
    }
    return 0;
}
