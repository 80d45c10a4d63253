/* Hostile: writes a file outside its folder (/tmp/rayo-hostile-written). */
#include <stdio.h>

int main(void)
{
    FILE *f = fopen("/tmp/rayo-hostile-written", "w");
    fprintf(stderr, "write %s\n", f != NULL ? "WORKED" : "refused");
    if (f != NULL) {
        fputs("pwned\n", f);
        fclose(f);
    }
    return 0;
}
