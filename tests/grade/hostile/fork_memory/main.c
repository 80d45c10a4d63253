/* Hostile: forks 20 children that take 700 MB each and touch it, so
   that a limit per process (700 MB fits under it) does not bound the
   whole: only a limit on the tree does. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#define CHILDREN 20
#define SIZE ((size_t)700 * 1000 * 1000)

int main(void)
{
    int i, made = 0;
    for (i = 0; i < CHILDREN; i++) {
        pid_t pid = fork();
        if (pid == 0) {
            char *block = malloc(SIZE);
            if (block != NULL)
                memset(block, 1, SIZE);
            for (;;)
                pause();
        }
        if (pid > 0)
            made++;
    }
    fprintf(stderr, "forked %d\n", made);
    while (wait(NULL) > 0)
        ;
    return 0;
}
