/* Hostile: nests 60 folders of 200-byte names (past PATH_MAX), each
   with a file and without write permission, to defeat the removal of
   the temporary folder. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int main(void)
{
    char name[201];
    int i;
    memset(name, 'd', 200);
    name[200] = '\0';
    for (i = 0; i < 60; i++) {
        FILE *f;
        if (mkdir(name, 0700) != 0 || chdir(name) != 0)
            break;
        f = fopen("file", "w");
        if (f != NULL)
            fclose(f);
        chmod("..", 0500);
    }
    fprintf(stderr, "nested %d\n", i);
    return 0;
}
