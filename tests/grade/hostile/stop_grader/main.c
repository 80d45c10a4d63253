/* Hostile: stops its parent and every process it may signal, then runs
   past the time limit (12 s) and exits 0 hoping to be called fast. */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

int main(void)
{
    kill(getppid(), SIGSTOP);
    kill(-1, SIGSTOP);
    sleep(4);
    printf("P1\n640 480\n");
    return 0;
}
