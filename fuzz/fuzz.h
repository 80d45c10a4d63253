/*
 * fuzz.h - what every fuzz target (fuzz/fuzz_*.c) and the replay driver
 * (fuzz/replay.c) share: libFuzzer's entry point, declared so that the
 * targets build clean under -Wmissing-prototypes with gcc as well, and
 * the check each target makes of a refusal.
 *
 * A target is one file defining LLVMFuzzerTestOneInput.  `make fuzz`
 * links it with libFuzzer (clang -fsanitize=fuzzer,address,undefined);
 * `make check` links it with replay.c instead and runs it on every file
 * of fuzz/corpus/<target>/ and fuzz/regression/<target>/.  Not a test
 * framework: a target reports a broken promise by aborting.
 */
#ifndef RAYO_FUZZ_H
#define RAYO_FUZZ_H

#include <stddef.h>
#include <stdint.h>

#include "rayo.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/*
 * Aborts unless a failed call kept the library's promise: a status other
 * than RAYO_OK, and one non-empty line of message.
 */
void fuzz_check_refusal(rayo_status status, const rayo_error *err);

#endif
