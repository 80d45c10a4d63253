/* Hostile: includes /dev/urandom, an endless stream of random bytes (the
   compiler, unbounded, reads until its time is up). */
#include "/dev/urandom"

int main(void)
{
    return 0;
}
