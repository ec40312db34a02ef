#pragma once
// The production cell with its supervisor as an actor: the operator of operation.hpp (who
// switches the controllers on and puts bricks on the feed belt) written as a chart, so that the
// whole cell, supervisor included, is one bsc::system whose actors can run on separate nodes
// (node.cpp, docs/composition.md "Deploying a system across machines").
//
// The supervisor's switch reaches each controller's `on` input through a bsc::fail_safe<false>
// link: a controller that loses its supervisor switches itself off, which stops its motors (the
// exit action of On) and, with history, resumes where it stopped once the supervisor is heard
// again. The supervisor's bricks are part of the simulated world: its links to the feed belt are
// bsc::lossless, like the plant models' own.

#include <array>
#include <cstdint>

#include "cell.hpp"

namespace pcell {

/// When the supervisor offers each brick, after switching the cell on (the same as main.cpp's);
/// further bricks (supervisor_io::bricks) as soon as the feed belt can take them.
inline constexpr std::array<bsc::duration, 5> supervisor_offers{0s, 0s, 2s, 15s, 16s};

struct Supervisor;
struct SvWait;  // waiting for the next brick's time and a free start of the feed belt
struct SvPut;   // a brick is being put on the belt (for one step)

struct supervisor_io {
    bsc::input<bool> start_free;                     // the feed belt's first slots are empty
    bsc::output<bool> on;                            // the controllers' manual switch
    bsc::output<brick> put;                          // a brick put at the start of the feed belt (for one step)
    bsc::timer clock{bsc::duration::max()};          // time since the cell was switched on
    std::uint8_t next = 0;                           // bricks put so far
    std::uint8_t bricks = supervisor_offers.size();  // bricks to put in all

    static constexpr bool due(supervisor_io const& c) {
        auto const at = c.next < supervisor_offers.size() ? supervisor_offers[c.next] : bsc::duration::zero();
        return c.next < c.bricks && c.clock.elapsed() >= at && c.start_free.get();
    }
};

inline constexpr auto supervisor_chart = bsc::make_chart<supervisor_io>(
    bsc::composite<Supervisor>(bsc::initial<SvWait>, bsc::state<SvPut>),
    bsc::state<Supervisor> + bsc::on_entry / bsc::named<"on=1, clock.start()">([](supervisor_io& c) {
                                 c.on.set(true);
                                 c.clock.start();
                             }),
    bsc::state<SvWait>[bsc::named<"due">(bsc::guard([](supervisor_io const& c) { return supervisor_io::due(c); }))] /
        bsc::named<"put=brick(next+1), ++next">([](supervisor_io& c) {
            c.put.set(brick{static_cast<std::uint8_t>(c.next + 1), false});
            ++c.next;
        }) = bsc::state<SvPut>,
    bsc::state<SvPut> / bsc::named<"put=none">([](supervisor_io& c) { c.put.set(brick{}); }) = bsc::state<SvWait>);

using supervisor_actor = bsc::machine<bsc::chart_ref<supervisor_chart>>;

/// The cell's eleven actors: the supervisor, the five controllers, the five plant models.
struct supervised_actors {
    supervisor_actor supervisor{supervisor_chart};
    feed_belt_actor feed_belt{feed_belt_chart};
    table_actor table{table_chart};
    robot_actor robot{robot_chart};
    press_actor press{press_chart};
    deposit_belt_actor deposit_belt{deposit_belt_chart};
    feed_belt_plant env_feed_belt{env_feed_belt_chart};
    table_plant env_table{env_table_chart};
    robot_plant env_robot{env_robot_chart};
    press_plant env_press{env_press_chart};
    deposit_belt_plant env_deposit_belt{env_deposit_belt_chart};
};

/// The supervised cell: the supervisor steps first, then the controllers, then the plant models.
using S = supervised_actors;
using supervised_cell = cell_system<
    S,
    bsc::order<&S::supervisor, &S::feed_belt, &S::table, &S::robot, &S::press, &S::deposit_belt, &S::env_feed_belt,
               &S::env_table, &S::env_robot, &S::env_press, &S::env_deposit_belt>,
    bsc::link<&S::supervisor, &supervisor_io::on, &S::feed_belt, &feed_belt_ctl::on, bsc::fail_safe<false>>,
    bsc::link<&S::supervisor, &supervisor_io::on, &S::table, &table_ctl::on, bsc::fail_safe<false>>,
    bsc::link<&S::supervisor, &supervisor_io::on, &S::robot, &robot_ctl::on, bsc::fail_safe<false>>,
    bsc::link<&S::supervisor, &supervisor_io::on, &S::press, &press_ctl::on, bsc::fail_safe<false>>,
    bsc::link<&S::supervisor, &supervisor_io::on, &S::deposit_belt, &deposit_belt_ctl::on, bsc::fail_safe<false>>,
    bsc::link<&S::supervisor, &supervisor_io::put, &S::env_feed_belt, &feed_belt_io::put, bsc::lossless>,
    bsc::link<&S::env_feed_belt, &feed_belt_io::start_free, &S::supervisor, &supervisor_io::start_free, bsc::lossless>>;

}  // namespace pcell
