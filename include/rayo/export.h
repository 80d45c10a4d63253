/*
 * export.h - RAYO_API, the mark on every function the library exports.
 *
 * The library is compiled with hidden visibility (-fvisibility=hidden),
 * so only what a public header declares with RAYO_API is part of the
 * shared library's interface; the helpers one source file shares with
 * another stay inside.  tests/cli/exports.t compares the shared
 * library's exported symbols with the headers' declarations, both ways.
 *
 * Not a portability layer: it only knows GCC-style visibility and is
 * empty elsewhere.  Valid C99, like every public header.
 */
#ifndef RAYO_EXPORT_H
#define RAYO_EXPORT_H

#if defined(__GNUC__) || defined(__clang__)
#define RAYO_API __attribute__((visibility("default")))
#else
#define RAYO_API
#endif

#endif
