/*
 * web.h - what the page's WebAssembly glue shares between its files:
 * bytes the library wrote into memory (output_memory.c), and the image
 * the page holds (web_api.c).  Not part of the library's interface: the
 * script calls the functions web_api.c exports (docs/web.md lists them).
 */
#ifndef RAYO_WEB_H
#define RAYO_WEB_H

#include <stddef.h>

#include "rayo/output.h"
#include "rayo/status.h"

#define WEB_EXPORT(name) __attribute__((export_name(name)))

typedef struct web_bytes {
    unsigned char *data; /* malloc'd; NULL when empty */
    size_t size;
} web_bytes;

/* An output into memory: on commit, its bytes go to *result (which owns
 * them from then on, replacing what it held). */
rayo_status web_output_open(rayo_output **out, const char *name,
                            web_bytes *result, rayo_error *err);

#endif
