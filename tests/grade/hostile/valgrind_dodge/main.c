/* Hostile: leaks 1 MB and tries to hide it from valgrind: forges a clean
   summary into every descriptor it finds, and replaces valgrind.log
   with a link to /dev/null. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

int main(void)
{
    static const char forged[] =
        "==2== HEAP SUMMARY:\n==2== All heap blocks were freed -- no "
        "leaks are possible\n==2== LEAK SUMMARY:\n==2==    definitely "
        "lost: 0 bytes in 0 blocks\n==2== ERROR SUMMARY: 0 errors from 0 "
        "contexts (suppressed: 0 from 0)\n";
    char *leak = malloc(1000000);
    int fd;
    if (leak != NULL)
        leak[0] = 1;
    unlink("../valgrind.log");
    if (symlink("/dev/null", "../valgrind.log") != 0)
        unlink("valgrind.log");
    for (fd = 3; fd < 1024; fd++)
        if (write(fd, forged, strlen(forged)) < 0)
            continue;
    leak = NULL;
    return 0;
}
