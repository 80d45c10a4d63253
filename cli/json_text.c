/*
 * json_text.c - strings in the JSON the command writes (grade's --json,
 * the Gradescope results): valid JSON whatever the bytes.
 *
 * Text from outside (a folder name, a compiler's quote of a student's
 * line) may hold control bytes and bytes that are not UTF-8.  Control
 * bytes become JSON escapes; a byte that is not valid UTF-8 becomes
 * U+FFFD, so a strict parser never rejects the document.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli.h"

#include <stdlib.h>
#include <string.h>

void cli_json_string(FILE *stream, const char *s)
{
    fputc('"', stream);
    for (; *s != '\0'; s++) {
        unsigned char ch = (unsigned char)*s;
        size_t n =
            ch >= 0x80 ? cli_utf8_sequence((const unsigned char *)s) : 0;
        if (n > 0) {
            fwrite(s, 1, n, stream);
            s += n - 1;
        } else if (ch >= 0x80)
            fputs("\\ufffd", stream);
        else if (ch == '"' || ch == '\\')
            fprintf(stream, "\\%c", ch);
        else if (ch == '\n')
            fputs("\\n", stream);
        else if (ch == '\t')
            fputs("\\t", stream);
        else if (ch < 0x20 || ch == 0x7f)
            fprintf(stream, "\\u%04x", ch);
        else
            fputc(ch, stream);
    }
    fputc('"', stream);
}

void cli_json_text_line(FILE *stream, const char *s, size_t max)
{
    size_t used = 0;
    char *line = malloc(max + 4);
    if (line == NULL) {
        cli_json_string(stream, "");
        return;
    }
    while (*s != '\0') {
        char text[8];
        size_t columns, n = cli_escape_unit(s, 0, text, &columns);
        size_t length = strlen(text);
        if (used + length > max) {
            memcpy(line + used, "...", 3);
            used += 3;
            break;
        }
        memcpy(line + used, text, length);
        used += length;
        s += n;
    }
    line[used] = '\0';
    cli_json_string(stream, line);
    free(line);
}
