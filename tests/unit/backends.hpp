#pragma once
// The two back ends as test-case parameters. A case about the shared interface or the
// semantics runs against both:
//
//   TEST_CASE_TEMPLATE("...", Backend, bsc_test::compiled, bsc_test::table) {
//       bsc_test::machine_t<Backend, decltype(chart)> m{chart, context{}};
//       ...
//   }
//
// and doctest names the instances "...<compiled>" and "...<table>".

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>
#include <bsc/table/machine.hpp>

namespace bsc_test {

/// bsc::machine, the compiled back end.
struct compiled {
    template <class Chart, class Policy = bsc::default_policy, class Observer = bsc::no_observer>
    using machine = bsc::machine<Chart, Policy, Observer>;

    /// The machine that `bsc::machine{arguments...}` declares: its type comes from the
    /// deduction guides, as in user code.
    template <class... Arguments>
    static constexpr auto deduce(Arguments const&... arguments) {
        return bsc::machine{arguments...};
    }
};

/// bsc::table::machine, the table-driven back end.
struct table {
    template <class Chart, class Policy = bsc::default_policy, class Observer = bsc::no_observer>
    using machine = bsc::table::machine<Chart, Policy, Observer>;

    template <class... Arguments>
    static auto deduce(Arguments const&... arguments) {
        return bsc::table::machine{arguments...};
    }
};

template <class Backend, class Chart, class Policy = bsc::default_policy, class Observer = bsc::no_observer>
using machine_t = typename Backend::template machine<Chart, Policy, Observer>;

}  // namespace bsc_test

TYPE_TO_STRING_AS("compiled", bsc_test::compiled);
TYPE_TO_STRING_AS("table", bsc_test::table);
