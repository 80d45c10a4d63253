/*
 * real_error.c - a submission with a real error (an undeclared
 * identifier) before a warning that -Werror makes fatal (an unused
 * variable): the real error is the one to fix, for rayo's grade tests
 * (tests/cli/grade_fixes.t).
 */
#include <stdio.h>

int main(void)
{
    int sin_usar;
    printf("P1\n%d 480\n", ancho);
    return 0;
}
