/*
 * setjmp.h - for the PNG writers (src/formats/png_write.c,
 * src/compare/diff_image.c) on wasm32-wasi, which clang 14 gives no
 * setjmp.  They call setjmp only to catch libpng's errors; the page's
 * libpng (png_shim.c) writes into memory and reports no error by jumping,
 * so setjmp returns 0 once, as it does on the path with no error, and
 * longjmp is never reached (it stops the module if it is).
 */
#ifndef RAYO_WEB_SETJMP_H
#define RAYO_WEB_SETJMP_H

typedef int jmp_buf[1];
#define setjmp(env) ((void)(env), 0)
_Noreturn void longjmp(jmp_buf env, int value);

#endif
