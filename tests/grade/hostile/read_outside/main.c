/* Hostile: reads a file outside its folder (the path is given by the
   test in /tmp/rayo-hostile-secret) and prints it on standard error. */
#include <stdio.h>

int main(void)
{
    char line[256];
    FILE *f = fopen("/tmp/rayo-hostile-secret", "r");
    if (f != NULL && fgets(line, sizeof line, f) != NULL)
        fprintf(stderr, "LEAKED %s", line);
    else
        fprintf(stderr, "could not read the secret\n");
    if (f != NULL)
        fclose(f);
    f = fopen("/etc/shadow", "r");
    fprintf(stderr, "shadow %s\n", f != NULL ? "READABLE" : "unreadable");
    if (f != NULL)
        fclose(f);
    return 0;
}
