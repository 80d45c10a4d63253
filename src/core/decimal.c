/*
 * decimal.c - decimal numbers read exactly as strtod reads them
 * (decimal.h), fast.
 *
 * Why: glibc's strtod goes to multi-precision arithmetic for numbers of 16
 * or 17 significant digits, which large scene files are full of
 * (docs/performance.md).  A plain decimal word with at most 19 significant
 * digits and an exponent in the table's range is converted by the
 * Eisel-Lemire algorithm; anything it does not claim goes to strtod, so
 * the result is strtod's correctly rounded value in every case, and the
 * words accepted and refused are exactly strtod's.  tests/unit/
 * t_decimal.c compares both on hundreds of thousands of words.
 */
#include "decimal.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/*
 * Why exact: a word that is a plain decimal number (sign, digits, one
 * '.', exponent) with at most 19 significant digits w and a decimal
 * exponent q in [POW5_LO, POW5_HI] is converted by the Eisel-Lemire
 * algorithm (D. Lemire, "Number parsing at a gigabyte per second",
 * Software: Practice and Experience 51, 2021, sections 5 and 6; the
 * algorithm of Go's, Rust's and C++'s fast_float readers): w, shifted so
 * its top bit is set, is multiplied by a 128-bit approximation of 5^q, and
 * the top 54 bits of the product give the correctly rounded double unless
 * the product's low bits leave the rounding undecided.  Those cases are
 * detected (the second product's all-ones low word, outside q in [-27, 55]
 * where the table is exact; a tie, which is only possible for q in
 * [-4, 23], settled to even) and anything else the algorithm does not
 * claim - more digits, exponents outside the table, underflow to
 * subnormals - goes to strtod.  The fast path only answers for words that
 * fully match the grammar above, and those strtod reads whole too.
 */

int decimal_read_strtod(const char *text, size_t length, double *value)
{
    char buffer[64];
    char *end;
    if (length == 0 || length >= sizeof buffer)
        return 0;
    memcpy(buffer, text, length);
    buffer[length] = '\0';
    if (strspn(buffer, "0123456789+-.eE") < length)
        return 0; /* decimal only: no hex, inf or nan spellings */
    *value = strtod(buffer, &end);
    return *end == '\0' && end != buffer && isfinite(*value);
}

/* 5^q for q in [POW5_LO, POW5_HI], 128 bits with the top bit set: {high
 * word, low word}.  For q >= 0, 5^q shifted and truncated; for q < 0,
 * floor(2^b / 5^-q) + 1 with b = z + 127 (q >= -27) or 2z + 128, z the
 * bit length of 5^-q, truncated to 128 bits: Lemire's table, made by
 *   for q in range(-100, 51):
 *     if q >= 0: v = 5**q; shift v into [2**127, 2**128)
 *     else: p = 5**-q; z = p.bit_length()
 *           v = 2**(z+127 if q >= -27 else 2*z+128) // p + 1
 *           while v >= 2**128: v >>= 1 */
#define POW5_LO (-100)
#define POW5_HI 50
static const uint64_t pow5[POW5_HI - POW5_LO + 1][2] = {
#include "decimal_table.h"

};

/* The 128-bit product of a and b. */
static void multiply(uint64_t a, uint64_t b, uint64_t *high, uint64_t *low)
{
#if defined(__SIZEOF_INT128__) && (defined(__x86_64__) || defined(__aarch64__))
    __extension__ typedef unsigned __int128 u128;
    u128 p = (u128)a * b;
    *high = (uint64_t)(p >> 64);
    *low = (uint64_t)p;
#else
    uint64_t a0 = a & 0xffffffffu, a1 = a >> 32;
    uint64_t b0 = b & 0xffffffffu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t middle = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
    *low = (middle << 32) | (p00 & 0xffffffffu);
    *high = p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32);
#endif
}

/* w != 0 */
static int leading_zeros(uint64_t w)
{
#if defined(__GNUC__) || defined(__clang__)
    return __builtin_clzll(w);
#else
    int n = 0;
    while (!(w & 0x8000000000000000u)) {
        w <<= 1;
        n++;
    }
    return n;
#endif
}

/*
 * Eisel-Lemire: w * 10^q as a double into *value (w != 0, q in the
 * table), or 0 when the rounding cannot be settled here.
 */
static int eisel_lemire(uint64_t w, int q, int negative, double *value)
{
    uint64_t high, low, mantissa, bits;
    const uint64_t *p = pow5[q - POW5_LO];
    int lz = leading_zeros(w), upper, power2;
    w <<= lz;
    multiply(w, p[0], &high, &low);
    if ((high & 0x1ffu) == 0x1ffu) { /* 9 = 64 - (52 + 3) bits unsure */
        uint64_t high2, low2;
        multiply(w, p[1], &high2, &low2);
        low += high2;
        if (high2 > low)
            high++;
    }
    if (low == 0xffffffffffffffffu && (q < -27 || q > 55))
        return 0;
    upper = (int)(high >> 63);
    mantissa = high >> (upper + 9);
    /* floor(q log2(10)) + 63, exact over the table's range */
    power2 = (int)(((152170 + 65536) * q) >> 16) + 63 + upper - lz + 1023;
    if (power2 <= 0 || power2 >= 0x7ff - 1)
        return 0; /* subnormal or near overflow: strtod's business */
    if (low <= 1 && q >= -4 && q <= 23 && (mantissa & 3) == 1 &&
        (mantissa << (upper + 9)) == high)
        mantissa &= ~(uint64_t)1; /* exactly halfway: to even */
    mantissa += mantissa & 1;
    mantissa >>= 1;
    if (mantissa >= ((uint64_t)2 << 52)) {
        mantissa = (uint64_t)1 << 52;
        power2++;
    }
    mantissa &= ~((uint64_t)1 << 52);
    bits = mantissa | (uint64_t)power2 << 52 |
           (uint64_t)(negative ? 1 : 0) << 63;
    memcpy(value, &bits, sizeof *value);
    return 1;
}

#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
/* Eight digits at a time (the first byte the lowest): 1 and their value
 * when the eight bytes at p are all '0'-'9'.  Lemire's SWAR conversion:
 * pairs, then quads, then the eight, by multiplications. */
static int eight_digits(const char *p, uint64_t *value)
{
    uint64_t v;
    memcpy(&v, p, sizeof v);
    if ((((v + 0x4646464646464646u) | (v - 0x3030303030303030u)) &
         0x8080808080808080u) != 0)
        return 0;
    v -= 0x3030303030303030u;
    v = v * 10 + (v >> 8);
    v = (((v & 0x000000ff000000ffu) * 0x000f424000000064u) +
         (((v >> 16) & 0x000000ff000000ffu) * 0x0000271000000001u)) >>
        32;
    *value = (uint32_t)v;
    return 1;
}
#else
static int eight_digits(const char *p, uint64_t *value)
{
    (void)p;
    (void)value;
    return 0;
}
#endif

/* Digits from *p up to end into *w (w * 10 + digit each, modulo 2^64);
 * how many. */
static inline size_t read_digits(const char **p, const char *end,
                                 uint64_t *w)
{
    const char *s = *p;
    uint64_t eight;
    while (end - s >= 8 && eight_digits(s, &eight)) {
        *w = *w * 100000000u + eight;
        s += 8;
    }
    while (s < end && *s >= '0' && *s <= '9') {
        *w = *w * 10 + (uint64_t)(*s - '0');
        s++;
    }
    eight = (uint64_t)(s - *p);
    *p = s;
    return (size_t)eight;
}

/*
 * The fast path: 1 with *value when the word is [+-]digits[.digits]
 * [(e|E)[+-]digits] (at least one mantissa digit) with at most 19
 * significant digits and a decimal exponent inside the table; 0 when it
 * cannot tell (the word may still be a number).  w gathers every digit
 * modulo 2^64; leading zeros add nothing to it, so with at most 19
 * significant digits it is exact.
 */
static int read_fast(const char *s, size_t length, double *value)
{
    const char *end = s + length, *first;
    uint64_t w = 0;
    size_t digits, fraction = 0;
    int negative = 0;
    long exponent = 0;
    if (s < end && (*s == '+' || *s == '-'))
        negative = *s++ == '-';
    first = s;
    digits = read_digits(&s, end, &w);
    if (s < end && *s == '.') {
        s++;
        fraction = read_digits(&s, end, &w);
        digits += fraction;
    }
    if (digits == 0)
        return 0;
    if (digits > 19) {
        const char *z;
        size_t zeros = 0;
        for (z = first; z < s && (*z == '0' || *z == '.'); z++)
            zeros += *z == '0';
        if (digits - zeros > 19)
            return 0;
    }
    if (s < end && (*s == 'e' || *s == 'E')) {
        int exp_negative = 0, exp_digits = 0;
        s++;
        if (s < end && (*s == '+' || *s == '-'))
            exp_negative = *s++ == '-';
        for (; s < end && *s >= '0' && *s <= '9'; s++, exp_digits++)
            if (exponent < 100000)
                exponent = 10 * exponent + (*s - '0');
        if (exp_digits == 0)
            return 0;
        if (exp_negative)
            exponent = -exponent;
    }
    if (s != end)
        return 0;
    if (w == 0) {
        *value = negative ? -0.0 : 0.0;
        return 1;
    }
    exponent -= (long)fraction;
    if (exponent < POW5_LO || exponent > POW5_HI)
        return 0;
    return eisel_lemire(w, (int)exponent, negative, value);
}

int decimal_read(const char *text, size_t length, double *value)
{
    if (length == 0 || length >= 64)
        return 0;
    if (read_fast(text, length, value))
        return 1;
    return decimal_read_strtod(text, length, value);
}
