/*
 * status.h - how every rayo library function reports failure.
 *
 * The library never prints and never exits.  A function that can fail
 * returns a rayo_status and, when the caller passes a rayo_error, fills it
 * with a one-line, human-readable message that names what was wrong and
 * where (a file and byte offset, an option and its value).  The command
 * line tool decides what to print and which exit status to use; the
 * status tells it which kind of failure happened.
 */
#ifndef RAYO_STATUS_H
#define RAYO_STATUS_H

#include "rayo/export.h"

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
    char message[RAYO_ERROR_MESSAGE_SIZE];
} rayo_error;

/* A short, static description of a status ("malformed input", ...). */
RAYO_API const char *rayo_status_string(rayo_status status);

/*
 * Records a failure in err (when err is not NULL) and returns status, so
 * library code can write `return rayo_error_set(err, RAYO_ERR_IO, ...)`.
 */
RAYO_API rayo_status rayo_error_set(rayo_error *err, rayo_status status,
                                    const char *format, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Resets err to RAYO_OK with an empty message. */
RAYO_API void rayo_error_clear(rayo_error *err);

#ifdef __cplusplus
}
#endif

#endif
