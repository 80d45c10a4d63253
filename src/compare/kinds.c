/*
 * kinds.c - what kind of picture an image is (black and white, gray,
 * colour), whether two images show the same picture, and the note a
 * report gives when the image's kind is not the reference's: a gray
 * image compared with exercise 1's black and white sphere is most
 * likely exercise 2's, compared with the wrong reference.
 *
 * The library does not know which file is the course's: the caller says
 * (it named course:ejN, or found the picture equal to the course's
 * image with rayo_image_same_picture).  Not a measure of how far two
 * pictures are apart (that is the comparison itself): only equal or not.
 */
#include <stdlib.h>
#include <string.h>

#include "report_sink.h"
#include "tone/tone_impl.h"

rayo_picture_kind rayo_picture_kind_of(const rayo_image *image)
{
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN); /* not shown */
    if (image == NULL || image->pixels == NULL ||
        rayo_image_info_check(&image->info, &err) != RAYO_OK)
        return RAYO_PICTURE_UNKNOWN;
    if (tone_is_bilevel(image))
        return RAYO_PICTURE_BILEVEL;
    return tone_has_colour(image) ? RAYO_PICTURE_COLOUR : RAYO_PICTURE_GRAY;
}

rayo_course_exercise rayo_picture_kind_exercise(rayo_picture_kind kind)
{
    switch (kind) {
    case RAYO_PICTURE_BILEVEL:
        return rayo_course_of_kind(RAYO_COURSE_BILEVEL);
    case RAYO_PICTURE_GRAY:
        return rayo_course_of_kind(RAYO_COURSE_GRAY);
    case RAYO_PICTURE_COLOUR:
        return rayo_course_of_kind(RAYO_COURSE_COLOUR);
    case RAYO_PICTURE_UNKNOWN:
        break;
    }
    return RAYO_COURSE_EXERCISES;
}

const char *rayo_picture_kind_name(rayo_picture_kind kind)
{
    switch (kind) {
    case RAYO_PICTURE_BILEVEL:
        return "bilevel";
    case RAYO_PICTURE_GRAY:
        return "gray";
    case RAYO_PICTURE_COLOUR:
        return "colour";
    case RAYO_PICTURE_UNKNOWN:
        break;
    }
    return "unknown";
}

int rayo_image_same_picture(const rayo_image *a, const rayo_image *b)
{
    tone_image ta, tb;
    rayo_error err = RAYO_ERROR_INIT(RAYO_LANG_EN); /* not shown */
    int same;
    if (a == NULL || b == NULL || a->info.width != b->info.width ||
        a->info.height != b->info.height)
        return 0;
    if (tone_image_make(a, 3, &ta, &err) != RAYO_OK)
        return 0;
    if (tone_image_make(b, 3, &tb, &err) != RAYO_OK) {
        tone_image_free(&ta);
        return 0;
    }
    same = memcmp(ta.v, tb.v, (size_t)ta.width * ta.height * 3) == 0;
    tone_image_free(&ta);
    tone_image_free(&tb);
    return same;
}

void rayo_compare_note_kinds(rayo_compare_report *report,
                             const rayo_image *reference,
                             const rayo_image *image,
                             rayo_course_exercise reference_course)
{
    report->reference_picture = RAYO_PICTURE_UNKNOWN;
    report->image_picture = RAYO_PICTURE_UNKNOWN;
    report->reference_is_course = reference_course < RAYO_COURSE_EXERCISES;
    report->reference_course =
        report->reference_is_course ? reference_course
                                    : (rayo_course_exercise)0;
    if (report->image_lossy_levels > 0)
        return;
    report->reference_picture = rayo_picture_kind_of(reference);
    report->image_picture = rayo_picture_kind_of(image);
}

/* The picture's kind as the note says it. */
static const char *kind_words(rayo_lang lang, rayo_picture_kind kind)
{
    switch (kind) {
    case RAYO_PICTURE_BILEVEL:
        /* TRANSLATORS: "your image is black and white" */
        return rayo_gettext(lang, "black and white");
    case RAYO_PICTURE_GRAY:
        /* TRANSLATORS: "your image is gray" */
        return rayo_gettext(lang, "gray");
    default:
        /* TRANSLATORS: "your image is in colour" */
        return rayo_gettext(lang, "in colour");
    }
}

static int kinds_differ(const rayo_compare_report *r)
{
    return r->reference_picture != RAYO_PICTURE_UNKNOWN &&
           r->image_picture != RAYO_PICTURE_UNKNOWN &&
           r->reference_picture != r->image_picture;
}

void cmp_put_kinds(cmp_sink *s, const rayo_compare_report *r)
{
    const rayo_course_info *shown, *guess;
    if (!kinds_differ(r))
        return;
    shown = rayo_course_info_of(r->reference_course);
    guess = rayo_course_info_of(
        rayo_picture_kind_exercise(r->image_picture));
    if (r->reference_is_course && shown != NULL && guess != NULL)
        cmp_put(s, "note: your image is %s; this reference is exercise "
                   "%d's %s (course:%s): is your image exercise %d's? "
                   "Compare it with course:%s\n",
                kind_words(s->lang, r->image_picture), shown->number,
                rayo_gettext(s->lang, shown->picture),
                shown->name, guess->number, guess->name);
    else
        cmp_put(s, "note: your image is %s and the reference is %s: are they "
                   "pictures of the same exercise? A black and white picture "
                   "is exercise 1's, a gray one exercise 2's, a colour one "
                   "exercise 3's\n",
                kind_words(s->lang, r->image_picture),
                kind_words(s->lang, r->reference_picture));
}

void cmp_put_kinds_json(cmp_sink *s, const rayo_compare_report *r)
{
    if (!kinds_differ(r))
        return;
    cmp_json(s, ", \"kinds\": {\"reference\": \"%s\", \"image\": \"%s\"",
            rayo_picture_kind_name(r->reference_picture),
            rayo_picture_kind_name(r->image_picture));
    if (r->reference_is_course)
        cmp_json(s, ", \"reference_course\": \"%s\"",
                rayo_course_name(r->reference_course));
    cmp_json(s, "}");
}
