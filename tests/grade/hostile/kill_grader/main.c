/* Hostile: kills its parent and every process it may signal. */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <unistd.h>

int main(void)
{
    kill(getppid(), SIGKILL);
    kill(-1, SIGKILL);
    fprintf(stderr, "still here\n");
    return 0;
}
