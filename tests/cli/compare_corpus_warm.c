/*
 * compare_corpus_warm.c - the pairs of compare_corpus.sh compared in ONE
 * process, PASSES times over (text, JSON and a hash of the --diff PNG of
 * each on standard output), so that what the comparison's cache
 * (src/compare/tone/tone_cache.c) keeps from one pair to the next can be seen
 * to change no report: run it linked with a build that has the cache and
 * with one that has none (or compare its passes with each other), on
 * pairs.txt in order and shuffled.  Not part of `make check`:
 *
 *   RAYO_CORPUS_KEEP=/tmp/pairs sh tests/cli/compare_corpus.sh record build/rayo /tmp/reports
 *   cc -O2 -Iinclude -o /tmp/warm tests/cli/compare_corpus_warm.c build/librayo.a -lpng16 -lpthread -lm
 *   (cd /tmp/pairs && /tmp/warm pairs.txt 3) > new.out
 *
 * OPTS understood: --levels N, --tolerance PX, --exercise NAME|none.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rayo/compare.h"
#include "rayo/course.h"
#include "rayo/reader.h"
#include "rayo/output.h"
static void put(const rayo_compare_report *r, size_t (*f)(const rayo_compare_report *, char *, size_t)) {
  size_t n = f(r, NULL, 0); char *t = malloc(n + 1); f(r, t, n + 1); fputs(t, stdout); free(t); }
int main(int argc, char **argv) {
  int passes = argc > 2 ? atoi(argv[2]) : 1, p; char line[8192];
  for (p = 0; p < passes; p++) {
    FILE *f = fopen(argv[1], "r");
    while (fgets(line, sizeof line, f)) {
      char *name = strtok(line, "|"), *opts = strtok(NULL, "|\n"), *ref = strtok(NULL, "|\n"), *img = strtok(NULL, "|\n");
      rayo_image a, b; rayo_read_report rr; rayo_read_options ro; rayo_error err; rayo_compare_options o; rayo_compare_report r;
      char *tok;
      if (img == NULL) { img = ref; ref = opts; opts = ""; } /* empty OPTS: strtok skipped it */
      rayo_error_clear(&err); rayo_compare_options_init(&o);
      for (tok = strtok(opts, " "); tok; tok = strtok(NULL, " ")) {
        char *v = strtok(NULL, " ");
        if (!strcmp(tok, "--levels")) o.levels = (unsigned)atoi(v);
        else if (!strcmp(tok, "--tolerance")) o.tolerance = atof(v);
        else if (!strcmp(tok, "--exercise")) o.course = !strcmp(v, "none") ? RAYO_COMPARE_COURSE_NONE : (int)rayo_course_find(v);
      }
      memset(&ro, 0, sizeof ro); ro.clamp = 1;
      if (rayo_image_read_file(ref, &a, NULL, &err) != RAYO_OK) { printf("%s: ref error\n", name); continue; }
      if (rayo_image_read_file_with(img, &ro, &b, &rr, &err) != RAYO_OK) { printf("%s: image error\n", name); rayo_image_free(&a); continue; }
      printf("== %s\n", name);
      if (rayo_compare_images(&a, &b, &o, &r, &err) != RAYO_OK) printf("compare error %s\n", err.message);
      else {
        rayo_output *out; FILE *d; int c;
        rayo_compare_note_clamped(&r, &rr);
        put(&r, rayo_compare_format_text); put(&r, rayo_compare_format_json);
        rayo_output_open(&out, "compare_corpus_warm.png", &err);
        if (rayo_compare_write_diff(&a, &b, &o, out, &err) == RAYO_OK) rayo_output_commit(out, &err); else rayo_output_abort(out);
        d = fopen("compare_corpus_warm.png", "rb"); unsigned long h = 5381;
        if (d) { while ((c = fgetc(d)) != EOF) h = h * 33 + (unsigned)c; fclose(d); remove("compare_corpus_warm.png"); }
        printf("diff %lx\n", h);
      }
      rayo_image_free(&a); rayo_image_free(&b);
    }
    fclose(f);
  }
  return 0;
}
