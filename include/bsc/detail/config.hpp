#pragma once
// How bsc spells what compilers spell differently: the attributes that steer inlining, the
// built-ins it uses where the standard spelling costs compile time, the signature a type's name
// is read from, and the part of <chrono> it includes. Every such spelling is here and nowhere
// else. GCC and Clang get the spellings bsc's instruction counts and compile times were
// measured with (docs/performance.md); any other compiler gets the standard spelling, or
// nothing where an optimisation hint has none (the same behaviour, possibly slower code).

#include <version>  // defines __GLIBCXX__ where the standard library is libstdc++

// ---- inlining ------------------------------------------------------------------------------------
// BSC_DETAIL_ALWAYS_INLINE: the function is inlined wherever it is called.
// BSC_DETAIL_NOINLINE: the function is never inlined.
// BSC_DETAIL_FLATTEN: every call in the function's body is inlined into it, whatever the
//   inlining budget (GCC: and every call below those; Clang: only the calls written in the body).
//   Nothing where the build optimises for size (-Os, __OPTIMIZE_SIZE__): a flattened firing copies
//   every exit and entry path into each event's function (docs/performance.md, "A firing is one
//   flattened function").
// BSC_DETAIL_WALK_INLINE: on the functions and lambdas of the compiled back end's walk of the
//   configuration, which a flattened firing is made of. Under GCC, whose `flatten` reaches
//   every call below, it adds nothing; under Clang the walk's functions are always inlined
//   themselves (docs/performance.md, rule "Walk inlined under Clang"). In the GNU spelling,
//   which a lambda takes after its parameters.
// BSC_DETAIL_VISIT_INLINE: on the functions that hand a context's fields to a visitor. Clang 14
//   leaves the visit out of line unless told; GCC 12 inlines it where that pays, and forced,
//   costs more (docs/performance.md, rule "Fields visited without a tuple").
#if defined(__GNUC__) || defined(__clang__)
#define BSC_DETAIL_ALWAYS_INLINE [[gnu::always_inline]]
#define BSC_DETAIL_NOINLINE [[gnu::noinline]]
#if defined(__OPTIMIZE_SIZE__)
#define BSC_DETAIL_FLATTEN
#else
#define BSC_DETAIL_FLATTEN [[gnu::flatten]]
#endif
#else
#define BSC_DETAIL_ALWAYS_INLINE
#define BSC_DETAIL_NOINLINE
#define BSC_DETAIL_FLATTEN
#endif
#if defined(__clang__)
#define BSC_DETAIL_WALK_INLINE __attribute__((always_inline))
#define BSC_DETAIL_VISIT_INLINE [[gnu::always_inline]]
#else
#define BSC_DETAIL_WALK_INLINE
#define BSC_DETAIL_VISIT_INLINE
#endif

// ---- what the optimiser is told ------------------------------------------------------------------
// BSC_DETAIL_ASSUME(cond): the optimiser may take cond as true (a statement; cond is not
//   evaluated and must hold, or the behaviour is undefined). bsc calls it through
//   detail::assume (detail/assume.hpp), which checks cond instead in builds without NDEBUG.
// BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS: 1 where the optimiser follows an assumption through
//   later tests, past the joins of paths (GCC); 0 where it drops it at the first join (Clang),
//   or is not known to keep it: there bsc stores what it would have assumed (detail/runtime/run_control.hpp).
#if defined(__clang__)
#define BSC_DETAIL_ASSUME(cond) __builtin_assume(cond)
#define BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS 0
#elif defined(__GNUC__)
#define BSC_DETAIL_ASSUME(cond)               \
    do {                                      \
        if (!(cond)) __builtin_unreachable(); \
    } while (false)
#define BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS 1
#elif defined(_MSC_VER)
#define BSC_DETAIL_ASSUME(cond) __assume(cond)
#define BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS 0
#else
#define BSC_DETAIL_ASSUME(cond) static_cast<void>(sizeof(cond))
#define BSC_DETAIL_ASSUMPTION_SURVIVES_JOINS 0
#endif

// ---- type traits as built-ins ----------------------------------------------------------------------
// BSC_DETAIL_IS_SAME(A, B), BSC_DETAIL_IS_BASE_OF(Base, Derived), BSC_DETAIL_IS_CLASS(T): the
// values of std::is_same_v, std::is_base_of_v and std::is_class_v, as the compiler's built-ins
// where it has them: a built-in instantiates no class template, which a chart's analysis would
// otherwise do once per pair of types it compares (docs/performance.md,
// rule "No template per lookup").
#if defined(__GNUC__) || defined(__clang__)
#define BSC_DETAIL_TRAIT_BUILTINS 1
#elif defined(__has_builtin)
#if __has_builtin(__is_same) && __has_builtin(__is_base_of) && __has_builtin(__is_class)
#define BSC_DETAIL_TRAIT_BUILTINS 1
#endif
#endif
#if defined(BSC_DETAIL_TRAIT_BUILTINS)
#define BSC_DETAIL_IS_SAME(A, B) __is_same(A, B)
#define BSC_DETAIL_IS_BASE_OF(Base, Derived) __is_base_of(Base, Derived)
#define BSC_DETAIL_IS_CLASS(T) __is_class(T)
#else
#include <type_traits>
#define BSC_DETAIL_IS_SAME(A, B) (std::is_same_v<A, B>)
#define BSC_DETAIL_IS_BASE_OF(Base, Derived) (std::is_base_of_v<Base, Derived>)
#define BSC_DETAIL_IS_CLASS(T) (std::is_class_v<T>)
#endif
// BSC_DETAIL_TYPE_PACK_ELEMENT(I, Ts...): the I-th of Ts, a built-in where the compiler has one
// (Clang), for detail::at: the lookup by overload resolution among every element that it
// replaces took Clang 5 ms per row of a 200-row chart.
#if defined(__has_builtin)
#if __has_builtin(__type_pack_element)
#define BSC_DETAIL_TYPE_PACK_ELEMENT(I, ...) __type_pack_element<I, __VA_ARGS__>
#endif
#endif
// BSC_DETAIL_BASES_OF(T): GCC's __bases, every base class of class T as a pack, so that the
// event families (detail/model/event_families.hpp) ask each event of its own bases, not of every
// other event: GCC takes 1.7 s for the 250,000 pairs of a chart of 500 events. Clang has no
// __bases, and asks the pairs in a tenth of the time.
#if defined(__GNUC__) && !defined(__clang__)
#define BSC_DETAIL_BASES_OF(T) __bases(T)
#endif

// ---- names -----------------------------------------------------------------------------------------
// BSC_DETAIL_FUNCTION_SIGNATURE: the enclosing function's signature, with its template arguments
// spelled out, from which detail/type_name.hpp reads a type's name and detail/member_names.hpp a
// member's. Its parsing knows GCC's and Clang's format; under another compiler names are not
// read correctly.
#if defined(__GNUC__) || defined(__clang__)
#define BSC_DETAIL_FUNCTION_SIGNATURE __PRETTY_FUNCTION__
#elif defined(_MSC_VER)
#define BSC_DETAIL_FUNCTION_SIGNATURE __FUNCSIG__
#else
#define BSC_DETAIL_FUNCTION_SIGNATURE __func__
#endif

// ---- diagnostics -----------------------------------------------------------------------------------
// BSC_DETAIL_PRINTS_STRING_ARGUMENTS: 1 where the compiler shows a string held by a template
// argument as text in its errors (GCC), so that an error can show a row as written; 0 where it
// shows numbers (Clang) or is not known to, and the text is not computed.
// BSC_DETAIL_DECLARED_ONLY_BEGIN, BSC_DETAIL_DECLARED_ONLY_END: around code that names a
// variable template declared and never defined, in constant expressions only (the objects whose
// members' addresses name the members): Clang warns of the missing definition, which is never
// needed.
#if defined(__GNUC__) && !defined(__clang__)
#define BSC_DETAIL_PRINTS_STRING_ARGUMENTS 1
#else
#define BSC_DETAIL_PRINTS_STRING_ARGUMENTS 0
#endif
#if defined(__clang__)
#define BSC_DETAIL_DECLARED_ONLY_BEGIN                                                                \
    _Pragma("clang diagnostic push") _Pragma("clang diagnostic ignored \"-Wundefined-var-template\"") \
        _Pragma("clang diagnostic ignored \"-Wundefined-internal\"")
#define BSC_DETAIL_DECLARED_ONLY_END _Pragma("clang diagnostic pop")
#else
#define BSC_DETAIL_DECLARED_ONLY_BEGIN
#define BSC_DETAIL_DECLARED_ONLY_END
#endif

// ---- the standard library --------------------------------------------------------------------------
// BSC_DETAIL_CHRONO_HEADER: the header detail/chrono.hpp includes for durations, time points and
// clocks. libstdc++ keeps them in <bits/chrono.h>, without the calendars, time zones and
// formatting that its C++20 <chrono> brings (0.17 s of CPU in every translation unit that
// includes bsc: docs/performance.md, rule "Headers include only what bsc uses"); any other
// library gets <chrono>.
#if defined(__GLIBCXX__) && defined(__has_include)
#if __has_include(<bits/chrono.h>)
#define BSC_DETAIL_CHRONO_HEADER <bits/chrono.h>
#endif
#endif
#if !defined(BSC_DETAIL_CHRONO_HEADER)
#define BSC_DETAIL_CHRONO_HEADER <chrono>
#endif
