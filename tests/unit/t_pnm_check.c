/*
 * t_pnm_check.c - the strict plain PGM (P2) and PPM (P3) checker of
 * rayo grade for exercises 2 and 3: each wrong number, count, header and
 * magic is found and explained with the right numbers and positions,
 * the pixels are still recovered (clamped) where they can be, and whole
 * images as `rayo render` writes the course's scenes pass, their pixels
 * those the readers read.
 *
 * The expected texts and positions are worked out by hand from the small
 * inputs written here.  The whole images come from the rayo command
 * ($RAYO, else build/rayo) run on $RAYO_SOURCE/examples (else ./).
 */
#define _POSIX_C_SOURCE 200809L /* popen */

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rayo/pbm_check.h"
#include "rayo/reader.h"
#include "tap.h"

typedef struct outcome {
    rayo_grade_item item;
    rayo_image image;
    rayo_status status;
} outcome;

static void check_n(const char *text, size_t size, char magic, uint32_t w,
                    uint32_t h, outcome *o)
{
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    memset(o, 0, sizeof *o);
    o->status = rayo_pnm_check(text, size, magic, w, h, &o->item, &o->image,
                               &err);
}

static void check(const char *text, char magic, uint32_t w, uint32_t h,
                  outcome *o)
{
    check_n(text, strlen(text), magic, w, h, o);
}

static void release(outcome *o)
{
    size_t i;
    for (i = 0; i < o->item.line_count; i++)
        free(o->item.lines[i]);
    free(o->item.lines);
    rayo_image_free(&o->image);
}

static void show(const outcome *o)
{
    size_t i;
    for (i = 0; i < o->item.line_count; i++)
        printf("#   line: %s\n", o->item.lines[i]);
}

/* 1 when some reason line contains needle. */
static int has(const outcome *o, const char *needle)
{
    size_t i;
    for (i = 0; i < o->item.line_count; i++)
        if (strstr(o->item.lines[i], needle) != NULL)
            return 1;
    return 0;
}

/* The same, showing the lines when none does. */
static int says(const outcome *o, const char *needle)
{
    if (has(o, needle))
        return 1;
    show(o);
    return 0;
}

/* The image's samples as "0 255 7/0 0 0" (rows separated by '/'). */
static void samples(const rayo_image *image, char *out, size_t room)
{
    uint32_t x, y;
    size_t n = 0;
    out[0] = '\0';
    if (image->pixels == NULL)
        return;
    for (y = 0; y < image->info.height; y++) {
        const unsigned char *row = rayo_image_row(image, y);
        for (x = 0; x < image->info.width * image->info.channels; x++)
            n += (size_t)snprintf(out + n, room - n, "%s%u",
                                  x == 0 ? (y == 0 ? "" : "/") : " ",
                                  row[x]);
    }
}

static void test_good(void)
{
    outcome o;
    char got[256];
    check("P2\n4 2\n255\n0 64 128 255\n1 2 3 4\n", '2', 4, 2, &o);
    is_int(o.status, RAYO_OK, "good P2: RAYO_OK");
    is_int(o.item.result, RAYO_GRADE_PASS, "good P2: passes");
    is_int(o.item.line_count, 1, "good P2: one line");
    ok(o.item.line_count == 1 &&
           strcmp(o.item.lines[0],
                  "plain PGM (P2), 4x2, maxval 255, 8 pixels") == 0,
       "good P2: says what it is");
    is_int(o.image.info.channels, 1, "good P2: gray");
    is_int(o.image.info.maxval, 255, "good P2: maxval 255");
    samples(&o.image, got, sizeof got);
    is_string(got, "0 64 128 255/1 2 3 4", "good P2: the samples");
    release(&o);

    check("P3\n# hecho por mi\n2 2\n255\n255 0 0\n0 255 0\n0 0 255\n"
          "10 20 30\n", '3', 2, 2, &o);
    is_int(o.item.result, RAYO_GRADE_PASS, "good P3, a header comment: "
                                           "passes");
    ok(says(&o, "plain PPM (P3), 2x2, maxval 255, 4 pixels (12 numbers)"),
       "good P3: says what it is");
    is_int(o.image.info.channels, 3, "good P3: RGB");
    samples(&o.image, got, sizeof got);
    is_string(got, "255 0 0 0 255 0/0 0 255 10 20 30", "good P3: samples");
    release(&o);

    check("P2 4 2 255 0 0 0 0 0 0 0 0", '2', 4, 2, &o);
    is_int(o.item.result, RAYO_GRADE_PASS, "P2 all on one line, no final "
                                           "newline: passes");
    release(&o);
}

static void test_out_of_range(void)
{
    outcome o;
    char got[256];
    check("P2\n4 2\n255\n0 260 0 0\n0 0 0 0\n", '2', 4, 2, &o);
    is_int(o.item.result, RAYO_GRADE_FAIL, "260: fails");
    ok(says(&o, "1 number above 255; the first, '260', at line 4, column 3 "
                "(pixel (1, 0)): values above 255 are not clamped (the "
                "statement: values above 255 become 255)"),
       "260 at (1, 0): count, line:column, pixel and cause");
    ok(says(&o, "the comparison takes it as 255"), "260: says it is clamped");
    is_int(o.item.line_count, 1, "260: nothing else is wrong");
    samples(&o.image, got, sizeof got);
    is_string(got, "0 255 0 0/0 0 0 0", "260: salvaged as 255");
    release(&o);

    check("P2\n4 2\n255\n0 0 0 0\n0 256 999 300\n", '2', 4, 2, &o);
    ok(says(&o, "3 numbers above 255; the first, '256', at line 5, column "
                "3 (pixel (1, 1))"),
       "three above 255: counted, the first located");
    ok(says(&o, "the comparison takes them as 255"), "... clamped");
    release(&o);

    check("P2\n2 1\n255\n256 0\n", '2', 2, 1, &o);
    ok(says(&o, "not clamped"), "P2 256: not clamped (scale 256 is P3's)");
    release(&o);

    check("P3\n2 1\n255\n0 0 0 0 256 0\n", '3', 2, 1, &o);
    ok(says(&o, "1 number is 256, none above; the first at line 4, column "
                "9 (pixel (1, 0), channel G): 0..1 scaled by 256 instead of "
                "255"),
       "P3 256 in G of (1, 0): scaled by 256");
    samples(&o.image, got, sizeof got);
    is_string(got, "0 0 0 0 255 0", "P3 256: salvaged as 255");
    release(&o);

    check("P3\n2 1\n255\n0 0 0 0 256 300\n", '3', 2, 1, &o);
    ok(says(&o, "2 numbers above 255; the first, '256', at line 4, column 9 "
                "(pixel (1, 0), channel G): values above 255 are not "
                "clamped (the statement: each channel above 1 becomes 1"),
       "P3 256 and 300: not clamped, the statement's channel rule");
    release(&o);

    check("P2\n4 2\n255\n0 0 -12 0\n0 0 0 -1\n", '2', 4, 2, &o);
    ok(says(&o, "2 negative numbers; the first, '-12', at line 4, column 5 "
                "(pixel (2, 0)): a negative intensity: the diffuse term is "
                "added where L.N < 0 (the statement adds it only when L.N > "
                "0); the comparison takes them as 0"),
       "negative: count, position, cause, clamped");
    is_int(o.item.line_count, 1, "negative: nothing else is wrong");
    samples(&o.image, got, sizeof got);
    is_string(got, "0 0 0 0/0 0 0 0", "negative: salvaged as 0");
    release(&o);

    check("P2\n4 1\n255\n0 -2147483648 -3 -2147483648\n", '2', 4, 1, &o);
    ok(says(&o, "2 numbers are -2147483648, the first at line 4, column 3 "
                "(pixel (1, 0)): that is what a NaN (not a number) or a "
                "value past the int range becomes through (int), not an "
                "intensity; look for 0/0, the square root of a negative "
                "discriminant or a normal of length 0; the comparison takes "
                "them as 0"),
       "-2147483648: a NaN through (int), not a negative intensity");
    ok(says(&o, "1 negative number; the first, '-3', at line 4, column 15 "
                "(pixel (2, 0)): a negative intensity"),
       "-2147483648: the other negative number is said apart");
    samples(&o.image, got, sizeof got);
    is_string(got, "0 0 0 0", "-2147483648: salvaged as 0");
    release(&o);

    check("P3\n1 2\n255\n1 2 3\n4 -5 6\n", '3', 1, 2, &o);
    ok(says(&o, "'-5', at line 5, column 3 (pixel (0, 1), channel G)"),
       "P3 negative: pixel and channel");
    release(&o);
}

static void test_fractions(void)
{
    outcome o;
    char got[256];
    check("P2\n4 2\n255\n0 12.5 0 0\n0 0 0 0\n", '2', 4, 2, &o);
    ok(says(&o, "1 number with a decimal point; the first, '12.5', at line "
                "4, column 3 (pixel (1, 0)): printed with %f instead of "
                "%d?"),
       "12.5: named, located, the likely printf");
    is_int(o.item.line_count, 1, "12.5: one number, no count problem");
    samples(&o.image, got, sizeof got);
    is_string(got, "0 12 0 0/0 0 0 0", "12.5: its whole part");
    release(&o);

    check("P3\n1 1\n255\n0.500000 0.250000 1.000000\n", '3', 1, 1, &o);
    ok(says(&o, "3 numbers with a decimal point; the first, '0.500000'"),
       "P3 floats: counted");
    ok(says(&o, "every number is between 0 and 1: the channels were not "
                "scaled to 0..255"),
       "P3 floats in 0..1: not scaled");
    release(&o);

    check("P3\n1 1\n255\n127.5 0 255\n", '3', 1, 1, &o);
    ok(says(&o, "'127.5'") && !has(&o, "between 0 and 1"),
       "P3 127.5: no 0..1 hint");
    release(&o);
}

static void test_counts(void)
{
    outcome o;
    char got[256];
    check("P2\n4 2\n255\n9 9 9 9\n", '2', 4, 2, &o);
    ok(says(&o, "the header promises 4x2 = 8 pixels but the output has 4 "
                "numbers: 4 fewer, exactly 1 row missing"),
       "P2 a row missing");
    samples(&o.image, got, sizeof got);
    is_string(got, "9 9 9 9/0 0 0 0", "missing pixels are black");
    release(&o);

    check("P2\n4 2\n255\n1 1 1 1 1 1 1 1 1 1 1 1 1\n", '2', 4, 2, &o);
    ok(says(&o, "has 13 numbers: 5 more, 1 row and 1 pixel"),
       "P2 5 more: in rows and pixels");
    release(&o);

    check("P3\n2 2\n255\n1 1 1 2 2 2 3 3 3\n", '3', 2, 2, &o);
    ok(says(&o, "the header promises 2x2 = 4 pixels of 3 numbers (R G B), "
                "12 in all, but the output has 9: 3 fewer, 1 pixel, less "
                "than one row"),
       "P3 one pixel short");
    release(&o);

    check("P3\n2 2\n255\n1 1 1 2 2 2 3 3 3 4\n", '3', 2, 2, &o);
    ok(says(&o, "has 10: 2 fewer, less than one pixel"),
       "P3 two numbers short");
    release(&o);

    check("P3\n2 1\n255\n1 1 1 2 2 2 3 3 3 4 4 4 5\n", '3', 2, 1, &o);
    ok(says(&o, "has 13: 7 more, not a whole number of pixels (2 pixels and "
                "1 number)"),
       "P3 seven more");
    release(&o);
}

static void test_text(void)
{
    outcome o;
    char got[256];
    check("P2\n4 2\n255\n0 0 0 0\n# fila 2\n0 0 0 0\n", '2', 4, 2, &o);
    ok(says(&o, "1 '#' comment among the numbers (the first at line 5); "
                "Netpbm allows comments only in the header"),
       "comment among the samples");
    is_int(o.item.line_count, 1, "comment: its text is not counted");
    release(&o);

    check("P3\n1 1\n255\n255,0,0\n", '3', 1, 1, &o);
    ok(says(&o, "2 characters among the numbers other than digits and "
                "whitespace; the first at line 4, column 4: ',0,0\\n'"),
       "commas: counted and located");
    is_int(o.item.line_count, 1, "commas: still three numbers");
    samples(&o.image, got, sizeof got);
    is_string(got, "255 0 0", "commas: the numbers recovered");
    release(&o);

    check("P2\n4 2\n1\n0 0 0 0 0 0 0 1\n", '2', 4, 2, &o);
    ok(says(&o, "the maximum value is 1 (line 3, column 1); the statement "
                "says it is always 255"),
       "maxval 1");
    ok(o.image.pixels != NULL, "maxval 1: pixels still read");
    release(&o);

    check("P2\n4 2\n7 0 0 0\n0 0 0 9\n", '2', 4, 2, &o);
    ok(says(&o, "the header has no maximum value: after the height comes 7 "
                "(line 3, column 1)"),
       "maxval left out: seen as the first pixel");
    is_int(o.item.line_count, 1, "maxval left out: no count problem");
    samples(&o.image, got, sizeof got);
    is_string(got, "7 0 0 0/0 0 0 9", "maxval left out: pixels in place");
    release(&o);

    check("P2\n4 2\n", '2', 4, 2, &o);
    ok(says(&o, "ends before the maximum value (255)"), "no maxval at all");
    ok(o.image.pixels == NULL, "no maxval at all: no image");
    release(&o);

    check("P2\n4x2\n255\n0 0 0 0 0 0 0 0\n", '2', 4, 2, &o);
    ok(says(&o, "written '4x2'"), "P2 4x2: named as for P1");
    ok(o.image.pixels != NULL, "P2 4x2: pixels read");
    release(&o);

    check("P3\n2 4\n255\n", '3', 4, 2, &o);
    ok(says(&o, "width and height are swapped"), "P3 swapped");
    release(&o);
}

static void test_magic(void)
{
    outcome o;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    char got[256];
    check("P3\n4 2\n255\n0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n",
          '2', 4, 2, &o);
    ok(says(&o, "the magic number is 'P3', plain PPM (colour); the exercise "
                "asks for plain PGM, 'P2'"),
       "P3 for P2: named");
    ok(o.image.pixels == NULL, "P3 for P2: left to the readers");
    release(&o);

    check("P3\n4 2\n255\n1 2 3 4 5 6 7 8\n", '2', 4, 2, &o);
    ok(says(&o, "the header says P3 (plain PPM, colour) but the output has "
                "1 number per pixel, written as text (4x2 pixels, 8 "
                "numbers): a text gray image is a PGM, P2"),
       "P3 header over one number a pixel: a PGM");
    samples(&o.image, got, sizeof got);
    is_string(got, "1 2 3 4/5 6 7 8", "... read as P2");
    release(&o);

    check("P2\n1 2\n255\n1 2 3 4 5 6\n", '3', 1, 2, &o);
    ok(says(&o, "the header says P2 (plain PGM, gray) but the output has 3 "
                "numbers per pixel"),
       "P2 header over three numbers a pixel: a PPM");
    samples(&o.image, got, sizeof got);
    is_string(got, "1 2 3/4 5 6", "... read as P3");
    release(&o);

    check("P1\n4 2\n0101\n1010\n", '2', 4, 2, &o);
    ok(says(&o, "'P1', plain PBM (black and white); the exercise asks for "
                "plain PGM, 'P2'"),
       "P1 for P2");
    release(&o);

    check("P5\n4 2\n255\n0 10 20 300\n1 2 3 4\n", '2', 4, 2, &o);
    ok(says(&o, "the header says P5 (raw, binary PGM) but the samples are "
                "written as text: a text PGM is P2"),
       "P5 over text: the brief's words");
    ok(says(&o, "1 number above 255"), "P5 over text: then read as P2");
    samples(&o.image, got, sizeof got);
    is_string(got, "0 10 20 255/1 2 3 4", "P5 over text: pixels salvaged");
    release(&o);

    check("P6\n1 1\n255\n1 2 3\n", '3', 1, 1, &o);
    ok(says(&o, "the header says P6 (raw, binary PPM) but the samples are "
                "written as text: a text PPM is P3"),
       "P6 over text");
    is_int(o.item.line_count, 1, "P6 over text: nothing else");
    release(&o);

    check_n("P5\n2 1\n255\n\x01\xff", 14, '2', 2, 1, &o);
    ok(says(&o, "the magic number is 'P5', raw PGM (gray, binary); the "
                "exercise asks for plain PGM, 'P2'"),
       "binary P5: refused");
    ok(o.image.pixels == NULL, "binary P5: left to the readers");
    release(&o);

    check_n("\x89PNG\r\n\x1a\n", 8, '3', 4, 2, &o);
    ok(says(&o, "a PNG image; the exercise asks for plain PPM ('P3' and "
                "numbers)"),
       "PNG for P3");
    release(&o);

    check("p2\n1 1\n255\n7\n", '2', 1, 1, &o);
    ok(says(&o, "'p2' in lowercase; Netpbm needs a capital 'P2'"),
       "p2 lowercase");
    is_int(o.item.line_count, 1, "p2: nothing else");
    release(&o);

    check("", '3', 4, 2, &o);
    ok(says(&o, "wrote nothing on standard output; it must write the image "
                "there (./programa > imagen.ppm)"),
       "empty P3");
    release(&o);

    check("hola\n", '2', 4, 2, &o);
    ok(says(&o, "does not begin with the magic number 'P2'; it begins with "
                "'hola\\n'"),
       "text for P2");
    release(&o);

    memset(&o, 0, sizeof o);
    is_int(rayo_pnm_check("P4", 2, '4', 4, 2, &o.item, &o.image, &err),
           RAYO_ERR_INVALID, "magic '4': RAYO_ERR_INVALID");
    release(&o);
}

static void test_note(void)
{
    outcome o;
    char text[200];
    size_t i;
    strcpy(text, "P2\n40 1\n255\n");
    for (i = 0; i < 40; i++)
        strcat(text, "0 ");
    check(text, '2', 40, 1, &o);
    is_int(o.item.result, RAYO_GRADE_PASS, "an 80-character line passes");
    is_int(o.item.warnings, 0, "... with no warning");
    ok(says(&o, "note: 1 line is longer than 70 characters (the longest, "
                "line 4, has 80)"),
       "... and a note");
    release(&o);
}

/* The output of `$RAYO render $RAYO_SOURCE/examples/scene -q`. */
static char *render(const char *scene, size_t *size)
{
    const char *rayo = getenv("RAYO"), *root = getenv("RAYO_SOURCE");
    char command[8192];
    char *data = NULL;
    size_t room = 0;
    FILE *pipe;
    snprintf(command, sizeof command, "'%s' render '%s/examples/%s' -q",
             rayo ? rayo : "build/rayo", root ? root : ".", scene);
    pipe = popen(command, "r");
    *size = 0;
    if (pipe == NULL)
        return NULL;
    for (;;) {
        size_t got;
        if (*size == room) {
            char *grown = realloc(data, room = room ? room * 2 : 1 << 20);
            if (grown == NULL)
                break;
            data = grown;
        }
        got = fread(data + *size, 1, room - *size, pipe);
        if (got == 0)
            break;
        *size += got;
    }
    if (pclose(pipe) != 0) {
        printf("# %s failed\n", command);
        *size = 0;
    }
    return data;
}

static int same_pixels(const rayo_image *a, const rayo_image *b)
{
    uint32_t y;
    size_t bytes = rayo_image_info_row_bytes(&a->info);
    if (a->pixels == NULL || b->pixels == NULL ||
        memcmp(&a->info, &b->info, sizeof a->info) != 0)
        return 0;
    for (y = 0; y < a->info.height; y++)
        if (memcmp(rayo_image_row(a, y), rayo_image_row(b, y), bytes) != 0)
            return 0;
    return 1;
}

/* Only the summary, and perhaps the line-length note. */
static int clean(const outcome *o)
{
    size_t i;
    for (i = 0; i + 1 < o->item.line_count; i++)
        if (strncmp(o->item.lines[i], "note: ", 6) != 0)
            return 0;
    return o->item.result == RAYO_GRADE_PASS && o->item.warnings == 0;
}

static void test_whole(const char *scene, char magic, const char *summary)
{
    outcome o;
    rayo_image read;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    size_t size, i, header = 0, lines = 0;
    char *data = render(scene, &size);
    ok(size > 640 * 480 && data != NULL && data[0] == 'P' &&
           data[1] == magic,
       "%s: rendered as P%c (%zu bytes)", scene, magic, size);
    if (size == 0 || data == NULL) {
        free(data);
        return;
    }
    check_n(data, size, magic, 640, 480, &o);
    ok(clean(&o), "%s: passes with no finding", scene);
    if (!clean(&o))
        show(&o);
    ok(says(&o, summary), "%s: %s", scene, summary);
    memset(&read, 0, sizeof read);
    is_int(rayo_image_read_memory(data, size, scene, &read, NULL, &err),
           RAYO_OK, "%s: the reader reads it", scene);
    ok(same_pixels(&o.image, &read), "%s: the checker's pixels are the "
                                     "reader's", scene);
    release(&o);

    /* The same numbers on one line after the header: a note, no more. */
    for (i = 0; i < size && lines < 3; i++)
        if (data[i] == '\n' && ++lines == 3)
            header = i + 1;
    for (i = header; i + 1 < size; i++)
        if (data[i] == '\n')
            data[i] = ' ';
    check_n(data, size, magic, 640, 480, &o);
    ok(clean(&o) && o.item.line_count == 2 &&
           says(&o, "note: 1 line is longer than 70 characters"),
       "%s on one line: passes, with a note", scene);
    ok(same_pixels(&o.image, &read), "%s on one line: the same pixels",
       scene);
    release(&o);

    /* The first sample (black, 0) made 300: found at pixel (0, 0). */
    if (data[header] == '0' && data[header + 1] == ' ') {
        char *changed = malloc(size + 2);
        if (changed != NULL) {
            memcpy(changed, data, header);
            memcpy(changed + header, "300", 3);
            memcpy(changed + header + 3, data + header + 1,
                   size - header - 1);
            check_n(changed, size + 2, magic, 640, 480, &o);
            ok(says(&o, magic == '3'
                            ? "1 number above 255; the first, '300', at "
                              "line 4, column 1 (pixel (0, 0), channel R)"
                            : "1 number above 255; the first, '300', at "
                              "line 4, column 1 (pixel (0, 0))"),
               "%s with 300 first: found", scene);
            rayo_image_row(&read, 0)[0] = 255;
            ok(same_pixels(&o.image, &read), "%s with 300 first: the "
                                             "reader's pixels but that one, "
                                             "255", scene);
            release(&o);
            free(changed);
        }
    } else {
        ok(0, "%s: the first sample is 0", scene);
    }
    rayo_image_free(&read);
    free(data);
}

int main(void)
{
    test_good();
    test_out_of_range();
    test_fractions();
    test_counts();
    test_text();
    test_magic();
    test_note();
    test_whole("ej2.scene", '2', "plain PGM (P2), 640x480, maxval 255, "
                                 "307200 pixels");
    test_whole("ej3.scene", '3', "plain PPM (P3), 640x480, maxval 255, "
                                 "307200 pixels (921600 numbers)");
    return tap_done();
}
