/*
 * status.h - how every rayo library function reports failure.
 *
 * The library never prints and never exits.  A function that can fail
 * returns a rayo_status and, when the caller passes a rayo_error, fills it
 * with a one-line, human-readable message that names what was wrong and
 * where (a file and byte offset, an option and its value).  The command
 * line tool decides what to print and which exit status to use; the
 * status tells it which kind of failure happened.  The caller also says
 * which language the message is to be written in (rayo_error_init):
 * the library has no language of its own.
 */
#ifndef RAYO_STATUS_H
#define RAYO_STATUS_H

#include "rayo/export.h"
#include "rayo/lang_id.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rayo_status {
    RAYO_OK = 0,
    RAYO_ERR_INVALID, /* a value outside what is accepted (bad argument) */
    RAYO_ERR_FORMAT,  /* input data that is malformed, truncated or lying */
    RAYO_ERR_LIMIT,   /* input that exceeds a documented limit */
    RAYO_ERR_NOMEM,   /* memory could not be allocated */
    RAYO_ERR_IO,      /* the operating system refused a read or write */
    RAYO_ERR_PIPE,    /* the reader of our output went away (EPIPE) */
    RAYO_ERR_CANCELLED /* the caller asked the operation to stop */
} rayo_status;

/* Room for one line naming a file, a position and what was expected. */
#define RAYO_ERROR_MESSAGE_SIZE 512

typedef struct rayo_error {
    rayo_status status;
    rayo_lang lang; /* the language of message, chosen by the caller */
    char message[RAYO_ERROR_MESSAGE_SIZE];
} rayo_error;

/*
 * An error that holds no failure yet and will be written in lang:
 * `rayo_error err = RAYO_ERROR_INIT(cli_lang());`.  Every rayo_error is
 * initialised before a library call may fill it (its language is read);
 * a zero-initialised one is English.
 */
#define RAYO_ERROR_INIT(lang) {RAYO_OK, (lang), ""}

/* The same as RAYO_ERROR_INIT, for an error already in memory. */
RAYO_API void rayo_error_init(rayo_error *err, rayo_lang lang);

/* The language err is written in; English when err is NULL.  Library
   code that reports through an error of its own, then copies the
   message into the caller's, initialises its own with this. */
RAYO_API rayo_lang rayo_error_lang(const rayo_error *err);

/* A short, static description of a status ("malformed input", ...). */
RAYO_API const char *rayo_status_string(rayo_status status);

/*
 * Records a failure in err (when err is not NULL) and returns status, so
 * library code can write `return rayo_error_set(err, RAYO_ERR_IO, ...)`.
 * format is English and is looked up in err's language (rayo_gettext)
 * before it is used; in a language whose decimal separator is not '.',
 * the numbers of its floating-point conversions (%g, %f, ...) are
 * written with that language's separator.
 */
RAYO_API rayo_status rayo_error_set(rayo_error *err, rayo_status status,
                                    const char *format, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Resets err to RAYO_OK with an empty message; its language stays. */
RAYO_API void rayo_error_clear(rayo_error *err);

#ifdef __cplusplus
}
#endif

#endif
