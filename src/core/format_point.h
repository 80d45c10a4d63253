/*
 * format_point.h - inside the library: vsnprintf with another decimal
 * separator, for messages in a language that writes 0,5 (status.c).
 * Not for use outside src/.
 */
#ifndef RAYO_FORMAT_POINT_H
#define RAYO_FORMAT_POINT_H

#include <stdarg.h>
#include <stddef.h>

/*
 * What vsnprintf(out, room, format, args) writes, except that the
 * decimal separator of each floating-point conversion (%g, %f, %e, %a)
 * is point.  Numbered arguments (%2$s, %1$.*3$s) are followed as printf
 * follows them.  A format it cannot take apart (%n, %ls, more than 32
 * arguments, numbered and unnumbered conversions mixed) is written by
 * vsnprintf as it is.  out is always terminated when room > 0.
 */
void rayo_format_point(char *out, size_t room, char point,
                       const char *format, va_list args)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 4, 0)))
#endif
    ;

#endif
