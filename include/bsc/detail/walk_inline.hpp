#pragma once
// BSC_DETAIL_WALK_INLINE: on the functions of the compiled back end's walk of the configuration,
// which a flattened microstep is made of. GCC's `flatten` inlines every call below the
// microstep, so there it adds nothing; Clang's inlines only the calls written in the
// microstep's own body, so under Clang the walk's functions are always inlined themselves
// (docs/benchmarks.md, analysis section 16).

#if defined(__clang__)
#define BSC_DETAIL_WALK_INLINE __attribute__((always_inline))
#else
#define BSC_DETAIL_WALK_INLINE
#endif
