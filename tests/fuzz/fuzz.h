/* fuzz.h: what the fuzzing harnesses share: the libFuzzer entry points and an invariant check. */
#ifndef RAYTRA_FUZZ_H
#define RAYTRA_FUZZ_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

/* Stops with a message when an invariant of a loaded scene or mesh does not hold: the
 * abort is what libFuzzer (or driver.c) reports as a crash, with the input that caused it. */
#define FUZZ_CHECK(cond)                                                                           \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            fprintf(stderr, "%s:%d: invariant failed: %s\n", __FILE__, __LINE__, #cond);           \
            abort();                                                                               \
        }                                                                                          \
    } while (0)

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#endif
