/*
 * report_sink.h - the text a comparison report is written into: the
 * caller's buffer with snprintf semantics (the whole length is counted,
 * the text cut to fit), shared by the mask and tone formatters of
 * src/compare and by no one else.
 */
#ifndef RAYO_REPORT_SINK_H
#define RAYO_REPORT_SINK_H

#include <stddef.h>

#include "rayo/lang.h"

typedef struct cmp_sink {
    char *buffer;
    size_t size, length;
    rayo_lang lang; /* the text's language; English for JSON */
} cmp_sink;

/* Appends a sentence of the text report: the format looked up in the
   sink's language, numbers written as it writes them ("0,5"); the
   format is extracted by xgettext (report_format.c). */
void cmp_put(cmp_sink *s, const char *format, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* cmp_put with the singular or plural format for count. */
void cmp_putn(cmp_sink *s, unsigned long long count, const char *singular,
              const char *plural, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 3, 5))) __attribute__((format(printf, 4, 5)))
#endif
    ;

/* Appends JSON, or punctuation between sentences: never translated,
   numbers as C writes them (report_format.c). */
void cmp_json(cmp_sink *s, const char *format, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

struct rayo_compare_report;

/* "verdict: consistent" and its newline, in the sink's language (the
   JSON's token stays English: report_format.c). */
void cmp_put_verdict(cmp_sink *s, int verdict);

/* The sentence about samples clamped out of 0..maxval, and their JSON
   member (report_format.c). */
void cmp_put_out_of_range(cmp_sink *s, const struct rayo_compare_report *r);
void cmp_put_clamped_json(cmp_sink *s, const struct rayo_compare_report *r);

/* The note, and the JSON member "kinds", when the image's kind of
   picture is not the reference's (kinds.c; nothing otherwise). */
void cmp_put_kinds(cmp_sink *s, const struct rayo_compare_report *r);
void cmp_put_kinds_json(cmp_sink *s, const struct rayo_compare_report *r);

/* 100 differences / band (0 for an empty band), and the JSON members
   of a crowded report, "band" and "crowded" (nothing otherwise:
   report_format.c). */
double cmp_band_percent(unsigned long long differences,
                        unsigned long long band);
void cmp_put_crowded_json(cmp_sink *s, const struct rayo_compare_report *r);

#endif
