#pragma once
// bsc::fields for Boost.Hana Structs, single-header distribution (needs bsc.hpp beside it, and Boost).
// Generated from include/bsc/adapt/hana.hpp by `python3 scripts/amalgamate.py`.
// Do not edit: change the headers under include/ and regenerate.
#include "bsc.hpp"
// begin include/bsc/adapt/hana.hpp
// The Boost.Hana adapter: a context type adapted as a Hana Struct (BOOST_HANA_DEFINE_STRUCT,
// BOOST_HANA_ADAPT_STRUCT, or accessors of its own) is walked member by member by every part of
// bsc, as an aggregate is: its channels are latched and committed, its timers updated, and its
// members saved (bsc::save), explored, recorded (bsc::vcd_recorder) and sent by their Hana
// names. It is the way for a class with private members, constructors or base classes, or with
// more than the 128 members an aggregate may have:
//
//   #include <bsc/adapt/hana.hpp>                  // before the machine is declared
//   #include <boost/hana/define_struct.hpp>
//
//   class axis {
//   public:
//       explicit axis(int limit) : settle{300ms}, limit{limit} {}
//       bool homed() const { return home.get(); }
//   private:
//       BOOST_HANA_DEFINE_STRUCT(axis, (bsc::input<bool>, home), (bsc::timer, settle), (int, limit));
//       template <class, class>
//       friend struct boost::hana::accessors_impl;  // Hana reads the private accessors
//   };
//
// A class whose members are declared as usual is adapted after it, with
// BOOST_HANA_ADAPT_STRUCT(axis, home, settle, limit) (inherited members may be listed) and, for
// private members, `friend struct boost::hana::accessors_impl<axis>;` in the class. Include this
// header wherever such a context is used: without it a class adapted in public by
// BOOST_HANA_DEFINE_STRUCT is an error (bsc::error::hana_adapter_not_included), but one adapted
// in private or by BOOST_HANA_ADAPT_STRUCT is a leaf bsc does not look into. Link with the CMake
// target bsc::hana (Boost 1.74 or later, headers only); no other part of bsc needs Boost.
//
// Requirements: each accessor returns a reference to its member (not BOOST_HANA_ADAPT_ADT's
// getters, which return copies), and each key is a hana::string, the member's name. Members the
// accessors leave out are not part of the machine's state (bsc::fields).

#include <array>
#include <string_view>
#include <type_traits>

#include <boost/hana/accessors.hpp>
#include <boost/hana/concept/struct.hpp>
#include <boost/hana/first.hpp>
#include <boost/hana/fwd/string.hpp>
#include <boost/hana/second.hpp>
#include <boost/hana/unpack.hpp>


namespace bsc::detail {

// A key's characters, stored once per name.
template <char... C>
inline constexpr char hana_key_chars[] = {C..., '\0'};

template <char... C>
constexpr std::string_view hana_key_name(boost::hana::string<C...> const&) {
    return {hana_key_chars<C...>, sizeof...(C)};
}
template <class Key>
constexpr std::string_view hana_key_name(Key const&) {
    static_assert(sizeof(Key) == 0,
                  "bsc: a member of a Hana Struct in the context is keyed by something other than a "
                  "hana::string; bsc names members by their keys (BOOST_HANA_STRING(\"name\"))");
    return {};
}

// f(), after the error that an accessor returns a copy, so that the error is the only one. A call
// that names the accessors' types: one that named none would be checked, and fail, even where
// the error is not.
template <class... Accessors, class F>
constexpr decltype(auto) call_without_members(F&& f) {
    return static_cast<F&&>(f)();
}

}  // namespace bsc::detail

namespace bsc {

/// Every Boost.Hana Struct: its members are its accessors', named by their keys, in order.
template <class T>
requires boost::hana::Struct<T>::value struct fields<T> {
    static constexpr auto names = boost::hana::unpack(boost::hana::accessors<T>(), [](auto const&... accessor) {
        return std::array<std::string_view, sizeof...(accessor)>{
            detail::hana_key_name(boost::hana::first(accessor))...};
    });

    template <class Self, class F>
    BSC_DETAIL_VISIT_INLINE  // as detail::apply_to_fields (detail/fields.hpp)
        static constexpr decltype(auto)
        apply(Self& self, F&& f) {
        return boost::hana::unpack(boost::hana::accessors<T>(), [&](auto const&... accessor) -> decltype(auto) {
            constexpr bool references = (std::is_lvalue_reference_v<decltype(boost::hana::second(accessor)(self))> &&
                                         ...);
            if constexpr (references) {
                return static_cast<F&&>(f)(boost::hana::second(accessor)(self)...);
            } else {
                static_assert(references,
                              "bsc: an accessor of a Hana Struct in the context returns a copy of its member, not a "
                              "reference; bsc drives and saves the members themselves (BOOST_HANA_DEFINE_STRUCT's "
                              "and BOOST_HANA_ADAPT_STRUCT's return references, BOOST_HANA_ADAPT_ADT's do not)");
                return detail::call_without_members<decltype(accessor)...>(static_cast<F&&>(f));
            }
        });
    }
};

}  // namespace bsc
// end include/bsc/adapt/hana.hpp
