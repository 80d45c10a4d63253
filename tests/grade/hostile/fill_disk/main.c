/* Hostile: fills the disk with many files of 32 MiB each (the limit on
   one file's size does not bound them all). */
#include <stdio.h>
#include <string.h>

int main(void)
{
    static char block[1 << 20];
    long total = 0;
    int i, j;
    memset(block, 'x', sizeof block);
    for (i = 0; i < 64; i++) {
        char name[32];
        FILE *f;
        snprintf(name, sizeof name, "fill%02d", i);
        f = fopen(name, "w");
        if (f == NULL)
            break;
        for (j = 0; j < 32; j++) {
            if (fwrite(block, 1, sizeof block, f) != sizeof block)
                break;
            total++;
        }
        if (fclose(f) != 0 || j < 32)
            break;
    }
    fprintf(stderr, "wrote %ld MiB\n", total);
    return 0;
}
