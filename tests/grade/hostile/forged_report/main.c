/* Hostile: forges the text report on standard error: a carriage return
   and escape sequences that would paint "PASS: 6 of 6" over the real
   lines, and a line a megabyte long. */
#include <stdio.h>

int main(void)
{
    long i;
    fprintf(stderr, "\r\033[2K\033[1A\033[2KPASS: 6 of 6 criteria passed\n");
    for (i = 0; i < 1000000; i++)
        fputc('A', stderr);
    fputc('\n', stderr);
    return 1;
}
