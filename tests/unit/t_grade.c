/*
 * t_grade.c - the grader's library surface that needs no compiler: the
 * exercise registry and its reference, the option defaults, finding a
 * submission's sources and a class's folders, the names and the overall
 * result, and the refusals of bad options.  Grading real programs is
 * tested through the command (tests/cli/grade_*.t).
 */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "rayo.h"
#include "tap.h"

static void touch(const char *dir, const char *name)
{
    char path[512];
    FILE *f;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    f = fopen(path, "w");
    if (f != NULL)
        fclose(f);
}

static void test_registry(void)
{
    size_t count = 0;
    const rayo_grade_exercise *all = rayo_grade_exercises(&count);
    const rayo_grade_exercise *ej1 = rayo_grade_exercise_find("ej1");
    rayo_image reference;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    uint32_t black = 0, x, y;
    ok(count >= 1 && all != NULL, "the registry has exercises");
    ok(ej1 != NULL, "ej1 is registered");
    ok(rayo_grade_exercise_find("ej99") == NULL, "an unknown name: NULL");
    if (ej1 == NULL)
        return;
    is_int(ej1->width, 640, "ej1: 640 wide");
    is_int(ej1->height, 480, "ej1: 480 high");
    is_int(ej1->magic, '1', "ej1: its output is plain PBM");
    memset(&reference, 0, sizeof reference);
    is_int(ej1->reference(&reference, &err), RAYO_OK, "ej1: reference made");
    is_int(reference.info.sample, RAYO_SAMPLE_BIT, "ej1 reference: bilevel");
    for (y = 0; y < reference.info.height; y++)
        for (x = 0; x < reference.info.width; x++)
            black += (uint32_t)rayo_bit_get(rayo_image_row(&reference, y), x);
    /* The README's compare report counts the seed render's black pixels. */
    is_int(black, 64503, "ej1 reference: the seed sphere's 64503 pixels");
    /* The sphere is up and right of centre: (0.5, 0.75) with y up. */
    is_int(rayo_bit_get(rayo_image_row(&reference, 0), 0), 0,
           "ej1 reference: top-left corner white");
    is_int(rayo_bit_get(rayo_image_row(&reference, 240 - 126), 320 + 84), 1,
           "ej1 reference: black where the centre projects");
    rayo_image_free(&reference);
}

static void test_options(void)
{
    rayo_grade_options o;
    rayo_grade_report report;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    rayo_grade_options_init(&o);
    ok(o.exercise == rayo_grade_exercise_find("ej1"), "default: ej1");
    is_double(o.timeout, 10, 0, "default: 10 s wall clock");
    is_double(o.cpu, 10, 0, "default: 10 s CPU");
    is_int(o.output_limit, 64u << 20, "default: 64 MiB of output");
    is_int(o.memory, 512u << 20,
           "default: 512 MiB for the tree and each address space");
    is_int(o.processes, 64, "default: 64 processes");
    is_int(o.valgrind, 1, "default: valgrind on");
    is_int(rayo_grade(&o, &report, &err), RAYO_ERR_INVALID,
           "no sources: RAYO_ERR_INVALID");
    rayo_grade_report_free(&report);
}

static void test_sources(void)
{
    char dir[] = "/tmp/rayo-t-grade.XXXXXX";
    char path[512];
    char **list = NULL;
    size_t count = 0;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN);
    if (mkdtemp(dir) == NULL) {
        ok(0, "mkdtemp");
        return;
    }
    touch(dir, "vector.c");
    touch(dir, "main.c");
    touch(dir, "vector.h");
    touch(dir, ".hidden.c");
    snprintf(path, sizeof path, "%s/ana", dir);
    mkdir(path, 0700);
    snprintf(path, sizeof path, "%s/beto", dir);
    mkdir(path, 0700);

    is_int(rayo_grade_sources(dir, &list, &count, &err), RAYO_OK,
           "a folder's sources");
    is_int(count, 2, "two .c files (not .h, not hidden, not folders)");
    if (count == 2) {
        ok(strstr(list[0], "/main.c") != NULL, "sorted: main.c first");
        ok(strstr(list[1], "/vector.c") != NULL, "then vector.c");
    }
    rayo_grade_paths_free(list, count);

    snprintf(path, sizeof path, "%s/main.c", dir);
    is_int(rayo_grade_sources(path, &list, &count, &err), RAYO_OK,
           "a file is its own submission");
    is_int(count, 1, "one source");
    if (count == 1)
        is_string(list[0], path, "the path as given");
    rayo_grade_paths_free(list, count);

    snprintf(path, sizeof path, "%s/ana", dir);
    is_int(rayo_grade_sources(path, &list, &count, &err), RAYO_ERR_INVALID,
           "a folder without .c files: RAYO_ERR_INVALID");
    ok(strstr(err.message, "no .c file in this folder") != NULL,
       "... saying so");

    is_int(rayo_grade_submissions(dir, &list, &count, &err), RAYO_OK,
           "a class's folders");
    is_int(count, 2, "two students");
    if (count == 2) {
        ok(strstr(list[0], "/ana") != NULL, "ana first");
        ok(strstr(list[1], "/beto") != NULL, "beto second");
    }
    rayo_grade_paths_free(list, count);

    snprintf(path, sizeof path, "%s/none", dir);
    is_int(rayo_grade_sources(path, &list, &count, &err), RAYO_ERR_IO,
           "a missing path: RAYO_ERR_IO");

    snprintf(path, sizeof path, "rm -rf '%s'", dir);
    ok(system(path) == 0, "cleaned up");
}

static void test_names(void)
{
    rayo_grade_report report;
    memset(&report, 0, sizeof report);
    is_string(rayo_grade_criterion_name(RAYO_GRADE_COMPILE), "compile",
              "criterion name");
    is_string(rayo_grade_criterion_name(RAYO_GRADE_VALGRIND), "valgrind",
              "last criterion name");
    is_string(rayo_grade_result_name(RAYO_GRADE_SKIPPED), "skipped",
              "result name");
    is_int(rayo_grade_overall(&report), RAYO_GRADE_PASS,
           "all skipped: nothing failed");
    report.items[RAYO_GRADE_IMAGE].result = RAYO_GRADE_FAIL;
    is_int(rayo_grade_overall(&report), RAYO_GRADE_FAIL, "one fail: fail");
}

int main(void)
{
    test_registry();
    test_options();
    test_sources();
    test_names();
    return tap_done();
}
