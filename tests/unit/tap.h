/*
 * tap.h - a minimal Test Anything Protocol producer for the C unit tests.
 *
 * Each test program prints "ok N - name" or "not ok N - name" lines and a
 * final plan; prove (run by `make check`) reads them.  Failures print the
 * expected and actual values as TAP diagnostics ("# ...").
 */
#ifndef RAYO_TAP_H
#define RAYO_TAP_H

#include <stdio.h>
#include <string.h>

static int tap_count;
static int tap_failed;

static inline int tap_ok(int pass, const char *name)
{
    tap_count++;
    if (!pass)
        tap_failed++;
    printf("%sok %d - %s\n", pass ? "" : "not ", tap_count, name);
    fflush(stdout);
    return pass;
}

#define ok(cond, ...)                                                        \
    do {                                                                     \
        char tap_name_[256];                                                 \
        snprintf(tap_name_, sizeof tap_name_, __VA_ARGS__);                  \
        tap_ok((cond) != 0, tap_name_);                                      \
    } while (0)

#define is_int(got, want, ...)                                               \
    do {                                                                     \
        long long tap_g_ = (long long)(got), tap_w_ = (long long)(want);     \
        char tap_name_[256];                                                 \
        snprintf(tap_name_, sizeof tap_name_, __VA_ARGS__);                  \
        if (!tap_ok(tap_g_ == tap_w_, tap_name_))                            \
            printf("#   got %lld, expected %lld\n", tap_g_, tap_w_);         \
    } while (0)

#define is_double(got, want, tolerance, ...)                                 \
    do {                                                                     \
        double tap_g_ = (double)(got), tap_w_ = (double)(want);              \
        double tap_d_ = tap_g_ > tap_w_ ? tap_g_ - tap_w_ : tap_w_ - tap_g_; \
        char tap_name_[256];                                                 \
        snprintf(tap_name_, sizeof tap_name_, __VA_ARGS__);                  \
        if (!tap_ok(tap_d_ <= (tolerance), tap_name_))                       \
            printf("#   got %.17g, expected %.17g (tolerance %g)\n", tap_g_, \
                   tap_w_, (double)(tolerance));                             \
    } while (0)

#define is_string(got, want, ...)                                            \
    do {                                                                     \
        const char *tap_g_ = (got), *tap_w_ = (want);                        \
        char tap_name_[256];                                                 \
        snprintf(tap_name_, sizeof tap_name_, __VA_ARGS__);                  \
        if (!tap_ok(tap_g_ && tap_w_ && strcmp(tap_g_, tap_w_) == 0,         \
                    tap_name_))                                              \
            printf("#   got '%s', expected '%s'\n", tap_g_ ? tap_g_ : "(null)", \
                   tap_w_ ? tap_w_ : "(null)");                              \
    } while (0)

/* Prints the plan; use as `return tap_done();` at the end of main. */
static inline int tap_done(void)
{
    printf("1..%d\n", tap_count);
    return tap_failed ? 1 : 0;
}

#endif
