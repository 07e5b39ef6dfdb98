/* A function the compiler must inline: a pair loop written once with its options as
 * parameters, which each caller passes as constants, so every copy is specialised
 * (no branch on an option in the loop). */
#ifndef FSI_ALWAYS_INLINE_H
#define FSI_ALWAYS_INLINE_H

#define FSI_ALWAYS_INLINE inline __attribute__((always_inline))

#endif
