#pragma once
/** MROLR_SIMD_CLONES before a function with a hot loop: GCC on x86-64 compiles it twice, for AVX2
 * and for the baseline, and picks the clone at load time from what the CPU has (GCC's
 * target_clones). The AVX2 clone does not fuse multiply-adds (FMA is a target of its own), so both
 * clones give the same results to the bit. Elsewhere it is empty and the loop is compiled once. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && defined(__linux__)
#define MROLR_SIMD_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define MROLR_SIMD_CLONES
#endif
