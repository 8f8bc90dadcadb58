/* test_exact_batch_wide.c: test_exact_batch.c with the AVX-512 build (avx512_copy.c, eight
 * lanes a vector) as its tallied copy: on a processor with AVX-512F its vectors must do the
 * releases from rest, moving librations and rotations, with the scalar code's bits; elsewhere
 * the core's own calls are checked and the line printed says that the copy did not run. */
#define EXACT_TEST_WIDE 1
#include "test_exact_batch.c"
