/*
 * scene_lexer.c - splitting a scene file into lines and words, and
 * pointing at them in messages (scene_lexer.h).
 *
 * It knows blanks, newlines and comments, nothing of keywords or numbers:
 * that is scene_file.c's job.
 */
#include "scene_lexer.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "rayo/lang.h"
#include "rayo/scene_file.h"

void scene_lexer_init(scene_lexer *lx, const char *name, const char *text,
                      size_t length, rayo_error *err)
{
    lx->name = name;
    lx->text = text;
    lx->length = length;
    lx->line_start = lx->line_end = lx->pos = 0;
    lx->next_line = 0;
    lx->line = 0;
    lx->err = err;
}

static int is_blank(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/* Finds the end of the line starting at lx->next_line; checks its bytes.
 * memchr, which looks at many bytes at a time, finds the newline, then
 * the NUL byte, if any, before it: a tenth of reading a large scene went
 * to looking at each byte twice here. */
static rayo_status take_line(scene_lexer *lx)
{
    size_t start = lx->next_line, end;
    const char *newline = memchr(lx->text + start, '\n', lx->length - start);
    const char *nul;
    end = newline ? (size_t)(newline - lx->text) : lx->length;
    nul = memchr(lx->text + start, '\0', end - start);
    if (nul != NULL)
        end = (size_t)(nul - lx->text);
    lx->line++;
    lx->line_start = start;
    lx->line_end = end;
    lx->pos = start;
    if (end - start > RAYO_SCENE_MAX_LINE)
        return scene_lexer_fail(lx, RAYO_SCENE_MAX_LINE + 1, RAYO_ERR_LIMIT,
                                "line is longer than %u bytes; expected "
                                "shorter lines",
                                RAYO_SCENE_MAX_LINE);
    if (nul != NULL)
        return scene_lexer_fail(lx, end - start + 1, RAYO_ERR_FORMAT,
                                "found a NUL byte; expected text");
    lx->next_line = end < lx->length ? end + 1 : end;
    return RAYO_OK;
}

rayo_status scene_lexer_next_line(scene_lexer *lx, int *more)
{
    *more = 0;
    while (lx->next_line < lx->length) {
        rayo_status status = take_line(lx);
        if (status != RAYO_OK)
            return status;
        if (scene_lexer_more(lx)) {
            *more = 1;
            return RAYO_OK;
        }
    }
    return RAYO_OK;
}

static void skip_blanks(scene_lexer *lx)
{
    while (lx->pos < lx->line_end && is_blank(lx->text[lx->pos]))
        lx->pos++;
}

int scene_lexer_more(scene_lexer *lx)
{
    skip_blanks(lx);
    return lx->pos < lx->line_end && lx->text[lx->pos] != '#';
}

size_t scene_lexer_column(scene_lexer *lx)
{
    skip_blanks(lx);
    return lx->pos - lx->line_start + 1;
}

/* Bytes that end a word: the blanks and '#'.  (A table: one look-up a
 * byte instead of six comparisons.) */
static int ends_word(unsigned char c)
{
    static const unsigned char table[256] = {
        ['\t'] = 1, ['\v'] = 1, ['\f'] = 1, ['\r'] = 1, [' '] = 1, ['#'] = 1,
    };
    return table[c];
}

int scene_lexer_word(scene_lexer *lx, scene_word *word)
{
    size_t start, pos, end;
    const char *text = lx->text;
    if (!scene_lexer_more(lx))
        return 0;
    start = pos = lx->pos;
    end = lx->line_end;
    while (pos < end && !ends_word((unsigned char)text[pos]))
        pos++;
    lx->pos = pos;
    word->text = lx->text + start;
    word->length = lx->pos - start;
    word->column = start - lx->line_start + 1;
    return 1;
}

int scene_word_is(const scene_word *word, const char *keyword)
{
    size_t i;
    for (i = 0; i < word->length; i++)
        if (word->text[i] != keyword[i]) /* keyword's NUL stops it */
            return 0;
    return keyword[i] == '\0';
}

size_t scene_word_hash(const char *text, size_t length)
{
    unsigned long long h = 14695981039346656037ull;
    size_t i;
    for (i = 0; i < length; i++) {
        h ^= (unsigned char)text[i];
        h *= 1099511628211ull;
    }
    return (size_t)h;
}

const char *scene_word_show(const scene_word *word, char *buffer,
                            size_t size)
{
    size_t n = word->length < 40 ? word->length : 40, i;
    if (size < 48) {
        if (size > 0)
            buffer[0] = '\0';
        return buffer;
    }
    for (i = 0; i < n; i++) {
        unsigned char c = (unsigned char)word->text[i];
        buffer[i] = (c >= 0x20 && c < 0x7f) ? (char)c : '?';
    }
    if (n < word->length) {
        memcpy(buffer + n, "...", 3);
        n += 3;
    }
    buffer[n] = '\0';
    return buffer;
}

rayo_status scene_lexer_fail(const scene_lexer *lx, size_t column,
                             rayo_status status, const char *format, ...)
{
    char message[RAYO_ERROR_MESSAGE_SIZE];
    va_list args;
    va_start(args, format);
    rayo_lang_vformat(rayo_error_lang(lx->err), message, sizeof message,
                      format, args);
    va_end(args);
    return rayo_error_set(lx->err, status, "%s:%lu:%lu: %s", lx->name,
                          lx->line, (unsigned long)column, message);
}
