/* Hostile: leaves FIFOs and links where the grader might open files:
   an image-named FIFO, the old capture names, a link to /etc/passwd. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

int main(void)
{
    mkfifo("imagen.pbm", 0600);
    mkfifo("stdout", 0600);
    mkfifo("stderr", 0600);
    mkfifo("../stdout", 0600);
    mkfifo("../valgrind.log", 0600);
    if (symlink("/etc/passwd", "../harness.c") != 0)
        perror("symlink");
    return 0;
}
