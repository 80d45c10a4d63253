/* Hostile: includes a file outside the submission, hoping the compiler
   quotes it in its errors. */
#include "/tmp/rayo-hostile-secret"

int main(void)
{
    return 0;
}
