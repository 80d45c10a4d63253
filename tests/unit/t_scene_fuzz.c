/*
 * t_scene_fuzz.c - the scene parser on thousands of damaged scene files:
 * it must never crash, read out of bounds (run under ASan and valgrind
 * by `make check-sanitize`), or fail without a message that names the
 * file and a line and column.
 *
 * The inputs are a valid scene (every statement, no final newline, so
 * the last word touches the end of the buffer) mutated by a seeded
 * generator: bytes replaced by others (digits, signs, blanks, '#', NUL,
 * newlines, high bytes), bytes deleted or duplicated, the text cut short.
 * The same seed gives the same inputs every run.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "rayo.h"
#include "tap.h"

static const char base[] =
    "shade phong\nsamples 2\ndepth 3\n"
    "camera size 64 48 fov 60 origin 0 1 -4 look-at 0 0.5 0 up 0 1 0\n"
    "background 0.5 0.7 1\nambient 0.2\n"
    "light point -3 5 -3 color 0.9\nlight directional 0 1 0\n"
    "material red color 0.9 0.1 0.1 ks 0.5 shininess 40 reflect 0.2\n"
    "sphere 0 0.5 0 0.5 material red\n"
    "plane 0 0 0 0 1 0\n"
    "triangle -1 0 2 1 0 2 0 1 2 material red";

static uint64_t state = 20261123u;

/* A number below n from a 64-bit linear congruential generator. */
static unsigned next(unsigned n)
{
    state = state * 6364136223846793005u + 1442695040888963407u;
    return (unsigned)((state >> 33) % n);
}

static size_t mutate(char *text, size_t length)
{
    static const char bytes[] = "0123456789-+.eE #\n\t\r\0abz\x80\xff";
    unsigned edits = 1 + next(4), k;
    for (k = 0; k < edits && length > 0; k++) {
        size_t at = next((unsigned)length);
        switch (next(4)) {
        case 0:
            text[at] = bytes[next(sizeof bytes - 1)];
            break;
        case 1:
            memmove(text + at, text + at + 1, length - at - 1);
            length--;
            break;
        case 2:
            if (length < 1000) {
                memmove(text + at + 1, text + at, length - at);
                length++;
            }
            break;
        default:
            length = at;
            break;
        }
    }
    return length;
}

int main(void)
{
    rayo_scene_file file;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    long good = 0, refused = 0, unnamed = 0, odd_status = 0;
    int round;
    for (round = 0; round < 3000; round++) {
        char text[1100];
        size_t length = sizeof base - 1;
        char *exact;
        rayo_status status;
        memcpy(text, base, length);
        length = mutate(text, length);
        /* An allocation of exactly the text, so reading past it shows. */
        exact = malloc(length ? length : 1);
        if (exact == NULL)
            return 1;
        memcpy(exact, text, length);
        status = rayo_scene_file_parse(&file, "fuzz.scene", exact, length,
                                       &err);
        if (status == RAYO_OK) {
            good++;
            rayo_scene_file_free(&file);
        } else {
            refused++;
            if (strncmp(err.message, "fuzz.scene:", 11) != 0)
                unnamed++;
            if (status != RAYO_ERR_FORMAT && status != RAYO_ERR_INVALID &&
                status != RAYO_ERR_LIMIT)
                odd_status++;
        }
        free(exact);
    }
    printf("# %ld parsed, %ld refused\n", good, refused);
    ok(good > 0 && refused > 0, "both outcomes are exercised");
    is_int(unnamed, 0, "every refusal names fuzz.scene:LINE:COL");
    is_int(odd_status, 0, "every refusal is a format, value or limit error");
    return tap_done();
}
