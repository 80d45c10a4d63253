/*
 * format_point.c - vsnprintf with another decimal separator: the
 * messages of rayo_error_set in a language that writes 0,5.
 *
 * printf writes the C locale's '.', and rayo never sets a locale (that
 * would change every number of the JSON, the CSV and the Netpbm headers,
 * in every thread).  So the format is taken apart here: its arguments
 * are fetched by the types its conversions name, each conversion is
 * printed on its own by snprintf, and the '.' a floating-point one
 * writes becomes the language's separator.  Not a printf of its own:
 * every digit is snprintf's; this only walks the format.
 */
#include "format_point.h"

#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#define FORMAT_ARGS 32

typedef enum arg_type {
    ARG_NONE = 0,
    ARG_INT,
    ARG_UINT,
    ARG_LONG,
    ARG_ULONG,
    ARG_LLONG,
    ARG_ULLONG,
    ARG_SIZE,
    ARG_INTMAX,
    ARG_UINTMAX,
    ARG_PTRDIFF,
    ARG_DOUBLE,
    ARG_LDOUBLE,
    ARG_STRING,
    ARG_POINTER
} arg_type;

typedef union arg_value {
    int i;
    unsigned u;
    long l;
    unsigned long ul;
    long long ll;
    unsigned long long ull;
    size_t z;
    intmax_t j;
    uintmax_t uj;
    ptrdiff_t t;
    double d;
    long double ld;
    const char *s;
    void *p;
} arg_value;

/* One conversion, from its '%' to its letter. */
typedef struct conversion {
    char flags[8];
    int width, width_arg;         /* -1: none, or not from an argument */
    int precision, precision_arg; /* precision -1: none */
    char length[3];
    char letter;
    int arg; /* the argument it prints */
} conversion;

/* The walk's state: numbered (%1$s) or in order, the next in order. */
typedef struct walk {
    int numbered; /* -1 not known yet, 0 in order, 1 numbered */
    int next;
} walk;

/* A decimal number at *p, or -1; *p moves past it. */
static int number(const char **p)
{
    long n = 0;
    if (**p < '0' || **p > '9')
        return -1;
    while (**p >= '0' && **p <= '9') {
        n = n * 10 + (**p - '0');
        if (n > INT_MAX / 10)
            return -1;
        (*p)++;
    }
    return (int)n;
}

/* The argument an item takes: its number ("3$") or the next in order. */
static int argument(const char **p, walk *w)
{
    const char *q = *p;
    int n = number(&q);
    int numbered = n > 0 && *q == '$';
    if (w->numbered >= 0 && w->numbered != numbered)
        return -1;
    w->numbered = numbered;
    if (!numbered)
        return w->next < FORMAT_ARGS ? w->next++ : -1;
    *p = q + 1;
    return n <= FORMAT_ARGS ? n - 1 : -1;
}

static arg_type integer_type(const char *length, int is_signed)
{
    if (strcmp(length, "l") == 0)
        return is_signed ? ARG_LONG : ARG_ULONG;
    if (strcmp(length, "ll") == 0)
        return is_signed ? ARG_LLONG : ARG_ULLONG;
    if (strcmp(length, "z") == 0)
        return ARG_SIZE;
    if (strcmp(length, "j") == 0)
        return is_signed ? ARG_INTMAX : ARG_UINTMAX;
    if (strcmp(length, "t") == 0)
        return ARG_PTRDIFF;
    return is_signed ? ARG_INT : ARG_UINT; /* none, h, hh: promoted */
}

/* Records that argument i has type t; 0 when i is out of range or an
   earlier conversion gave it another type. */
static int typed(arg_type *types, int i, arg_type t)
{
    if (i < 0 || i >= FORMAT_ARGS || (types[i] != ARG_NONE && types[i] != t))
        return 0;
    types[i] = t;
    return 1;
}

/* The conversion after a '%' at *p into c, its arguments' types into
   types; *p moves past its letter.  0 when it is not one to take apart. */
static int read_conversion(const char **p, walk *w, conversion *c,
                           arg_type *types)
{
    const char *q = *p;
    size_t nflags = 0, nlength = 0;
    const char *digits = q;
    arg_type t;
    memset(c, 0, sizeof *c);
    c->width = c->width_arg = c->precision = c->precision_arg = -1;
    /* "%3$..." names its argument first; "%3d" is a width. */
    if (number(&digits) > 0 && *digits == '$')
        c->arg = argument(&q, w);
    else
        c->arg = -2; /* taken in order after the width and precision */
    while (*q != '\0' && strchr("-+ #0", *q) != NULL && nflags < 6)
        c->flags[nflags++] = *q++;
    if (*q == '*') {
        q++;
        c->width_arg = argument(&q, w);
        if (!typed(types, c->width_arg, ARG_INT))
            return 0;
    } else if (*q >= '0' && *q <= '9') {
        c->width = number(&q);
        if (c->width < 0)
            return 0;
    }
    if (*q == '.') {
        q++;
        if (*q == '*') {
            q++;
            c->precision_arg = argument(&q, w);
            if (!typed(types, c->precision_arg, ARG_INT))
                return 0;
        } else {
            c->precision = *q >= '0' && *q <= '9' ? number(&q) : 0;
            if (c->precision < 0)
                return 0;
        }
    }
    while (*q != '\0' && strchr("hlLzjt", *q) != NULL && nlength < 2)
        c->length[nlength++] = *q++;
    c->letter = *q;
    if (c->letter == '\0')
        return 0;
    q++;
    if (c->arg == -2)
        c->arg = argument(&q, w);
    if (strchr("di", c->letter) != NULL)
        t = integer_type(c->length, 1);
    else if (strchr("ouxX", c->letter) != NULL)
        t = integer_type(c->length, 0);
    else if (strchr("fFeEgGaA", c->letter) != NULL)
        t = strcmp(c->length, "L") == 0 ? ARG_LDOUBLE : ARG_DOUBLE;
    else if (c->letter == 'c' && nlength == 0)
        t = ARG_INT;
    else if (c->letter == 's' && nlength == 0)
        t = ARG_STRING;
    else if (c->letter == 'p' && nlength == 0)
        t = ARG_POINTER;
    else
        return 0; /* %n, %ls, %lc, a letter printf does not know */
    *p = q;
    return typed(types, c->arg, t);
}

/* Every conversion of format read once: the arguments' types; 0 when
   the format is not one to take apart. */
static int read_types(const char *format, arg_type *types, int *count)
{
    walk w = {-1, 0};
    const char *p = format;
    int i;
    memset(types, 0, FORMAT_ARGS * sizeof *types);
    while ((p = strchr(p, '%')) != NULL) {
        conversion c;
        p++;
        if (*p == '%') {
            p++;
            continue;
        }
        if (!read_conversion(&p, &w, &c, types))
            return 0;
    }
    for (*count = FORMAT_ARGS; *count > 0 && types[*count - 1] == ARG_NONE;)
        (*count)--;
    for (i = 0; i < *count; i++)
        if (types[i] == ARG_NONE)
            return 0; /* printf cannot skip an argument either */
    return 1;
}

/* One conversion with its value, by snprintf, into out (room > 0).  spec
   is not a literal: spec_text wrote it from a conversion read_conversion
   took apart, whose argument's type is t, so the check is done there. */
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
#endif
static int print_one(char *out, size_t room, const char *spec, arg_type t,
                     const arg_value *v)
{
    switch (t) {
    case ARG_INT: return snprintf(out, room, spec, v->i);
    case ARG_UINT: return snprintf(out, room, spec, v->u);
    case ARG_LONG: return snprintf(out, room, spec, v->l);
    case ARG_ULONG: return snprintf(out, room, spec, v->ul);
    case ARG_LLONG: return snprintf(out, room, spec, v->ll);
    case ARG_ULLONG: return snprintf(out, room, spec, v->ull);
    case ARG_SIZE: return snprintf(out, room, spec, v->z);
    case ARG_INTMAX: return snprintf(out, room, spec, v->j);
    case ARG_UINTMAX: return snprintf(out, room, spec, v->uj);
    case ARG_PTRDIFF: return snprintf(out, room, spec, v->t);
    case ARG_DOUBLE: return snprintf(out, room, spec, v->d);
    case ARG_LDOUBLE: return snprintf(out, room, spec, v->ld);
    case ARG_STRING: return snprintf(out, room, spec, v->s);
    case ARG_POINTER: return snprintf(out, room, spec, v->p);
    case ARG_NONE: break;
    }
    return 0;
}
#if defined(__GNUC__) || defined(__clang__)
#pragma GCC diagnostic pop
#endif

/* The conversion c, its width and precision made literal, as a format
   for one argument in order ("%-12.3lu"). */
static void spec_text(const conversion *c, const arg_value *values,
                      char *spec, size_t room)
{
    int width = c->width_arg >= 0 ? values[c->width_arg].i : c->width;
    int precision =
        c->precision_arg >= 0 ? values[c->precision_arg].i : c->precision;
    char w[16] = "", pr[16] = "";
    if (width < 0 && c->width_arg >= 0 && width != INT_MIN) {
        width = -width; /* a negative width from an argument is a '-' flag */
        snprintf(w, sizeof w, "-%d", width);
    } else if (width >= 0) {
        snprintf(w, sizeof w, "%d", width);
    }
    if (precision >= 0)
        snprintf(pr, sizeof pr, ".%d", precision);
    snprintf(spec, room, "%%%s%s%s%s%c", c->flags, w, pr, c->length,
             c->letter);
}

void rayo_format_point(char *out, size_t room, char point,
                       const char *format, va_list args)
{
    arg_type types[FORMAT_ARGS];
    arg_value values[FORMAT_ARGS];
    walk w = {-1, 0};
    const char *p = format;
    size_t used = 0;
    int count, i;
    if (room == 0)
        return;
    if (!read_types(format, types, &count)) {
        vsnprintf(out, room, format, args);
        return;
    }
    for (i = 0; i < count; i++) {
        switch (types[i]) {
        case ARG_INT: values[i].i = va_arg(args, int); break;
        case ARG_UINT: values[i].u = va_arg(args, unsigned); break;
        case ARG_LONG: values[i].l = va_arg(args, long); break;
        case ARG_ULONG: values[i].ul = va_arg(args, unsigned long); break;
        case ARG_LLONG: values[i].ll = va_arg(args, long long); break;
        case ARG_ULLONG:
            values[i].ull = va_arg(args, unsigned long long);
            break;
        case ARG_SIZE: values[i].z = va_arg(args, size_t); break;
        case ARG_INTMAX: values[i].j = va_arg(args, intmax_t); break;
        case ARG_UINTMAX: values[i].uj = va_arg(args, uintmax_t); break;
        case ARG_PTRDIFF: values[i].t = va_arg(args, ptrdiff_t); break;
        case ARG_DOUBLE: values[i].d = va_arg(args, double); break;
        case ARG_LDOUBLE: values[i].ld = va_arg(args, long double); break;
        case ARG_STRING: values[i].s = va_arg(args, const char *); break;
        case ARG_POINTER: values[i].p = va_arg(args, void *); break;
        case ARG_NONE: break;
        }
    }
    while (*p != '\0' && used + 1 < room) {
        const char *percent = strchr(p, '%');
        size_t literal = percent ? (size_t)(percent - p) : strlen(p);
        conversion c;
        arg_type ignored[FORMAT_ARGS] = {ARG_NONE};
        char spec[64];
        int n;
        if (literal > room - 1 - used)
            literal = room - 1 - used;
        memcpy(out + used, p, literal);
        used += literal;
        p += literal;
        if (percent == NULL || p != percent)
            break;
        p++;
        if (*p == '%') {
            out[used++] = '%';
            p++;
            continue;
        }
        read_conversion(&p, &w, &c, ignored); /* read_types took it */
        spec_text(&c, values, spec, sizeof spec);
        n = print_one(out + used, room - used, spec, types[c.arg],
                      &values[c.arg]);
        if (n < 0)
            n = 0;
        if ((size_t)n > room - 1 - used)
            n = (int)(room - 1 - used);
        if (strchr("fFeEgGaA", c.letter) != NULL) {
            char *dot = memchr(out + used, '.', (size_t)n);
            if (dot != NULL)
                *dot = point;
        }
        used += (size_t)n;
    }
    out[used] = '\0';
}
