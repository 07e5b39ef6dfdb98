/* The spatial dimension of the build: the one place it is set (CMake FSI_DIM). */
#ifndef FSI_DIM_H
#define FSI_DIM_H

#ifndef FSI_DIM
#define FSI_DIM 2
#endif

#if FSI_DIM != 2 && FSI_DIM != 3
#error "FSI_DIM must be 2 or 3"
#endif

#endif
