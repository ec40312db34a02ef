#pragma once
// A row as the user wrote it, as text computed from its type: "Idle + go [ready] / start = Busy".
// Errors about a row carry it (bsc::error::as_written), so that the row at fault can be found
// by reading it. What the type does not hold is written generically: an unnamed guard is
// "[guard]", an unnamed action "/ action", a timeout "after(...)" (its delay is a value).
// Only rejected charts compute it.

#include <cstddef>
#include <string_view>

#include <bsc/detail/fixed_string.hpp>
#include <bsc/detail/type_name.hpp>
#include <bsc/dsl/named.hpp>
#include <bsc/event_name.hpp>
#include <bsc/dsl/row.hpp>

namespace bsc::detail {

// The writers run twice: once counting characters, once filling a fixed_string of that size.
struct text_counter {
    std::size_t size = 0;
    constexpr void operator()(std::string_view s) { size += s.size(); }
};
template <std::size_t N>
struct text_filler {
    fixed_string<N>* out;
    std::size_t at = 0;
    constexpr void operator()(std::string_view s) {
        for (char const c : s) out->chars[at++] = c;
    }
};

// Operator precedence of a guard expression, for parentheses: || below && below !.
enum class guard_precedence { any, disjunction, conjunction, negation };

// The name a guard or an action carries in its type (bsc::named<"text">), or "" if none: a
// named guard or action derives from its static_name, and a named plain callable sits in the
// guard_fn, action_fn or state_action that wraps it (member fn).
template <class T>
constexpr std::string_view static_name_of() {
    if constexpr (names_itself<T>)
        return T::name;
    else if constexpr (requires { &T::fn; })
        return static_name_of<decltype(T::fn)>();
    else
        return {};
}

// A guard part: its name if it has one, else "guard" (compositions are specialised below).
template <class G>
struct guard_words {
    template <class Out>
    static constexpr void write(Out& out, guard_precedence) {
        out(static_name_of<G>().empty() ? std::string_view{"guard"} : static_name_of<G>());
    }
};
template <class S>
struct guard_words<in_guard<S>> {  // bsc::in<S>: "In(S)", as the exports write it
    template <class Out>
    static constexpr void write(Out& out, guard_precedence) {
        out("In(");
        out(name_of<S>);
        out(")");
    }
};
template <class G>
struct guard_words<not_guard<G>> {
    template <class Out>
    static constexpr void write(Out& out, guard_precedence) {
        out("!");
        guard_words<G>::write(out, guard_precedence::negation);
    }
};
template <class L, class R>
struct guard_words<and_guard<L, R>> {
    template <class Out>
    static constexpr void write(Out& out, guard_precedence outer) {
        bool const parens = outer > guard_precedence::conjunction;
        if (parens) out("(");
        guard_words<L>::write(out, guard_precedence::conjunction);
        out(" && ");
        guard_words<R>::write(out, guard_precedence::conjunction);
        if (parens) out(")");
    }
};
template <class L, class R>
struct guard_words<or_guard<L, R>> {
    template <class Out>
    static constexpr void write(Out& out, guard_precedence outer) {
        bool const parens = outer > guard_precedence::disjunction;
        if (parens) out("(");
        guard_words<L>::write(out, guard_precedence::disjunction);
        out(" || ");
        guard_words<R>::write(out, guard_precedence::disjunction);
        if (parens) out(")");
    }
};

template <class A>
struct action_words {
    template <class Out>
    static constexpr void write(Out& out) {
        out(static_name_of<A>().empty() ? std::string_view{"action"} : static_name_of<A>());
    }
};
template <class A>
struct action_words<state_action<A>> : action_words<A> {};
template <>
struct action_words<defer_action> {
    template <class Out>
    static constexpr void write(Out& out) {
        out("defer");
    }
};
template <class... As>
struct action_words<action_seq<As...>> {
    template <class Out>
    static constexpr void write(Out& out) {
        bool first = true;
        ((out(first ? "(" : ", "), action_words<As>::write(out), first = false), ...);
        out(")");
    }
};

template <class Row>
struct row_words;

// An event as written: its name; a completion event as `done<S>`, with S's name.
template <class E>
struct event_words {
    template <class Out>
    static constexpr void write(Out& out) {
        out(name_of<E>);
    }
};
template <class S>
struct event_words<done<S>> {
    template <class Out>
    static constexpr void write(Out& out) {
        out("done<");
        out(name_of<S>);
        out(">");
    }
};

template <class S, class Trigger, class G, class A, class T>
struct row_words<transition_row<S, Trigger, G, A, T>> {
    template <class Out>
    static constexpr void write(Out& out) {
        out(name_of<S>);
        if constexpr (std::is_same_v<Trigger, timeout_trigger>) {
            out(" + after(...)");
        } else if constexpr (!std::is_same_v<Trigger, eventless_trigger>) {
            out(" + ");
            event_words<typename Trigger::event>::write(out);
        }
        if constexpr (!std::is_same_v<G, no_guard>) {
            out(" [");
            guard_words<G>::write(out, guard_precedence::any);
            out("]");
        }
        if constexpr (!std::is_same_v<A, no_action>) {
            out(" / ");
            action_words<A>::write(out);
        }
        if constexpr (target_parts<T>::all::size > 1) {
            out(" = targets(");
            // clang-format off
            [&]<class... Targets>(type_list<Targets...>) {
                bool first = true;
                ((out(first ? "" : ", "), out(name_of<Targets>), first = false), ...);
            }(typename target_parts<T>::all{});
            // clang-format on
            out(")");
        } else if constexpr (target_parts<T>::local) {
            out(" = local(");
            out(name_of<typename target_parts<T>::state>);
            out(")");
        } else if constexpr (!std::is_same_v<T, no_target>) {
            out(" = ");
            out(name_of<T>);
        }
    }
};
template <class S, class A>
struct row_words<entry_row<S, A>> {
    template <class Out>
    static constexpr void write(Out& out) {
        out(name_of<S>);
        out(" + on_entry / ");
        action_words<A>::write(out);
    }
};
template <class S, class A>
struct row_words<initial_row<S, A>> {
    template <class Out>
    static constexpr void write(Out& out) {
        out(name_of<S>);
        out(" + on_initial / ");
        action_words<A>::write(out);
    }
};
template <class S, class A>
struct row_words<exit_row<S, A>> {
    template <class Out>
    static constexpr void write(Out& out) {
        out(name_of<S>);
        out(" + on_exit / ");
        action_words<A>::write(out);
    }
};

template <class Row>
constexpr std::size_t row_text_size() {
    text_counter count;
    row_words<Row>::write(count);
    return count.size;
}

/// The text of a row, e.g. "Idle + go [ready] = Busy".
template <class Row>
constexpr auto row_text() {
    fixed_string<row_text_size<Row>() + 1> text{};
    text_filler<row_text_size<Row>() + 1> fill{&text};
    row_words<Row>::write(fill);
    return text;
}

}  // namespace bsc::detail
