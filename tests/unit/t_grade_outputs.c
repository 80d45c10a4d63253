/*
 * t_grade_outputs.c - what the grader reads of a submission's output
 * before trusting it: the size an image's header promises (read without
 * decoding; output_header.c) and valgrind's log read as bytes, with the
 * signs that the program wrote into it (valgrind_log.c).
 *
 * The expected values are worked out by hand from the bytes each case
 * builds; no program is run.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../../src/grade/grade_impl.h"
#include "../../src/grade/valgrind_log.h"
#include "tap.h"

static void peeks(void)
{
    static const unsigned char png[] = {
        0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13,
        'I', 'H', 'D', 'R', 0, 1, 0, 0, 0, 0, 0x40, 0, 16, 0, 0, 0, 0};
    static const rayo_grade_exercise ej1 = {"ej1", "test", 640, 480, '1',
                                            RAYO_COURSE_EJ1, NULL, NULL};
    grade_header h;
    rayo_image reference;
    const char *text;

    ok(grade_header_peek(png, sizeof png, &h), "PNG: read");
    is_string(h.format, "PNG", "PNG: named");
    ok(h.width == 65536 && h.height == 16384 && h.depth == 16,
       "PNG: 65536x16384, 16 bits, from IHDR");
    ok(!grade_header_peek(png, 20, &h), "PNG cut before IHDR's size: not read");

    text = "P1\n# a comment\n640 480\n0 1";
    ok(grade_header_peek(text, strlen(text), &h) && h.width == 640 &&
           h.height == 480 && h.depth == 1 &&
           strcmp(h.format, "plain PBM") == 0,
       "plain PBM with a comment: 640x480");
    text = "  p1 640x480\n";
    ok(grade_header_peek(text, strlen(text), &h) && h.width == 640 &&
           h.height == 480,
       "lowercase magic, whitespace before it, '640x480': read as the "
       "checker reads it");
    text = "P6\n100000 100000\n65535\n";
    ok(grade_header_peek(text, strlen(text), &h) && h.width == 100000 &&
           h.height == 100000 && h.depth == 16 &&
           strcmp(h.format, "raw PPM") == 0,
       "raw PPM, maxval 65535: 16 bits");
    text = "P3 99999999999999999999999 2 255";
    ok(grade_header_peek(text, strlen(text), &h) &&
           h.width == ((uint64_t)1 << 40) && h.height == 2,
       "a width of 23 digits saturates instead of wrapping");
    text = "P7\n640 480\n";
    ok(!grade_header_peek(text, strlen(text), &h), "P7: not a header it knows");
    ok(!grade_header_peek("P2\n640", 6, &h), "no height: not read");
    ok(!grade_header_peek("", 0, &h), "nothing: not read");

    memset(&reference, 0, sizeof reference);
    ok(grade_pixels_allowed(&ej1, NULL) == 4ull * 640 * 480,
       "allowed: 4 times the exercise's 640x480");
    reference.info.width = 1000;
    reference.info.height = 1000;
    ok(grade_pixels_allowed(&ej1, &reference) == 4000000ull,
       "allowed: 4 times a larger reference's 1000x1000");
}

static void lines(void)
{
    static const char log[] = "==12== Invalid read of size 4\n"
                              "==12==    at 0x1: main (a.c:3)\n"
                              "--7-- a warning\n"
                              "no frame\n"
                              "==12==";
    static const char with_nul[] = "==3== a\0b\n==3== c";
    char *wide;
    size_t pos = 0, n = 100000;
    vg_line line;
    char copy[16];

    ok(vg_next_line(log, sizeof log - 1, &pos, &line) && line.pid == 12 &&
           vg_begins(&line, "Invalid read of size 4") &&
           line.body_length == strlen("Invalid read of size 4"),
       "a framed line: its PID and body");
    ok(vg_next_line(log, sizeof log - 1, &pos, &line) &&
           vg_begins(&line, "at 0x1") && vg_find(&line, ": main") != NULL,
       "the spaces after the frame are not the body's");
    ok(vg_next_line(log, sizeof log - 1, &pos, &line) && line.pid == 7,
       "a --PID-- frame");
    ok(vg_next_line(log, sizeof log - 1, &pos, &line) && line.pid == -1 &&
           line.body_length == 8,
       "a line without a frame");
    ok(vg_next_line(log, sizeof log - 1, &pos, &line) && line.pid == 12 &&
           line.body_length == 0,
       "the last line, without its newline");
    ok(!vg_next_line(log, sizeof log - 1, &pos, &line), "then the end");

    pos = 0;
    ok(vg_next_line(with_nul, sizeof with_nul - 1, &pos, &line) &&
           line.body_length == 3 && line.body[2] == 'b',
       "a NUL byte is part of the line, not its end");
    ok(vg_next_line(with_nul, sizeof with_nul - 1, &pos, &line) &&
           vg_begins(&line, "c"),
       "and the line after it is still read");
    vg_copy("a\0b", 3, copy, sizeof copy);
    is_string(copy, "a b", "vg_copy: a NUL becomes a space");

    wide = malloc(n + 32);
    if (wide != NULL) {
        memcpy(wide, "==5== ", 6);
        memset(wide + 6, 'x', n);
        memcpy(wide + 6 + n, "ERROR SUMMARY: 3\n", 17);
        pos = 0;
        ok(vg_next_line(wide, n + 23, &pos, &line) &&
               line.body_length == n + 16 &&
               vg_find(&line, "ERROR SUMMARY: 3") != NULL,
           "a line of 100 kB is one line");
        free(wide);
    }
}

static void signs(void)
{
    static const char clean[] =
        "==9== Memcheck, a memory error detector\n==9== \n"
        "==9== ERROR SUMMARY: 0 errors from 0 contexts\n"
        "==10== ERROR SUMMARY: 0 errors from 0 contexts\n";
    static const char nul[] = "==9== ERROR SUMMARY: 0 errors\n\0==9== x\n";
    static const char twice[] = "==9== ERROR SUMMARY: 2 errors\n"
                                "==9== ERROR SUMMARY: 0 errors\n";
    static const char refused[] =
        "==9== Warning: invalid file descriptor 1023 in syscall write()\n";
    static const char closed[] =
        "==9== Warning: invalid file descriptor 1023 in syscall close()\n"
        "==9== Warning: invalid file descriptor 40 in syscall write()\n";
    static const char panic[] =
        "==9== Command: ./p\n\nvalgrind: m_x.c:1 (f): Assertion 'a' "
        "failed.\n\nhost stacktrace:\n";
    const char *text;
    vg_signs s;

    vg_check(clean, sizeof clean - 1, 1023, &s);
    ok(!s.nul && !s.unframed && !s.duplicate && s.touched_fd < 0 && !s.panic,
       "a clean log of two processes: no sign");
    vg_check(nul, sizeof nul - 1, 1023, &s);
    ok(s.nul, "a NUL byte");
    vg_check("==9== a\nforged\n", 15, 1023, &s);
    ok(s.unframed, "a line without a frame");
    text = "### unhandled dwarf2 abbrev form code 0x25\n"
           "get_Form_szB: unhandled 27 (DW_FORM_addrx)\n"
           "==9== ERROR SUMMARY: 0 errors from 0 contexts\n";
    vg_check(text, strlen(text), 1023, &s);
    ok(!s.unframed && !s.duplicate,
       "valgrind's own notices on clang's DWARF 5: not forged lines");
    text = "### unhandled dwarf2\n";
    vg_check(text, strlen(text), 1023, &s);
    ok(s.unframed, "a line that only starts like such a notice: forged");
    vg_check(twice, sizeof twice - 1, 1023, &s);
    ok(s.duplicate, "two error summaries from one process");
    vg_check(refused, sizeof refused - 1, 1023, &s);
    is_int(s.touched_fd, 1023, "a refused write to the log's descriptor");
    vg_check(closed, sizeof closed - 1, 1023, &s);
    is_int(s.touched_fd, -1, "a refused close, or a write below the log's "
                             "descriptor: not a write into it");
    vg_check(panic, sizeof panic - 1, 1023, &s);
    ok(s.panic && !s.unframed && s.panic_at == 20,
       "valgrind's crash report: found where it begins, its lines not "
       "taken for forged ones");

    text = "P1\n1 1\n0\n==1== ERROR SUMMARY: 0\n";
    ok(vg_framed_text(text, strlen(text)),
       "valgrind's framing in a program's output");
    text = "P1\n1 1\n0\n== not a frame\n--1-- x\n";
    ok(!vg_framed_text(text, strlen(text)),
       "no framing: '== ' alone, or a --PID-- line");
    ok(!vg_framed_text(NULL, 0), "no output");
}

int main(void)
{
    peeks();
    lines();
    signs();
    return tap_done();
}
