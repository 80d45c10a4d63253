/*
 * refusal.c - the promise every refusal keeps, checked by the fuzz
 * targets: a failing status comes with one non-empty line of message
 * (status.h).  Linked into every fuzz target and replay driver; not part
 * of the library.
 */
#define _POSIX_C_SOURCE 200809L

#include <stdlib.h>
#include <string.h>

#include "fuzz.h"

void fuzz_check_refusal(rayo_status status, const rayo_error *err)
{
    size_t length = strnlen(err->message, sizeof err->message);
    if (status == RAYO_OK || err->status != status)
        abort();
    if (length == 0 || length == sizeof err->message)
        abort();
    if (memchr(err->message, '\n', length) != NULL)
        abort();
}
