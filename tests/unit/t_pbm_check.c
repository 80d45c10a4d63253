/*
 * t_pbm_check.c - the strict plain PBM checker of rayo grade: each
 * deviation a student makes is found, explained with the right numbers
 * and positions, and the pixels are still recovered where they can be.
 *
 * The expected texts and positions are worked out by hand from the
 * inputs written here; a 4x2 exercise keeps them short.
 */
#include <stdlib.h>
#include <string.h>

#include "rayo/pbm_check.h"
#include "tap.h"

typedef struct outcome {
    rayo_grade_item item;
    rayo_image image;
    rayo_status status;
} outcome;

static void check(const char *text, uint32_t w, uint32_t h, outcome *o)
{
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    memset(o, 0, sizeof *o);
    o->status = rayo_pbm_check(text, strlen(text), w, h, &o->item, &o->image,
                               &err);
}

static void release(outcome *o)
{
    size_t i;
    for (i = 0; i < o->item.line_count; i++)
        free(o->item.lines[i]);
    free(o->item.lines);
    rayo_image_free(&o->image);
}

/* 1 when some reason line contains needle. */
static int says(const outcome *o, const char *needle)
{
    size_t i;
    for (i = 0; i < o->item.line_count; i++)
        if (strstr(o->item.lines[i], needle) != NULL)
            return 1;
    for (i = 0; i < o->item.line_count; i++)
        printf("#   line: %s\n", o->item.lines[i]);
    return 0;
}

/* The image's pixels as "0101/1010". */
static void bits(const rayo_image *image, char *out)
{
    uint32_t x, y;
    size_t n = 0;
    for (y = 0; y < image->info.height; y++) {
        if (y > 0)
            out[n++] = '/';
        for (x = 0; x < image->info.width; x++)
            out[n++] = rayo_bit_get(rayo_image_row(image, y), x) ? '1' : '0';
    }
    out[n] = '\0';
}

static void test_good(void)
{
    outcome o;
    char got[64];
    check("P1\n4 2\n0101\n1010\n", 4, 2, &o);
    is_int(o.status, RAYO_OK, "good: RAYO_OK");
    is_int(o.item.result, RAYO_GRADE_PASS, "good: passes");
    is_int(o.item.line_count, 1, "good: one line");
    is_string(o.item.lines[0], "plain PBM (P1), 4x2, 8 pixels",
              "good: says what it is");
    bits(&o.image, got);
    is_string(got, "0101/1010", "good: the pixels, 1 = black");
    release(&o);

    check("P1\n# hecho por mi\n4 2 01011010", 4, 2, &o);
    is_int(o.item.result, RAYO_GRADE_PASS,
           "a comment in the header and digits without spaces pass");
    bits(&o.image, got);
    is_string(got, "0101/1010", "digits without spaces are pixels");
    release(&o);
}

static void test_header(void)
{
    outcome o;
    char got[64];
    check("p1\n4 2\n0101\n1010\n", 4, 2, &o);
    is_int(o.item.result, RAYO_GRADE_FAIL, "p1: fails");
    ok(says(&o, "'p1' in lowercase"), "p1: named");
    is_int(o.item.line_count, 1, "p1: nothing else is wrong");
    bits(&o.image, got);
    is_string(got, "0101/1010", "p1: pixels recovered");
    release(&o);

    check("P1\n4x2\n0101\n1010\n", 4, 2, &o);
    ok(says(&o, "written '4x2'; Netpbm needs two numbers separated by "
                "whitespace: '4 2'"),
       "4x2: named, with the fix");
    is_int(o.item.line_count, 1, "4x2: nothing else is wrong");
    bits(&o.image, got);
    is_string(got, "0101/1010", "4x2: pixels recovered");
    release(&o);

    check("P1\n2 4\n01\n01\n10\n10\n", 4, 2, &o);
    ok(says(&o, "width and height are swapped"), "2 4 for 4x2: swapped");
    is_int(o.image.info.width, 2, "swapped: the image has the header's size");
    release(&o);

    check("P1\n3 2\n010\n101\n", 4, 2, &o);
    ok(says(&o, "the header says 3x2; the exercise asks for 4x2"),
       "3x2 for 4x2: named");
    release(&o);

    check("\nP1\n4 2\n0101\n1010\n", 4, 2, &o);
    ok(says(&o, "begins with 1 whitespace character before the magic"),
       "leading newline: named");
    release(&o);

    check("P14 2\n0101\n1010\n", 4, 2, &o);
    ok(says(&o, "no whitespace after the magic number"), "P14: named");
    release(&o);

    check("P1\n4\n", 4, 2, &o);
    ok(says(&o, "ends before the height"), "no height: named");
    ok(o.image.pixels == NULL, "no height: no image");
    release(&o);

    check("P1\nancho alto\n", 4, 2, &o);
    ok(says(&o, "expected the width after 'P1' at line 2, column 1; found "
                "'ancho alto\\n'"),
       "words for the width: position and text");
    release(&o);

    check("P1 100000 100000\n", 4, 2, &o);
    ok(says(&o, "100000x100000 image, which no reader accepts"),
       "huge header: refused before allocating");
    ok(o.image.pixels == NULL, "huge header: no image");
    release(&o);
}

static void test_formats(void)
{
    outcome o;
    check("", 4, 2, &o);
    ok(says(&o, "wrote nothing on standard output"), "empty: named");
    release(&o);

    check("P4\n4 2\nPZ", 4, 2, &o);
    ok(says(&o, "'P4', raw PBM (binary); the exercise asks for plain PBM"),
       "P4: named, refused");
    ok(o.image.pixels == NULL, "P4: left to the readers");
    release(&o);

    check("P3\n4 2\n255\n", 4, 2, &o);
    ok(says(&o, "'P3', plain PPM (colour)"), "P3: named");
    release(&o);

    check("hola mundo\n", 4, 2, &o);
    ok(says(&o, "does not begin with the magic number 'P1'; it begins with "
                "'hola mundo\\n'"),
       "text: quoted");
    release(&o);

    check("P6\n4 2\n255\n0000000000000000000000000000000000000000000000"
          "000000000000000000000000000000000000000000000000\n", 4, 2, &o);
    is_int(o.item.line_count, 1, "P6: no line-length note on binary "
                                 "data");
    release(&o);
}

static void test_raster(void)
{
    outcome o;
    char got[64];
    check("P1\n4 2\n0121\n1010\n", 4, 2, &o);
    ok(says(&o, "1 character in the pixels other than 0, 1 and whitespace; "
                "the first at line 3, column 3: '21\\n1010\\n'"),
       "a 2: counted and located");
    ok(says(&o, "4x2 = 8 pixels but the output has 7: 1 fewer, less than "
                "one row"),
       "a 2: one pixel short");
    release(&o);

    check("P1\n4 2\n0101\n", 4, 2, &o);
    ok(says(&o, "has 4: 4 fewer, exactly 1 row missing"), "a row missing");
    bits(&o.image, got);
    is_string(got, "0101/0000", "missing pixels are white");
    release(&o);

    check("P1\n4 2\n0101 1010 01010\n", 4, 2, &o);
    ok(says(&o, "has 13: 5 more, 1 row and 1 pixel"), "5 more: in rows");
    bits(&o.image, got);
    is_string(got, "0101/1010", "surplus pixels are dropped");
    release(&o);

    check("P1\n4 2\n0101\n# fila 2\n1010\n", 4, 2, &o);
    ok(says(&o, "a '#' comment among the pixels (line 4)"),
       "comment in the raster: named");
    is_int(o.item.line_count, 1, "comment in the raster: its text is not "
                                 "counted as pixels");
    release(&o);
}

static void test_lines(void)
{
    outcome o;
    char text[200];
    memset(text, 0, sizeof text);
    strcpy(text, "P1\n80 1\n");
    memset(text + 8, '0', 80);
    strcat(text, "\n");
    check(text, 80, 1, &o);
    is_int(o.item.result, RAYO_GRADE_PASS, "an 80-character line passes");
    is_int(o.item.warnings, 0, "... with no warning (layout is free)");
    ok(says(&o, "note: 1 line is longer than 70 characters (the "
                "longest, line 3, has 80)"),
       "... but a note naming the line and its length");
    is_int(o.item.line_count, 2, "... beside the summary");
    release(&o);

    strcpy(text, "P1\n70 1\n");
    memset(text + 8, '0', 70);
    text[78] = '\0';
    check(text, 70, 1, &o);
    is_int(o.item.line_count, 1, "a 70-character line: no note");
    release(&o);
}

/* rayo_pbm_check is rayo_pnm_check with '1': the same lines. */
static void test_pnm_entry(void)
{
    static const char *const inputs[] = {
        "P1\n4 2\n0101\n1010\n", "p1\n4x2\n0121\n", "P2\n4 2\n255\n",
        "", "P1\n4 2\n0101\n# fila 2\n1010 1\n"};
    size_t i, j;
    for (i = 0; i < sizeof inputs / sizeof inputs[0]; i++) {
        outcome a, b;
        rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
        int same;
        check(inputs[i], 4, 2, &a);
        memset(&b, 0, sizeof b);
        b.status = rayo_pnm_check(inputs[i], strlen(inputs[i]), '1', 4, 2,
                                  &b.item, &b.image, &err);
        same = a.status == b.status && a.item.result == b.item.result &&
               a.item.line_count == b.item.line_count &&
               (a.image.pixels == NULL) == (b.image.pixels == NULL);
        for (j = 0; same && j < a.item.line_count; j++)
            same = strcmp(a.item.lines[j], b.item.lines[j]) == 0;
        ok(same, "input %zu: rayo_pnm_check '1' says what rayo_pbm_check "
                 "says", i);
        release(&a);
        release(&b);
    }
}

int main(void)
{
    test_good();
    test_header();
    test_formats();
    test_raster();
    test_lines();
    test_pnm_entry();
    return tap_done();
}
