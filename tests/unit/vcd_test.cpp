// bsc::vcd_recorder (<bsc/vcd.hpp>): the header declares each composite's active child, each
// state, and the context by member name; the first sample dumps every value, later ones only
// what changed, at the machine's time; both back ends write the same file. And the member names
// it relies on (detail::member_names).

#include <doctest/doctest.h>

#include <bsc/bsc.hpp>
#include <bsc/vcd.hpp>

#include <array>
#include <chrono>
#include <cstdint>
#include <locale>
#include <sstream>
#include <string>

#include "backends.hpp"
#include "inside.hpp"

namespace vcd_test {

using namespace std::chrono_literals;

struct go {};
struct stop {};
struct Root;
struct Idle;
struct Work;
struct Feed;
struct Cut;
template <int A, int B>
struct Mode;

enum class lamp : std::uint8_t { off, green, red = 200 };

struct spindle {
    double rpm = 0;
    std::array<bool, 2> limits{};
};

struct ctx {
    bsc::input<bool> start;
    bsc::output<int> count{-1};
    bsc::inout<lamp> light;
    spindle s;
    bsc::timer dwell{300ms};
    std::string note;  // not recorded
    std::uint16_t raw = 5;
};

inline constexpr auto chart = bsc::make_chart<ctx>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::composite<Work>(bsc::initial<Feed>, bsc::state<Cut>),
                         bsc::state<Mode<1, 2>>),
    bsc::state<Idle>[([](ctx const& c) { return c.start.get(); })] /
        [](ctx& c) {
            c.count.set(c.count.pending() + 2);
            c.light.set(lamp::red);
            c.s.rpm = 1.5;
            c.s.limits[1] = true;
            c.dwell.start();
            c.note = "started";
        } = bsc::state<Work>,
    bsc::state<Feed>[([](ctx const& c) { return c.dwell.tm(); })] = bsc::state<Cut>,
    bsc::state<Work> + bsc::event<stop> / [](ctx& c) { c.dwell.reset(); } = bsc::state<Mode<1, 2>>,
    bsc::state<Mode<1, 2>> + bsc::event<go> = bsc::state<Idle>);

static_assert(inside::member_names<ctx>[0] == "start");
static_assert(inside::member_names<ctx>[3] == "s");
static_assert(inside::member_names<ctx>[6] == "raw");
static_assert(inside::member_names<spindle>[1] == "limits");

constexpr char const* header =
    "$comment bsc::vcd_recorder: the states, channels, timers and variables of one machine $end\n"
    "$timescale 1 ns $end\n"
    "$scope module Root $end\n"
    "$scope module states $end\n"
    "$var string 1 ! Root $end\n"
    "$var string 1 \" Work $end\n"
    "$scope module active $end\n"
    "$var wire 1 % Root $end\n"
    "$var wire 1 & Idle $end\n"
    "$var wire 1 ' Work $end\n"
    "$var wire 1 ( Feed $end\n"
    "$var wire 1 ) Cut $end\n"
    "$var wire 1 * Mode<1,_2> $end\n"
    "$upscope $end\n"
    "$upscope $end\n"
    "$scope module data $end\n"
    "$var wire 1 + start $end\n"
    "$var integer 32 , count $end\n"
    "$var reg 8 - light $end\n"
    "$scope module s $end\n"
    "$var real 64 . rpm $end\n"
    "$var wire 1 / limits_0 $end\n"
    "$var wire 1 0 limits_1 $end\n"
    "$upscope $end\n"
    "$scope module dwell $end\n"
    "$var wire 1 1 running $end\n"
    "$var wire 1 2 expired $end\n"
    "$var integer 64 3 elapsed $end\n"
    "$upscope $end\n"
    "$var reg 16 4 raw $end\n"
    "$upscope $end\n"
    "$upscope $end\n"
    "$enddefinitions $end\n";

template <class M>
std::string record(M& m) {
    std::ostringstream out;
    {
        bsc::vcd_recorder vcd{out, m};
        CHECK(vcd.variables() == 18);
        m.step(0ms);
        vcd.sample();  // everything, at 0
        vcd.sample();  // nothing changed: nothing written
        m.context().start.set(true);
        m.step(100ms);
        vcd.sample();  // Idle -> Work
        m.step(200ms);
        vcd.sample();  // the dwell timer runs
        m.step(500ms);
        vcd.sample();  // expired: Feed -> Cut
        m.dispatch(stop{});
        vcd.sample();  // at the same time: no second #500000000; the timer is reset
        m.step(700ms);
        vcd.sample();  // nothing changes
        m.step(900ms);
        vcd.sample();
        CHECK(vcd.samples() == 8);
    }  // the end of the run: the last sample's time
    return out.str();
}

TEST_CASE_TEMPLATE("vcd: the states, channels, timers and variables, sample by sample", Backend, bsc_test::compiled,
                   bsc_test::table) {
    bsc_test::machine_t<Backend, decltype(chart), bsc::scan_policy> m{chart, ctx{}};
    std::string const expected = std::string{header} +
                                 "#0\n$dumpvars\n"
                                 "sIdle !\n"
                                 "s- \"\n"
                                 "1%\n1&\n0'\n0(\n0)\n0*\n"
                                 "0+\n"
                                 "b11111111111111111111111111111111 ,\n"  // -1, every bit of 32
                                 "b0 -\n"
                                 "r0 .\n"
                                 "0/\n00\n"
                                 "01\n02\nb0 3\n"
                                 "b101 4\n"
                                 "$end\n"
                                 "#100000000\n"
                                 "sWork !\n"
                                 "sFeed \"\n"
                                 "0&\n1'\n1(\n"
                                 "1+\n"
                                 "b1 ,\n"
                                 "b11001000 -\n"  // red = 200
                                 "r1.5 .\n"
                                 "10\n"
                                 "#200000000\n"
                                 "11\n"
                                 "#500000000\n"
                                 "sCut \"\n"
                                 "0(\n1)\n"
                                 "01\n12\nb10001111000011010001100000000 3\n"  // 300 ms
                                 "sMode<1,_2> !\n"
                                 "s- \"\n"
                                 "0'\n0)\n1*\n"
                                 "02\nb0 3\n"
                                 "#900000000\n";
    CHECK(record(m) == expected);
}

TEST_CASE("vcd: the stream's locale and flags do not change the file") {
    struct grouping : std::numpunct<char> {
        char do_thousands_sep() const override { return ','; }
        std::string do_grouping() const override { return "\3"; }
        char do_decimal_point() const override { return ';'; }
    };
    bsc::machine<decltype(chart), bsc::scan_policy> plain{chart, ctx{}};
    bsc::machine<decltype(chart), bsc::scan_policy> localised{chart, ctx{}};
    std::ostringstream a;
    std::ostringstream b;
    b.imbue(std::locale(std::locale::classic(), new grouping));
    b << std::hex << std::showbase;
    {
        bsc::vcd_recorder va{a, plain};
        bsc::vcd_recorder vb{b, localised};
        for (auto* m : {&plain, &localised}) {
            m->context().start.set(true);
            m->step(1234567ms);
        }
        va.sample();
        vb.sample();
    }
    CHECK(a.str() == b.str());
    CHECK(a.str().find("#1234567000000\n") != std::string::npos);
    CHECK(a.str().find("r1.5 .\n") != std::string::npos);
}

}  // namespace vcd_test
