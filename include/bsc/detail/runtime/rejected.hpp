#pragma once
// A machine declared on a chart that failed its checks (detail::rejected_chart): the chart's
// errors are already reported where the chart is declared, so the machine accepts whatever
// the program does with it and does nothing, instead of burying the chart's errors under
// errors of its own. Both back ends specialise their machine on it.

#include <cstddef>
#include <exception>
#include <type_traits>

#include <bsc/chart_ref.hpp>
#include <bsc/duration.hpp>
#include <bsc/error.hpp>
#include <bsc/outcome.hpp>

namespace bsc::detail {

// Declared on `decltype(chart)` or on `bsc::chart_ref<chart>` (whose chart_type is the chart's
// type), alike: either way the chart's own errors are the only ones.
template <class Chart>
concept rejected = is_rejected_chart<std::remove_cv_t<Chart>> ||
    (is_chart_ref<std::remove_cv_t<Chart>>&& is_rejected_chart<typename std::remove_cv_t<Chart>::chart_type>);

template <class Chart>
class inert_machine {
public:
    using chart_type = std::remove_cv_t<Chart>;
    using context_type = typename chart_type::context_type;
    static constexpr std::size_t queue_capacity = 0;

    template <class... Arguments>
    constexpr explicit inert_machine(Arguments const&...) {}

    template <class... Arguments>
    constexpr outcome dispatch(Arguments const&...) {
        return outcome::ignored;
    }
    template <class... Arguments>
    constexpr outcome dispatch_by_name(Arguments const&...) {
        return outcome::ignored;
    }
    template <class... Arguments>
    constexpr outcome dispatch_by_number(Arguments const&...) {
        return outcome::ignored;
    }
    template <class... Arguments>
    constexpr auto step(Arguments const&...) {
        return 0;
    }
    template <class... States>
    constexpr bool is() const {
        return false;
    }
    constexpr bool halted() const { return false; }
    constexpr outcome last_outcome() const { return outcome::ignored; }
    std::exception_ptr last_failure() const { return nullptr; }
    constexpr duration now() const { return duration::zero(); }
    constexpr context_type const& context() const { return context_; }  // const, as a machine's

private:
    friend struct access;
    context_type context_{};
};

}  // namespace bsc::detail
