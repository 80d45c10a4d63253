/* Hostile: forks without end (bounded at 2000 here, so that a test run
   as root, where RLIMIT_NPROC is not enforced, stays kind to the
   machine); every child waits for ever. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <unistd.h>

int main(void)
{
    int i, made = 0;
    for (i = 0; i < 2000; i++) {
        pid_t pid = fork();
        if (pid == 0) {
            for (;;)
                pause();
        }
        if (pid > 0)
            made++;
    }
    fprintf(stderr, "forked %d\n", made);
    for (;;)
        pause();
}
