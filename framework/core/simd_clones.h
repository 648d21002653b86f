#pragma once

// Prepare-time loops compiled for the baseline x86-64 and again for AVX2 and AVX-512, the widest
// the processor has chosen at load time (the compilers' target_clones; elsewhere one plain
// function). Every clone must give the same numbers bit for bit, or a scene would render
// differently on another machine: no contraction of a product and a sum into a fused
// multiply-add (AVX-512 has them, the baseline has not), and no reduction whose order depends
// on the vector width (write sums in fixed lanes). GCC takes the first through the attribute,
// Clang through FITFEEL_NO_FP_CONTRACT, which opens the body of every such function. GCC also
// takes no-trapping-math there: without it a comparison that selects a value (x > 0 ? a : 0)
// stays a branch, the loop scalar; it changes no value, only which exceptions may be raised.
// That attribute also keeps GCC from inlining into a clone a function compiled without it:
// std::min or std::max in a clone's loop is a call per element and the loop scalar (the cylinder's
// ChunkMinima runs 5.8 times slower so). Write a minimum as its select,
// d < h ? d : h, which is what std::min(h, d) computes.
//
// Not under the sanitizers (their builds check behaviour, not speed): the load-time choice runs
// before ThreadSanitizer's runtime is up and crashes it.
#if defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define FITFEEL_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define FITFEEL_SANITIZED 1
#endif

#if defined(FITFEEL_SANITIZED)
#define FITFEEL_SIMD_CLONES
#define FITFEEL_NO_FP_CONTRACT
#elif defined(__x86_64__) && defined(__clang__)
#define FITFEEL_SIMD_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#define FITFEEL_NO_FP_CONTRACT _Pragma("clang fp contract(off)")
#elif defined(__x86_64__) && defined(__GNUC__)
#define FITFEEL_SIMD_CLONES                                   \
  __attribute__((target_clones("avx512f", "avx2", "default"), \
                 optimize("fp-contract=off", "no-trapping-math")))
#define FITFEEL_NO_FP_CONTRACT
#else
#define FITFEEL_SIMD_CLONES
#define FITFEEL_NO_FP_CONTRACT
#endif
