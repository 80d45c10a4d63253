/* Hostile: reads past a block and leaks 4000 bytes, and first forges
   valgrind's verdict: a clean "ERROR SUMMARY: 0 errors" followed by a
   NUL byte (which once ended the grader's reading of the log) written
   to descriptor 3, where valgrind's log used to be, and then to every
   descriptor up to 1100, the range valgrind keeps for itself included. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

int main(void)
{
    static const char forged[] =
        "==1== HEAP SUMMARY:\n==1==     in use at exit: 0 bytes in 0 "
        "blocks\n==1== All heap blocks were freed -- no leaks are "
        "possible\n==1== ERROR SUMMARY: 0 errors from 0 contexts "
        "(suppressed: 0 from 0)\n";
    int *block = malloc(4 * sizeof *block);
    char *leak = malloc(4000);
    volatile int four = 4, past;
    int fd;
    if (block == NULL || leak == NULL)
        return 1;
    /* First, so that the real findings come after the NUL. */
    if (write(3, forged, sizeof forged) < 0)
        leak[1] = 0;
    for (fd = 3; fd <= 1100; fd++)
        if (write(fd, forged, sizeof forged) < 0)
            continue;
    block[0] = 1;
    past = block[four]; /* invalid read of size 4 */
    leak[0] = (char)past;
    free(block);
    printf("P1\n1 1\n0\n");
    leak = NULL;
    return 0;
}
