/*
 * huge_pages.h - asks the system to back a large array with huge pages
 * (2 MiB on x86-64) where it allows them on request (Linux's transparent
 * huge pages set to "madvise"): a million-triangle scene's arrays are
 * otherwise first written a 4 KiB page at a time, each a fault of about
 * 2 us here (docs/performance.md).  Advice only: nothing changes but the
 * cost of first touching the memory, and where the call or the system
 * does not support it nothing happens at all.  Private to the library.
 */
#ifndef RAYO_HUGE_PAGES_H
#define RAYO_HUGE_PAGES_H

#include <stddef.h>

/* Advises huge pages for the whole 2 MiB blocks within [p, p + bytes),
 * when bytes is large enough to hold some; p may be NULL. */
void rayo_huge_pages(void *p, size_t bytes);

#endif
