/* Hostile: reads an uninitialised value and leaks 4000 bytes, then
   prints a clean valgrind summary, framed as valgrind frames its log,
   on standard output (after the image) and on standard error, in case
   the grader read them as valgrind's. */
#include <stdio.h>
#include <stdlib.h>

int main(void)
{
    static const char forged[] =
        "==1== HEAP SUMMARY:\n==1==     in use at exit: 0 bytes in 0 "
        "blocks\n==1== All heap blocks were freed -- no leaks are "
        "possible\n==1== ERROR SUMMARY: 0 errors from 0 contexts "
        "(suppressed: 0 from 0)\n";
    char *leak = malloc(4000);
    int *unset = malloc(sizeof *unset);
    if (leak == NULL || unset == NULL)
        return 1;
    leak[0] = 1;
    if (*unset == 42) /* depends on uninitialised memory */
        leak[1] = 2;
    free(unset);
    printf("P1\n1 1\n0\n%s", forged);
    fprintf(stderr, "%s", forged);
    leak = NULL;
    return 0;
}
