/* Hostile: connects to a listener on 127.0.0.1 (the port is in
   /tmp/rayo-hostile-port; the test also passes it as the default). */
#define _POSIX_C_SOURCE 200809L
#include <arpa/inet.h>
#include <netinet/in.h>
#include <stdio.h>
#include <string.h>
#include <sys/socket.h>
#include <unistd.h>

int main(void)
{
    struct sockaddr_in to;
    int port = 0, s = socket(AF_INET, SOCK_STREAM, 0);
    FILE *f = fopen("/tmp/rayo-hostile-port", "r");
    if (f != NULL) {
        if (fscanf(f, "%d", &port) != 1)
            port = 0;
        fclose(f);
    }
    if (port == 0)
        port = 47321;
    memset(&to, 0, sizeof to);
    to.sin_family = AF_INET;
    to.sin_port = htons((unsigned short)port);
    to.sin_addr.s_addr = htonl(0x7f000001);
    if (s >= 0 && connect(s, (struct sockaddr *)&to, sizeof to) == 0) {
        const char hello[] = "CONNECTED\n";
        if (write(s, hello, sizeof hello - 1) < 0)
            perror("write");
        fprintf(stderr, "connect WORKED\n");
    } else
        fprintf(stderr, "connect refused\n");
    return 0;
}
