/* Hostile: looks for another process's environment in /proc (the
   grader's, holding RAYO_HOSTILE_MARK set by the test). */
#include <dirent.h>
#include <stdio.h>
#include <string.h>

int main(void)
{
    DIR *d = opendir("/proc");
    struct dirent *e;
    int seen = 0;
    while (d != NULL && (e = readdir(d)) != NULL) {
        char path[300], buffer[65536];
        FILE *f;
        size_t n, i;
        if (e->d_name[0] < '0' || e->d_name[0] > '9')
            continue;
        seen++;
        snprintf(path, sizeof path, "/proc/%s/environ", e->d_name);
        f = fopen(path, "r");
        if (f == NULL)
            continue;
        n = fread(buffer, 1, sizeof buffer - 1, f);
        fclose(f);
        for (i = 0; i < n; i++)
            if (buffer[i] == '\0')
                buffer[i] = '\n';
        buffer[n] = '\0';
        if (strstr(buffer, "RAYO_HOSTILE_MARK=") != NULL)
            fprintf(stderr, "LEAKED the environment of %s\n", e->d_name);
    }
    if (d != NULL)
        closedir(d);
    fprintf(stderr, "processes seen: %d\n", seen);
    return 0;
}
