#pragma once
// Completion (SCXML's done.state events; the rule is detail/model/completion.hpp): done<S> raised
// when a final state is entered, and for a parallel state once all its regions are final, at the
// moment SCXML raises it; and the exit of every state when the machine halts. Called by the back
// ends as they enter states. A layer of the driver (detail/runtime/driver.hpp).

#include <cstddef>
#include <utility>

#include <bsc/detail/runtime/backend.hpp>
#include <bsc/detail/runtime/deferral.hpp>
#include <bsc/events.hpp>

namespace bsc::detail {

template <class Backend, class Chart, class Policy, class Observer, class Queue>
class done_raising : public deferral<Backend, Chart, Policy, Observer, Queue> {
    using base = deferral<Backend, Chart, Policy, Observer, Queue>;

protected:
    using base::base;
    using typename base::model;
    using typename base::layout;
    using typename base::completion;
    using base::tree;
    using base::root;
    using base::state_count;
    using base::config_;
    using base::queue_;
    using base::entering_;
    using base::backend;
    using base::halted;

    // After the entry actions of final state f: raises done for its parent, and for the
    // parallel state above the parent if every region of it is now in a final state (SCXML's
    // enterStates). A final child of the root raises nothing: the machine halts.
    constexpr void entered_final(int f) {
        if constexpr (completion::raises) {
            int const p = tree.parent[static_cast<std::size_t>(f)];
            if (p == root) return;
            raise_done(p);
            int const g = tree.parent[static_cast<std::size_t>(p)];
            if (tree.kinds[static_cast<std::size_t>(g)] == kind::parallel && !entering(g) && in_final(g)) raise_done(g);
        } else {
            (void)f;
        }
    }

    // The back end is about to enter the regions of parallel state g. Until it has entered them
    // all (regions_entered), a final state entered in a region does not look at the regions
    // after its own, which are not entered yet.
    constexpr void regions_entering(int g) {
        if constexpr (completion::parallel_count > 0) {
            int const n = completion::parallel_number[static_cast<std::size_t>(g)];
            if (n >= 0) entering_.flag[static_cast<std::size_t>(n)] = true;
        } else {
            (void)g;
        }
    }
    // The back end has entered every region of parallel state g: done for g is raised if they are
    // all final and the last was entered through a final state of its own (a composite region),
    // where SCXML raises it, after the last final state entered.
    constexpr void regions_entered(int g) {
        if constexpr (completion::parallel_count > 0) {
            int const n = completion::parallel_number[static_cast<std::size_t>(g)];
            if (n >= 0) {
                entering_.flag[static_cast<std::size_t>(n)] = false;
                if (tree.kinds[static_cast<std::size_t>(last_child(g))] == kind::composite && in_final(g))
                    raise_done(g);
            }
        } else {
            (void)g;
        }
    }

    // Runs the exit actions of every active state, innermost first, when the machine halts
    // (SCXML's exitInterpreter).
    constexpr void halt_if_final() {
        if constexpr (layout::can_halt)
            if (halted()) {
                backend().exit_all();
                queue_.clear();
            }
    }

private:
    constexpr bool entering(int g) const {
        if constexpr (completion::parallel_count > 0) {
            int const n = completion::parallel_number[static_cast<std::size_t>(g)];
            return n >= 0 && entering_.flag[static_cast<std::size_t>(n)];
        } else {
            return (void)g, false;
        }
    }
    static constexpr int last_child(int s) {
        int last = tree.first_child[static_cast<std::size_t>(s)];
        while (tree.next_sibling[static_cast<std::size_t>(last)] >= 0)
            last = tree.next_sibling[static_cast<std::size_t>(last)];
        return last;
    }
    // SCXML's isInFinalState: a composite whose active child is final, a parallel state all of
    // whose regions are.
    constexpr bool in_final(int s) const {
        auto const i = static_cast<std::size_t>(s);
        if (tree.kinds[i] == kind::composite) {
            auto const ordinal = config_.active[static_cast<std::size_t>(tree.slot[i])];
            for (int c = tree.first_child[i]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)])
                if (tree.ordinal[static_cast<std::size_t>(c)] == ordinal)
                    return tree.kinds[static_cast<std::size_t>(c)] == kind::final_state;
            return false;
        }
        if (tree.kinds[i] == kind::parallel) {
            for (int c = tree.first_child[i]; c >= 0; c = tree.next_sibling[static_cast<std::size_t>(c)])
                if (!in_final(c)) return false;
            return true;
        }
        return false;
    }
    // Queues done<S> for state s, if a row takes it.
    constexpr void raise_done(int s) {
        // clang-format off
        [&]<std::size_t... S>(std::index_sequence<S...>) {
            if constexpr (state_count <= max_fold)
                (void)((s == static_cast<int>(S) ? (raise_done_of<S>(), true) : false) || ...);
            else  // (a list: detail::max_fold)
                [[maybe_unused]] bool const raised[] = {(s == static_cast<int>(S) ? (raise_done_of<S>(), true) : false)...};
        }(std::make_index_sequence<state_count>{});
        // clang-format on
    }
    template <std::size_t S>
    constexpr void raise_done_of() {
        if constexpr (completion::trigger[S] >= 0)
            (void)queue_(done<typename model::template tag_at<static_cast<int>(S)>>{});
    }
};

}  // namespace bsc::detail
