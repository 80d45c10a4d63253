/*
 * plural.c - a catalog's plural rule, evaluated: the expression after
 * "plural=" in a PO header's Plural-Forms, which GNU gettext writes in
 * C's syntax (n, whole numbers, ! * / % + - < > <= >= == != && || ?:
 * and parentheses).
 *
 * Read and evaluated in one pass, by recursive descent with C's
 * precedence; both arms of ?: are evaluated (nothing has side effects)
 * and division by zero gives 0.  It exists so that adding a language
 * with other plural forms is adding its PO file; it is not a general
 * expression evaluator.
 */
#include "catalog.h"

#include <ctype.h>

typedef struct parser {
    const char *p, *end;
    unsigned long n;
    int failed;
    int depth;
} parser;

static unsigned long ternary(parser *ps);

static void skip_space(parser *ps)
{
    while (ps->p < ps->end && isspace((unsigned char)*ps->p))
        ps->p++;
}

/* Consumes the operator text when it comes next (and is not the start
   of a longer one named in `not_before`). */
static int accept(parser *ps, const char *op, char not_before)
{
    const char *q;
    skip_space(ps);
    q = ps->p;
    while (*op != '\0') {
        if (q >= ps->end || *q != *op)
            return 0;
        q++;
        op++;
    }
    if (not_before != '\0' && q < ps->end && *q == not_before)
        return 0;
    ps->p = q;
    return 1;
}

static unsigned long primary(parser *ps)
{
    unsigned long v = 0;
    skip_space(ps);
    if (++ps->depth > 64) {
        ps->failed = 1;
        return 0;
    }
    if (accept(ps, "!", '=')) {
        v = !primary(ps);
    } else if (accept(ps, "(", 0)) {
        v = ternary(ps);
        if (!accept(ps, ")", 0))
            ps->failed = 1;
    } else if (ps->p < ps->end && *ps->p == 'n') {
        ps->p++;
        v = ps->n;
    } else if (ps->p < ps->end && isdigit((unsigned char)*ps->p)) {
        while (ps->p < ps->end && isdigit((unsigned char)*ps->p))
            v = v * 10 + (unsigned long)(*ps->p++ - '0');
    } else {
        ps->failed = 1;
    }
    ps->depth--;
    return v;
}

static unsigned long product(parser *ps)
{
    unsigned long v = primary(ps);
    for (;;) {
        if (accept(ps, "*", 0)) {
            v *= primary(ps);
        } else if (accept(ps, "/", 0)) {
            unsigned long d = primary(ps);
            v = d ? v / d : 0;
        } else if (accept(ps, "%", 0)) {
            unsigned long d = primary(ps);
            v = d ? v % d : 0;
        } else {
            return v;
        }
    }
}

static unsigned long sum(parser *ps)
{
    unsigned long v = product(ps);
    for (;;) {
        if (accept(ps, "+", 0))
            v += product(ps);
        else if (accept(ps, "-", 0))
            v -= product(ps);
        else
            return v;
    }
}

static unsigned long relation(parser *ps)
{
    unsigned long v = sum(ps);
    for (;;) {
        if (accept(ps, "<=", 0))
            v = v <= sum(ps);
        else if (accept(ps, ">=", 0))
            v = v >= sum(ps);
        else if (accept(ps, "<", 0))
            v = v < sum(ps);
        else if (accept(ps, ">", 0))
            v = v > sum(ps);
        else
            return v;
    }
}

static unsigned long equality(parser *ps)
{
    unsigned long v = relation(ps);
    for (;;) {
        if (accept(ps, "==", 0))
            v = v == relation(ps);
        else if (accept(ps, "!=", 0))
            v = v != relation(ps);
        else
            return v;
    }
}

static unsigned long conjunction(parser *ps)
{
    unsigned long v = equality(ps);
    while (accept(ps, "&&", 0)) {
        unsigned long w = equality(ps);
        v = v && w;
    }
    return v;
}

static unsigned long disjunction(parser *ps)
{
    unsigned long v = conjunction(ps);
    while (accept(ps, "||", 0)) {
        unsigned long w = conjunction(ps);
        v = v || w;
    }
    return v;
}

static unsigned long ternary(parser *ps)
{
    unsigned long condition = disjunction(ps), yes, no;
    if (!accept(ps, "?", 0))
        return condition;
    yes = ternary(ps);
    if (!accept(ps, ":", 0)) {
        ps->failed = 1;
        return 0;
    }
    no = ternary(ps);
    return condition ? yes : no;
}

long rayo_plural_form(const char *expression, size_t length, unsigned long n)
{
    parser ps;
    unsigned long v;
    ps.p = expression;
    ps.end = expression + length;
    ps.n = n;
    ps.failed = 0;
    ps.depth = 0;
    v = ternary(&ps);
    skip_space(&ps);
    /* a trailing ';' ends the expression in the header */
    if (ps.failed || (ps.p < ps.end && *ps.p != ';') || v > 1000)
        return -1;
    return (long)v;
}
