/*
 * tone_choice.h - what the tone diagnosis's two halves share: the
 * candidate chosen so far and the rule that takes a better one.
 * tone_diagnose.c tries what the picture shows wrongly (flips, shifts,
 * offsets); tone_mistakes.c tries the course's mistakes, each a render
 * of the student model.  Private to those two files.
 */
#ifndef RAYO_TONE_CHOICE_H
#define RAYO_TONE_CHOICE_H

#include "../compare_impl.h"
#include "tone_impl.h"

/* A candidate is named when it leaves at most this fraction of the
   unexplained pixels. */
#define CLOSE_REDUCTION 20

typedef struct tone_choice {
    int found;
    uint64_t unexplained, differing;
    tone_xform t;
    int mistake; /* >= 0: a course mistake instead of t */
} tone_choice;

/* Takes the candidate (t, or mistake when t is NULL) whose counts k
   fit and beat the choice so far. */
void tone_choice_consider(tone_choice *ch, const rayo_compare_report *r,
                          const tone_counts *k, const tone_xform *t,
                          int mistake);

/* A choice that leaves no pixel differing: nothing can beat it. */
int tone_choice_unbeatable(const tone_choice *ch);

/* Caps t's pass at what could still make it fit and beat ch. */
void tone_choice_cap(tone_xform *t, const rayo_compare_report *r,
                     const tone_choice *ch);

/* tone_mistakes.c: the course exercise whose right render the reference
   is (-1 none; options may name it), its mistakes tried as candidates
   when the reference is its scene, into ch; r->tone.course set when
   they were. */
rayo_status tone_try_mistakes(const tone_image *ref, const tone_image *image,
                              const rayo_compare_options *options,
                              rayo_compare_report *r, tone_choice *ch,
                              rayo_error *err);

/* tone_mistakes.c: a consistent image against the course's scene: a
   mistake the reference cannot see, named when its render agrees with
   the image far better than the right render does. */
rayo_status tone_look_for_hidden(const tone_image *ref,
                                 const tone_image *image,
                                 const rayo_compare_options *options,
                                 rayo_compare_report *r, rayo_error *err);

#endif
