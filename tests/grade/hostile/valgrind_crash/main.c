/* Hostile: leaks 4000 bytes, then opens every descriptor up to 1100 by
   its /proc/self/fd name and writes a byte into it: under valgrind that
   reaches valgrind's own descriptors (which the program cannot use by
   number) and stops valgrind on an internal error before its summary,
   once reported as "valgrind did not run to the end" and skipped. */
#define _POSIX_C_SOURCE 200809L
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

int main(void)
{
    char path[64];
    char *leak = malloc(4000);
    int fd;
    signal(SIGPIPE, SIG_IGN);
    if (leak != NULL)
        leak[0] = 1;
    for (fd = 3; fd <= 1100; fd++) {
        int reopened;
        snprintf(path, sizeof path, "/proc/self/fd/%d", fd);
        reopened = open(path, O_WRONLY | O_NONBLOCK);
        if (reopened >= 0) {
            if (write(reopened, "0", 1) < 0)
                fputs("refused\n", stderr);
            close(reopened);
        }
    }
    printf("P1\n1 1\n0\n");
    leak = NULL;
    return 0;
}
