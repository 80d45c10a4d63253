/*
 * huge_pages.c - transparent huge pages asked for a large array
 * (huge_pages.h).  madvise only: the memory stays malloc's, its contents
 * untouched.  Without MADV_HUGEPAGE (not Linux, WebAssembly) a no-op.
 */
#define _DEFAULT_SOURCE /* madvise, MADV_HUGEPAGE */

#include "huge_pages.h"

#include <stdint.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#define HUGE_PAGE ((uintptr_t)2 << 20)

void rayo_huge_pages(void *p, size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    uintptr_t begin = (uintptr_t)p, end = begin + bytes;
    begin = (begin + HUGE_PAGE - 1) & ~(HUGE_PAGE - 1);
    end &= ~(HUGE_PAGE - 1);
    if (p != NULL && end > begin)
        (void)madvise((void *)begin, (size_t)(end - begin), MADV_HUGEPAGE);
#else
    (void)p;
    (void)bytes;
#endif
}
