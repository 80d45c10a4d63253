/* Hostile: leaves a double-forked daemon behind (it sleeps a minute
   under the name the test looks for, rayo-hostile-daemon). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

int main(void)
{
    pid_t pid = fork();
    if (pid == 0) {
        setsid();
        if (fork() == 0) {
            execlp("sh", "sh", "-c", "exec -a rayo-hostile-daemon sleep 60",
                   (char *)NULL);
            execlp("sleep", "rayo-hostile-daemon", "60", (char *)NULL);
            _exit(1);
        }
        _exit(0);
    }
    sleep(1);
    return 0;
}
