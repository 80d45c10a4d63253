/* Hostile: includes /dev/zero, an endless stream of NUL bytes (the
   compiler, unbounded, grows until the machine's memory is gone). */
#include "/dev/zero"

int main(void)
{
    return 0;
}
