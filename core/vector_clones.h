#pragma once
// The clones of a vector kernel: AVX-512 (x86-64-v4), AVX2 with FMA (x86-64-v3) and the
// baseline, one picked at load time for the CPU (GCC's target_clones; docs/performance.md).
// Clang 14 compiles target_clones("arch=...") as its first target alone, without a dispatch:
// AVX-512 instructions on every CPU, SIGILL on one without them. A Clang build (the sanitizer
// stage) takes the baseline alone.

#if defined(__clang__)
#define SHOCKMAP_VECTOR_CLONES
#else
#define SHOCKMAP_VECTOR_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#endif
