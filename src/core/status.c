/*
 * status.c - the messages behind rayo_status and rayo_error.
 *
 * Kept apart so that every layer can report failures the same way.  A
 * message is written in its error's language: the English format of the
 * call is looked up in the embedded catalogs and numbers get the
 * language's decimal separator (rayo_lang_vformat); nothing above core/
 * is reached, so every layer may report through here.
 */
#include "rayo/status.h"

#include <stdarg.h>

#include "rayo/lang.h"

const char *rayo_status_string(rayo_status status)
{
    switch (status) {
    case RAYO_OK: return "success";
    case RAYO_ERR_INVALID: return "invalid argument";
    case RAYO_ERR_FORMAT: return "malformed input";
    case RAYO_ERR_LIMIT: return "input exceeds a limit";
    case RAYO_ERR_NOMEM: return "out of memory";
    case RAYO_ERR_IO: return "input/output error";
    case RAYO_ERR_PIPE: return "the reader of the output went away";
    case RAYO_ERR_CANCELLED: return "cancelled";
    }
    return "unknown status";
}

void rayo_error_init(rayo_error *err, rayo_lang lang)
{
    if (err != NULL) {
        err->status = RAYO_OK;
        err->lang = lang;
        err->message[0] = '\0';
    }
}

rayo_lang rayo_error_lang(const rayo_error *err)
{
    return err != NULL && (unsigned)err->lang < RAYO_LANG_COUNT
               ? err->lang
               : RAYO_LANG_EN;
}

rayo_status rayo_error_set(rayo_error *err, rayo_status status,
                           const char *format, ...)
{
    if (err != NULL) {
        va_list args;
        err->status = status;
        va_start(args, format);
        rayo_lang_vformat(rayo_error_lang(err), err->message,
                          sizeof err->message, format, args);
        va_end(args);
    }
    return status;
}

void rayo_error_clear(rayo_error *err)
{
    if (err != NULL) {
        err->status = RAYO_OK;
        err->message[0] = '\0';
    }
}
