/*
 * lang_id.h - rayo_lang, the languages rayo writes human text in, as a
 * value and nothing more.
 *
 * Kept apart from lang.h (the lookup of translations, the environment's
 * choice) so that status.h can say which language an error's message is
 * written in without including the lookup, which itself reports its
 * failures through status.h.  Include lang.h, not this, to use a
 * language.  Valid C99.
 */
#ifndef RAYO_LANG_ID_H
#define RAYO_LANG_ID_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rayo_lang {
    RAYO_LANG_EN = 0, /* English: the sources' own text */
    RAYO_LANG_ES      /* Spanish (rioplatense): po/es.po */
} rayo_lang;
#define RAYO_LANG_COUNT 2

#ifdef __cplusplus
}
#endif

#endif
