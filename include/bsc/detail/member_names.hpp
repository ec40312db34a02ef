#pragma once
// The names of an aggregate's members as its definition spells them, at compile time, without
// macros: the address of a member of an object that is declared but never defined is a constant
// that may be a template argument, and both supported compilers spell that argument in the
// function's signature (BSC_DETAIL_FUNCTION_SIGNATURE) ending with the member's name (GCC 12:
// "{(& object<T>.T::speed)}", Clang 14: "{&object.speed}"). Used by the opt-in parts that show
// or store a context by name (the VCD recorder, the retentive state's layout fingerprint);
// nothing else pays for it.

#include <array>
#include <cstddef>
#include <string_view>
#include <tuple>
#include <utility>

#include <bsc/detail/config.hpp>
#include <bsc/detail/fields.hpp>

namespace bsc::detail {

// Holds the address as a class-type template argument: Clang 14 accepts a pointer to a
// subobject there, but not as a template argument of pointer type.
template <class T>
struct member_address {
    T const* address;
};

BSC_DETAIL_DECLARED_ONLY_BEGIN
// Never defined: only its members' addresses are taken, in constant expressions. T is wrapped so
// that a T without linkage (in an anonymous namespace, or local to a function) may be named: the
// wrapper's linkage is the variable's, and Clang refuses an undefined variable of a type without.
template <class T>
struct declared_object {
    T value;
};
template <class T>
extern declared_object<T> const declared_only;

template <auto Address>
constexpr char const* spelled_address() {
    return BSC_DETAIL_FUNCTION_SIGNATURE;
}

// Identifiers may hold letters beyond ASCII, spelled in UTF-8: every byte of those is >= 0x80.
constexpr bool is_identifier_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           static_cast<unsigned char>(c) >= 0x80;
}

// The last identifier of a signature: the member's name, before the closing brackets.
constexpr std::string_view last_identifier(std::string_view s) {
    std::size_t end = s.size();
    while (end > 0 && !is_identifier_char(s[end - 1])) --end;
    std::size_t begin = end;
    while (begin > 0 && is_identifier_char(s[begin - 1])) --begin;
    return s.substr(begin, end - begin);
}

template <class T, std::size_t I>
constexpr std::string_view member_name_of() {
    constexpr auto& member = std::get<I>(tie_fields(declared_only<T>.value));
    using member_type = std::remove_cvref_t<decltype(member)>;
    return last_identifier(spelled_address<member_address<member_type>{&member}>());
}
BSC_DETAIL_DECLARED_ONLY_END

/// The names of T's members, in declaration order. Requirements: T is an aggregate that
/// detail::tie_fields supports.
template <class T>
// clang-format off
inline constexpr auto member_names = []<std::size_t... I>(std::index_sequence<I...>) {
    return std::array<std::string_view, sizeof...(I)>{member_name_of<T, I>()...};
}(std::make_index_sequence<std::tuple_size_v<decltype(tie_fields(std::declval<T&>()))>>{});
// clang-format on

template <class Class, class Member>
Class class_of_member(Member Class::*);

BSC_DETAIL_DECLARED_ONLY_BEGIN
/// The position of the member that the pointer to member `Member` designates among its
/// aggregate's members (their count if none), found by comparing addresses: GCC 12 does not
/// accept the address that `.*` yields as a template argument.
template <auto Member>
constexpr std::size_t member_index() {
    using Class = decltype(class_of_member(Member));
    // clang-format off
    return []<std::size_t... I>(std::index_sequence<I...>) {
        auto const& object = declared_only<Class>.value;
        void const* const target = &(object.*Member);
        auto const fields = tie_fields(object);
        std::size_t found = sizeof...(I);
        ((static_cast<void const*>(&std::get<I>(fields)) == target ? (found = I, 0) : 0), ...);
        return found;
    }(std::make_index_sequence<member_names<Class>.size()>{});
    // clang-format on
}
/// The name of the member that the pointer to member `Member` designates, e.g. "speed" for
/// `&axis::speed`.
template <auto Member>
constexpr std::string_view member_name() {
    using Class = decltype(class_of_member(Member));
    constexpr std::size_t index = member_index<Member>();
    static_assert(index < member_names<Class>.size(), "the pointer designates no member of the aggregate");
    return member_names<Class>[index];
}
BSC_DETAIL_DECLARED_ONLY_END

}  // namespace bsc::detail
