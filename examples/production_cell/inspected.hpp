#pragma once
// The production cell with every actor traced, for the live view in the browser
// (bsc::system_inspector; `production_cell --inspect PORT`). The same charts, links and order as
// the cell of cell.hpp; each machine's observer is a bsc::tracer writing into a ring of its own.

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>

#include <bsc/trace.hpp>
#include <bsc/trace_buffer.hpp>

#include "cell.hpp"

namespace pcell {

/// A machine of `Chart` whose observer is a tracer.
template <auto const& Chart>
using traced_machine =
    bsc::machine<bsc::chart_ref<Chart>, bsc::default_policy, bsc::tracer<std::remove_cvref_t<decltype(Chart)> const>>;

/// The rings the actors' tracers write into, one per actor in the order of traced_actors: 64 KiB
/// each, drained by the inspector at every poll. In static storage: they outlive the actors.
inline std::array<std::array<std::byte, std::size_t{1} << 16>, 10> trace_storage{};
inline std::array<bsc::trace_buffer, 10> trace_rings{
    bsc::trace_buffer{trace_storage[0]}, bsc::trace_buffer{trace_storage[1]}, bsc::trace_buffer{trace_storage[2]},
    bsc::trace_buffer{trace_storage[3]}, bsc::trace_buffer{trace_storage[4]}, bsc::trace_buffer{trace_storage[5]},
    bsc::trace_buffer{trace_storage[6]}, bsc::trace_buffer{trace_storage[7]}, bsc::trace_buffer{trace_storage[8]},
    bsc::trace_buffer{trace_storage[9]}};

/// The actors of basic_actors<true>, each traced into its own ring.
struct traced_actors {
    traced_machine<feed_belt_chart> feed_belt{feed_belt_chart, {}, bsc::tracer{feed_belt_chart, trace_rings[0]}};
    traced_machine<table_chart> table{table_chart, {}, bsc::tracer{table_chart, trace_rings[1]}};
    traced_machine<robot_chart> robot{robot_chart, {}, bsc::tracer{robot_chart, trace_rings[2]}};
    traced_machine<press_chart> press{press_chart, {}, bsc::tracer{press_chart, trace_rings[3]}};
    traced_machine<deposit_belt_chart> deposit_belt{
        deposit_belt_chart, {}, bsc::tracer{deposit_belt_chart, trace_rings[4]}};
    traced_machine<env_feed_belt_chart> env_feed_belt{
        env_feed_belt_chart, {}, bsc::tracer{env_feed_belt_chart, trace_rings[5]}};
    traced_machine<env_table_chart> env_table{env_table_chart, {}, bsc::tracer{env_table_chart, trace_rings[6]}};
    traced_machine<env_robot_chart> env_robot{env_robot_chart, {}, bsc::tracer{env_robot_chart, trace_rings[7]}};
    traced_machine<env_press_chart> env_press{env_press_chart, {}, bsc::tracer{env_press_chart, trace_rings[8]}};
    traced_machine<env_deposit_belt_chart> env_deposit_belt{
        env_deposit_belt_chart, {}, bsc::tracer{env_deposit_belt_chart, trace_rings[9]}};
};

/// The production cell, every actor traced.
using traced_cell = system_of<traced_actors>;

/// Writes the channels, timers and variables of every actor that changed (each tracer's sample).
inline void sample_all(traced_cell& cell) {
    auto& a = cell.actors;
    std::apply([](auto&... actor) { (actor.observer().sample(actor), ...); },
               std::tie(a.feed_belt, a.table, a.robot, a.press, a.deposit_belt, a.env_feed_belt, a.env_table,
                        a.env_robot, a.env_press, a.env_deposit_belt));
}

}  // namespace pcell
