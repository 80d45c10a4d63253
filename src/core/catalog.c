/*
 * catalog.c - rayo_gettext and rayo_ngettext: a message's translation
 * looked up in the compiled catalogs embedded in the library.
 *
 * A catalog is a GNU .mo file as msgfmt writes it (the gettext manual's
 * "The Format of GNU MO Files"): a header of 32-bit words in either byte
 * order, then a table of the original strings, sorted, and one of their
 * translations.  The lookup is a binary search over the bytes as they
 * are, with no state and no allocation, so any thread may call it in any
 * language.  glibc's gettext is not used: it needs a generated locale
 * and one process-wide language (docs/i18n.md says more).
 */
#include "rayo/lang.h"

#include <string.h>

#include "catalog.h"

#define MO_MAGIC 0x950412deUL

typedef struct mo {
    const unsigned char *data;
    size_t size;
    int swapped;
    unsigned long count, originals, translations;
} mo;

static unsigned long word(const mo *m, size_t offset)
{
    const unsigned char *b = m->data + offset;
    if (m->swapped)
        return (unsigned long)b[0] << 24 | (unsigned long)b[1] << 16 |
               (unsigned long)b[2] << 8 | b[3];
    return (unsigned long)b[3] << 24 | (unsigned long)b[2] << 16 |
           (unsigned long)b[1] << 8 | b[0];
}

/* The catalog of lang, checked; 0 when there is none. */
static int open_catalog(rayo_lang lang, mo *m)
{
    const char *code = rayo_lang_code(lang);
    const rayo_catalog_blob *blob;
    for (blob = rayo_catalog_blobs; blob->code != NULL; blob++)
        if (strcmp(blob->code, code) == 0)
            break;
    if (blob->code == NULL || blob->size < 28)
        return 0;
    m->data = blob->data;
    m->size = blob->size;
    m->swapped = 0;
    if (word(m, 0) != MO_MAGIC) {
        m->swapped = 1;
        if (word(m, 0) != MO_MAGIC)
            return 0;
    }
    m->count = word(m, 8);
    m->originals = word(m, 12);
    m->translations = word(m, 16);
    if (m->originals > m->size || m->translations > m->size ||
        m->count > (m->size - m->originals) / 8 ||
        m->count > (m->size - m->translations) / 8)
        return 0;
    return 1;
}

/* String i of the table at `table` (its length without the final NUL
   into *length); NULL when it does not lie inside the catalog. */
static const char *string_at(const mo *m, unsigned long table,
                             unsigned long i, size_t *length)
{
    unsigned long n = word(m, table + 8 * i);
    unsigned long offset = word(m, table + 8 * i + 4);
    if (offset >= m->size || n >= m->size - offset ||
        m->data[offset + n] != '\0')
        return NULL;
    *length = n;
    return (const char *)m->data + offset;
}

/* The index of msgid among the originals, or -1. */
static long find(const mo *m, const char *msgid)
{
    unsigned long low = 0, high = m->count;
    while (low < high) {
        unsigned long middle = low + (high - low) / 2;
        size_t length;
        const char *original = string_at(m, m->originals, middle, &length);
        int order;
        if (original == NULL)
            return -1;
        /* a plural entry is "singular\0plural": strcmp stops at the
           singular, which is what is looked up */
        order = strcmp(msgid, original);
        if (order == 0)
            return (long)middle;
        if (order < 0)
            high = middle;
        else
            low = middle + 1;
    }
    return -1;
}

/* The plural rule in the header (the translation of ""), or NULL. */
static const char *plural_rule(const mo *m, size_t *length)
{
    static const char key[] = "plural=";
    size_t header_length;
    const char *header, *rule, *end;
    long i = find(m, "");
    if (i < 0 ||
        (header = string_at(m, m->translations, (unsigned long)i,
                            &header_length)) == NULL ||
        (rule = strstr(header, key)) == NULL)
        return NULL;
    rule += sizeof key - 1;
    end = strchr(rule, '\n');
    *length = end ? (size_t)(end - rule) : strlen(rule);
    return rule;
}

const char *rayo_gettext(rayo_lang lang, const char *msgid)
{
    mo m;
    long i;
    size_t length;
    const char *text;
    if (lang == RAYO_LANG_EN || msgid == NULL || *msgid == '\0' ||
        !open_catalog(lang, &m) || (i = find(&m, msgid)) < 0)
        return msgid;
    text = string_at(&m, m.translations, (unsigned long)i, &length);
    return text != NULL && length > 0 ? text : msgid;
}

const char *rayo_ngettext(rayo_lang lang, const char *singular,
                          const char *plural, unsigned long count)
{
    const char *fallback = count == 1 ? singular : plural;
    const char *text, *rule;
    size_t length, rule_length;
    long i, form;
    mo m;
    if (lang == RAYO_LANG_EN || singular == NULL || *singular == '\0' ||
        !open_catalog(lang, &m) || (i = find(&m, singular)) < 0 ||
        (text = string_at(&m, m.translations, (unsigned long)i, &length)) ==
            NULL ||
        (rule = plural_rule(&m, &rule_length)) == NULL ||
        (form = rayo_plural_form(rule, rule_length, count)) < 0)
        return fallback;
    /* the forms follow each other, each ending with a NUL */
    while (form-- > 0) {
        size_t n = strlen(text) + 1;
        if (n > length)
            return fallback;
        text += n;
        length -= n;
    }
    return *text != '\0' ? text : fallback;
}
