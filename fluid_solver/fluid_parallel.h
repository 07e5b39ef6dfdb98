/* How the fluid's per-particle loops share the threads (every scheme and the shared
 * walls use these). */
#ifndef FSI_FLUID_PARALLEL_H
#define FSI_FLUID_PARALLEL_H

/* Below this many particles the loops run on one thread (a fork costs more than the
 * work; the results are the same either way). */
#define FLUID_PARALLEL_MIN_PARTICLES 128

/* Particles per chunk of the parallel loops, handed out dynamically. The work per
 * particle is far from even: fluid particles come first, wall particles last, and
 * idle walls (verlet_list.h) and most walls' loops do almost nothing, so a static split
 * in halves left one thread with nearly all of it; chunks also let a thread that keeps
 * its core take over from one that lost it to another job. Not smaller: where two
 * chunks meet, their per-particle arrays share cache lines that two threads write (the
 * rows' ends, flags, shape tensors), and with 64 particles a chunk those lines were
 * what kept the operators phase from scaling (docs/performance.md). Every particle's
 * results are computed alone, so they do not depend on which thread takes it. */
#define FLUID_CHUNK 512

#endif
