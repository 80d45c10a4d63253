/*
 * t_decimal.c - the decimal number reader (src/core/decimal.c)
 * against strtod.
 *
 * Every word is read twice, by the fast path and by the strtod path, and
 * both must agree on whether it is a number and, when it is, on the
 * double to the last bit.  Words: the field's kind (%.17g of random
 * doubles), every precision from 1 to 21 digits, random digit strings
 * with random exponents, exact halfway cases between two doubles (ties
 * to even), the edges of the table, subnormals, -0, and malformed words.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

#include "../../src/core/decimal.h"

static unsigned long mismatches, checked, fast_numbers;

static uint64_t next64(uint64_t *state)
{
    /* splitmix64 */
    uint64_t z = (*state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

/* Both readings of one word; 1 when they agree. */
static int same(const char *word)
{
    double fast = 0.0, slow = 0.0;
    size_t n = strlen(word);
    int a = decimal_read(word, n, &fast);
    int b = decimal_read_strtod(word, n, &slow);
    checked++;
    if (a == b && (!a || memcmp(&fast, &slow, sizeof fast) == 0)) {
        fast_numbers += (unsigned long)a;
        return 1;
    }
    if (mismatches++ < 10)
        printf("# '%s': fast %d %.17g, strtod %d %.17g\n", word, a, fast, b,
               slow);
    return 0;
}

static int all_same(const char *const *words, size_t count)
{
    size_t i;
    int good = 1;
    for (i = 0; i < count; i++)
        good &= same(words[i]);
    return good;
}

static double random_double(uint64_t *state)
{
    uint64_t bits;
    double d;
    do {
        bits = next64(state);
        memcpy(&d, &bits, sizeof d);
    } while (!isfinite(d));
    return d;
}

int main(void)
{
    static const char *const edges[] = {
        "0", "-0", "+0", "0.0", "-0.0", "0e0", "-0e-999", "0e99999999",
        ".5", "-.5", "5.", "+5.", "00012", "0.000", "1", "-1",
        "9007199254740993",  /* 2^53 + 1: halfway, to even (2^53) */
        "9007199254740995",  /* 2^53 + 3: halfway, to even (2^53 + 4) */
        "9007199254740993.0", "900719925474099.3e1",
        "9007199254740992.5", "18014398509481985", "18014398509481987",
        "4503599627370497.5", "1.7976931348623157e308", "1.7976931348623159e308",
        "2.2250738585072011e-308", "2.2250738585072014e-308",
        "4.9406564584124654e-324", "5e-324", "2e-324", "1e-400", "1e309",
        "1e-100", "1e-101", "1e50", "1e51", "9999999999999999999e50",
        "9999999999999999999e-100", "1.0000000000000000000", "12345678901234567890",
        "1234567890123456789", "0.1", "0.2", "0.3", "1e23", "8.589973e9",
        "1e12", "-1e12", "1000000000000.0001", "7.2057594037927933e16",
        "0.000000000000000000000000000001", "3.0517578125e-05",
        "2.9802322387695312e-08", "123456789012345678e-5", "1e-27", "1e-28",
        "1e55", "1e56", "4.35679e-10", "00000000000000000000001",
        "0000000000000000000000.1234567890123456789",
        "0.00000000000000000000000001234567890123456789",
        "0.000000000000000000000000012345678901234567891",
        "12345678.12345678", "1234567812345678", "99999999.99999999",
        "-00000000.00000000e5", "12345678901234567.8", "1234567890123456789.0",
        "123456789012345678.9e-3", "9999999999999999999", "18446744073709551616",
        "18446744073709551615", "10000000000000000000", "1.0e+0022",
        "12345678e", "12345678.", ".12345678", "1234567_", "1234567/",
        "12345678:", "-12345678.87654321e-12",
        /* not numbers (or not wholly): */
        "", ".", "+", "-", "e5", "1e", "1e+", "1e-", "--1", "+-1", "1-",
        "1..2", "1.2.3", "1e5e5", "0x10", "inf", "nan", "-inf", "1,5",
        "1 2", "1E+", "E", ".e1", "+.", "1.e", "123456789012345678901234567890123456789012345678901234567890123456789",
    };
    char word[80];
    uint64_t state = 2026;
    int i, good;

    ok(all_same(edges, sizeof edges / sizeof edges[0]),
       "edge cases: %lu words", (unsigned long)(sizeof edges /
                                               sizeof edges[0]));
    {
        double v = 0;
        ok(decimal_read("-0", 2, &v) && signbit(v) && v == 0.0,
           "-0 reads as negative zero");
        ok(decimal_read("9007199254740993", 16, &v) &&
               v == 9007199254740992.0,
           "2^53 + 1 rounds to even");
        ok(decimal_read("0.1", 3, &v) && v == 0.1, "0.1");
        ok(!decimal_read("1e309", 5, &v), "1e309 overflows: refused");
    }

    good = 1;
    for (i = 0; i < 200000; i++) {
        double d = random_double(&state);
        snprintf(word, sizeof word, "%.17g", d);
        good &= same(word);
        snprintf(word, sizeof word, "%.*g", 1 + (int)(next64(&state) % 21),
                 d);
        good &= same(word);
    }
    ok(good, "random doubles at 17 and 1-21 digits");

    good = 1;
    for (i = 0; i < 200000; i++) {
        /* the field's kind: scene-sized values at 15-17 digits */
        double d = ((double)(next64(&state) >> 11) / 9007199254740992.0 -
                    0.5) * pow(10.0, (double)(next64(&state) % 8));
        snprintf(word, sizeof word, "%.*g", 15 + (int)(next64(&state) % 3),
                 d);
        good &= same(word);
        snprintf(word, sizeof word, "%.17f", d);
        good &= same(word);
    }
    ok(good, "scene-sized values at 15-17 digits, %%g and %%f");

    good = 1;
    for (i = 0; i < 200000; i++) {
        int digits = 1 + (int)(next64(&state) % 22), k, n = 0;
        int point = (int)(next64(&state) % (unsigned)(digits + 2));
        if (next64(&state) & 1)
            word[n++] = '-';
        for (k = 0; k < digits; k++) {
            if (k == point)
                word[n++] = '.';
            word[n++] = (char)('0' + next64(&state) % 10);
        }
        if (next64(&state) % 3)
            n += snprintf(word + n, sizeof word - (size_t)n, "e%d",
                          (int)(next64(&state) % 260) - 130);
        word[n] = '\0';
        good &= same(word);
    }
    ok(good, "random digit strings with random exponents");

    good = 1;
    for (i = 0; i < 100000; i++) {
        /* exact halfway points m * 2^e + 2^(e-1) between two doubles */
        uint64_t m = (next64(&state) >> 11) | ((uint64_t)1 << 52);
        int e = (int)(next64(&state) % 40) - 20;
        long double half = ((long double)m + 0.5L) * powl(2.0L, e);
        snprintf(word, sizeof word, "%.25Lg", half);
        good &= same(word);
        snprintf(word, sizeof word, "%.19Lg", half);
        good &= same(word);
    }
    ok(good, "halfway points and their neighbours");

    ok(mismatches == 0, "%lu words, %lu numbers, no mismatch", checked,
       fast_numbers);
    return tap_done();
}
