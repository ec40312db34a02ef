// Contexts adapted with Boost.Hana (<bsc/adapt/hana.hpp>) work wherever an aggregate does: a
// class with private members and a constructor (BOOST_HANA_DEFINE_STRUCT), a class with a base
// class (BOOST_HANA_ADAPT_STRUCT, an inherited member listed), and a struct of 150 members, more
// than an aggregate may have (accessors written with Boost.Preprocessor). On both back ends their
// inputs are latched, their outputs committed and their timers updated; bsc::save and
// bsc::restore, the explorer and the VCD recorder see every member, by its Hana name.

#include <doctest/doctest.h>

#include <bsc/adapt/hana.hpp>
#include <bsc/bsc.hpp>
#include <bsc/retain.hpp>
#include <bsc/vcd.hpp>
#include <bsc/verify.hpp>

#include <boost/hana/adapt_struct.hpp>
#include <boost/hana/define_struct.hpp>
#include <boost/hana/pair.hpp>
#include <boost/hana/string.hpp>
#include <boost/hana/tuple.hpp>
#include <boost/preprocessor/repetition/enum.hpp>
#include <boost/preprocessor/repetition/repeat.hpp>
#include <boost/preprocessor/stringize.hpp>

#include <array>
#include <chrono>
#include <cstddef>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "backends.hpp"

using namespace std::chrono_literals;

namespace hana_test {

struct Root;
struct Idle;
struct Busy;

// ---- a class with private members and a constructor: BOOST_HANA_DEFINE_STRUCT -----------------

class press {
public:
    explicit press(int limit) : dwell{300ms}, strokes{0}, limit{limit} {}

    void request(bool on) const { start.set(on); }  // the environment's: on the const context
    bool requested() const { return start.get(); }
    bool may_stroke() const { return start.get() && strokes < limit; }
    void stroke() {
        ++strokes;
        shown.set(strokes);
        dwell.start();
    }
    bool dwelt() const { return dwell.tm(); }
    void release() { dwell.reset(); }
    int published() const { return shown.get(); }
    int count() const { return strokes; }
    bool dwelling() const { return dwell.running(); }

private:
    BOOST_HANA_DEFINE_STRUCT(press, (bsc::input<bool>, start), (bsc::output<int>, shown), (bsc::timer, dwell),
                             (int, strokes), (int, limit));
    // The macro's accessors are private too: Hana reads them through its accessors_impl.
    template <class, class>
    friend struct boost::hana::accessors_impl;
};

static_assert(!std::is_aggregate_v<press>);
static_assert(bsc::fields<press>::names.size() == 5);
static_assert(bsc::fields<press>::names[0] == "start" && bsc::fields<press>::names[4] == "limit");

inline constexpr auto press_chart = bsc::make_chart<press>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle>[([](press const& p) { return p.may_stroke(); })] / [](press& p) { p.stroke(); } = bsc::state<Busy>,
    bsc::state<Busy>[([](press const& p) { return p.dwelt(); })] / [](press& p) { p.release(); } = bsc::state<Idle>);

// ---- a class with a base class: BOOST_HANA_ADAPT_STRUCT ---------------------------------------------

class station_base {
protected:
    bsc::input<bool> enable;
    int faults = 0;
};

class station : public station_base {
public:
    explicit station(bsc::duration on_time, int faults_so_far = 0) : blink{on_time} { faults = faults_so_far; }

    void allow(bool on) const { enable.set(on); }  // the environment's: on the const context
    bool enabled() const { return enable.get(); }
    void light() {
        lamp.set(true);
        blink.start();
        ++cycles;
    }
    bool lit_long_enough() const { return blink.tm(); }
    void dark() {
        lamp.set(false);
        blink.reset();
    }
    bool lamp_on() const { return lamp.get(); }
    bool blinking() const { return blink.running(); }
    int cycle_count() const { return cycles; }
    void fault() { ++faults; }
    int fault_count() const { return faults; }

private:
    bsc::output<bool> lamp;
    bsc::timer blink;
    int cycles = 0;
    friend struct boost::hana::accessors_impl<station>;
};

}  // namespace hana_test

BOOST_HANA_ADAPT_STRUCT(hana_test::station, enable, faults, lamp, blink, cycles);

namespace hana_test {

static_assert(bsc::fields<station>::names[0] == "enable" && bsc::fields<station>::names[3] == "blink");

inline constexpr auto station_chart = bsc::make_chart<station>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle>[([](station const& s) { return s.enabled(); })] / [](station& s) { s.light(); } = bsc::state<Busy>,
    bsc::state<Busy>[([](station const& s) { return s.lit_long_enough(); })] /
        [](station& s) { s.dark(); } = bsc::state<Idle>);

// ---- 150 members, more than an aggregate's 128: accessors of its own ----------------------------

#define HANA_TEST_MEMBER(z, n, data) int m##n = n;
struct big {
    BOOST_PP_REPEAT(147, HANA_TEST_MEMBER, ~)
    // After the 128th: a walk that stopped there would neither latch, commit nor update them.
    bsc::input<int> in;
    bsc::output<int> out;
    bsc::timer wait{300ms};
};
#undef HANA_TEST_MEMBER

}  // namespace hana_test

// Hana's own way to adapt a type: its accessors, (name, function to the member) pairs.
#define HANA_TEST_ACCESSOR(z, n, data) \
    boost::hana::make_pair(            \
        BOOST_HANA_STRING("m" BOOST_PP_STRINGIZE(n)), [](auto& b) -> auto& { return b.m##n; })
template <>
struct boost::hana::accessors_impl<hana_test::big> {
    static constexpr auto apply() {
        namespace hana = boost::hana;
        return hana::make_tuple(BOOST_PP_ENUM(147, HANA_TEST_ACCESSOR, ~),
                                hana::make_pair(
                                    BOOST_HANA_STRING("in"), [](auto& b) -> auto& { return b.in; }),
                                hana::make_pair(
                                    BOOST_HANA_STRING("out"), [](auto& b) -> auto& { return b.out; }),
                                hana::make_pair(
                                    BOOST_HANA_STRING("wait"), [](auto& b) -> auto& { return b.wait; }));
    }
};
#undef HANA_TEST_ACCESSOR

namespace hana_test {

static_assert(bsc::fields<big>::names.size() == 150);
static_assert(bsc::fields<big>::names[146] == "m146" && bsc::fields<big>::names[149] == "wait");

inline constexpr auto big_chart = bsc::make_chart<big>(
    bsc::composite<Root>(bsc::initial<Idle>, bsc::state<Busy>),
    bsc::state<Idle>[([](big const& b) { return b.in.get() > 0; })] /
        [](big& b) {
            b.out.set(b.in.get() + b.m146);
            b.wait.start();
        } = bsc::state<Busy>,
    bsc::state<Busy>[([](big const& b) { return b.wait.tm(); })] = bsc::state<Idle>);

// ---- the explorer's chart: A -go/n=(n+1)%3-> B -go[n==2]-> C; back returns to A --------------------

struct go {};
struct back {};
struct A;
struct B;
struct C;

class counter {
public:
    explicit counter(int start) : n{start} {}
    void advance() { n = (n + 1) % 3; }
    int value() const { return n; }

private:
    BOOST_HANA_DEFINE_STRUCT(counter, (int, n));
    template <class, class>
    friend struct boost::hana::accessors_impl;
};

inline constexpr auto counter_chart = bsc::make_chart<counter>(
    bsc::composite<Root>(bsc::initial<A>, bsc::state<B>, bsc::state<C>),
    bsc::state<A> + bsc::event<go> / [](counter& c) { c.advance(); } = bsc::state<B>,
    bsc::state<B> + bsc::event<go>[([](counter const& c) { return c.value() == 2; })] = bsc::state<C>,
    bsc::state<B> + bsc::event<back> = bsc::state<A>, bsc::state<C> + bsc::event<back> = bsc::state<A>);

// The `$var` lines of a VCD header's scope `data`, without their identifier codes: "wire 1 start".
std::vector<std::string> data_variables(std::string const& vcd) {
    std::vector<std::string> lines;
    std::istringstream in{vcd.substr(vcd.find("$scope module data $end"))};
    std::string line;
    int depth = 0;
    while (std::getline(in, line)) {
        if (line.starts_with("$scope")) {
            ++depth;
            if (depth > 1) lines.push_back(line.substr(14, line.size() - 14 - 5));  // "scope NAME"
        } else if (line.starts_with("$upscope")) {
            if (--depth == 0) break;
            lines.push_back("upscope");
        } else if (line.starts_with("$var")) {
            std::istringstream words{line};
            std::string var, type, width, id, name;
            words >> var >> type >> width >> id >> name;
            lines.push_back(type + " " + width + " " + name);
        }
    }
    return lines;
}

}  // namespace hana_test

using namespace hana_test;

TEST_CASE("hana: fields<T> passes the members themselves, const for a const object, named by their keys") {
    big b;
    std::array<void const*, 150> seen{};
    bsc::fields<big>::apply(b, [&](auto&... member) {
        static_assert(!(std::is_const_v<std::remove_reference_t<decltype(member)>> || ...));
        seen = {static_cast<void const*>(&member)...};
    });
    CHECK(seen[0] == &b.m0);
    CHECK(seen[146] == &b.m146);
    CHECK(seen[147] == &b.in);
    CHECK(seen[149] == &b.wait);

    big const& constant = b;
    bsc::fields<big>::apply(constant, [&](auto&... member) {
        static_assert((std::is_const_v<std::remove_reference_t<decltype(member)>> && ...));
        seen = {static_cast<void const*>(&member)...};
    });
    CHECK(seen[148] == &b.out);

    press p{3};
    int strokes = -1;
    bsc::fields<press>::apply(p, [&](auto&, auto&, auto&, int& s, int&) { s = 2; });
    bsc::fields<press>::apply(std::as_const(p), [&](auto&, auto&, auto&, int const& s, int const&) { strokes = s; });
    CHECK(p.count() == 2);
    CHECK(strokes == 2);
}

TEST_CASE_TEMPLATE("hana: private members: the input is latched, the output committed, the timer updated", Backend,
                   bsc_test::compiled, bsc_test::table) {
    bsc_test::machine_t<Backend, decltype(press_chart), bsc::scan_policy> m{press_chart, press{2}};
    m.context().request(true);
    CHECK_FALSE(m.context().requested());  // not latched yet
    m.step(0ms);
    CHECK(m.context().requested());
    CHECK(m.template is<Busy>());
    CHECK(m.context().count() == 1);
    CHECK(m.context().published() == 1);  // committed at the end of the cycle
    CHECK_FALSE(m.context().dwelling());  // times from the next cycle
    m.step(100ms);
    CHECK(m.context().dwelling());
    m.step(399ms);
    CHECK(m.template is<Busy>());
    m.step(400ms);  // 300 ms after timing began
    CHECK(m.template is<Idle>());
    m.step(500ms);  // the second stroke; the limit of 2 then holds the press
    m.step(600ms);
    m.step(900ms);
    m.step(1000ms);
    CHECK(m.context().count() == 2);
    CHECK(m.context().published() == 2);
    CHECK(m.template is<Idle>());
}

TEST_CASE_TEMPLATE("hana: a base class: the inherited input is latched, the output committed, the timer updated",
                   Backend, bsc_test::compiled, bsc_test::table) {
    bsc_test::machine_t<Backend, decltype(station_chart), bsc::scan_policy> m{station_chart, station{200ms}};
    m.context().allow(true);
    m.step(0ms);
    CHECK(m.context().enabled());
    CHECK(m.template is<Busy>());
    CHECK(m.context().lamp_on());
    m.context().allow(false);
    m.step(100ms);
    CHECK(m.context().blinking());
    m.step(299ms);
    CHECK(m.template is<Busy>());
    m.step(300ms);
    CHECK(m.template is<Idle>());
    CHECK_FALSE(m.context().lamp_on());
    CHECK(m.context().cycle_count() == 1);
}

TEST_CASE_TEMPLATE("hana: 150 members: the channels and the timer after the 128th are driven", Backend,
                   bsc_test::compiled, bsc_test::table) {
    bsc_test::machine_t<Backend, decltype(big_chart), bsc::scan_policy> m{big_chart, big{}};
    m.context().in.set(4);
    CHECK(m.context().in.get() == 0);
    m.step(0ms);
    CHECK(m.context().in.get() == 4);
    CHECK(m.template is<Busy>());
    CHECK(m.context().out.get() == 150);
    m.step(100ms);
    CHECK(m.context().wait.running());
    m.step(400ms);
    CHECK(m.template is<Idle>());
}

TEST_CASE("hana: save and restore keep every member, private, inherited or past the 128th") {
    using press_machine = bsc::machine<decltype(press_chart), bsc::scan_policy>;
    press_machine p{press_chart, press{5}};
    p.context().request(true);
    p.step(0ms);
    p.step(100ms);
    auto const press_bytes = bsc::save(p);
    REQUIRE(press_bytes.size() == bsc::saved_size<press_machine>);
    press_machine p2{press_chart, press{1}};  // another limit, no stroke yet
    auto const r = bsc::restore(p2, press_bytes);
    REQUIRE_MESSAGE(r, bsc::to_string(r));
    CHECK(p2.is<Busy>());
    CHECK(p2.context().count() == 1);
    CHECK(p2.context().published() == 1);
    CHECK(p2.context().dwelling());
    CHECK(bsc::save(p2) == press_bytes);
    p2.step(400ms);
    CHECK(p2.is<Idle>());
    p2.step(500ms);  // the restored limit, 5, allows a second stroke
    CHECK(p2.context().count() == 2);

    using station_machine = bsc::machine<decltype(station_chart), bsc::scan_policy>;
    station_machine s{station_chart, station{200ms, 2}};  // two faults so far
    s.context().allow(true);
    s.step(0ms);
    station_machine s2{station_chart, station{1s}};
    REQUIRE(bsc::restore(s2, bsc::save(s)));
    CHECK(s2.context().fault_count() == 2);  // inherited
    CHECK(s2.context().enabled());
    CHECK(s2.context().lamp_on());
    s2.step(100ms);
    s2.step(300ms);  // the restored limit, 200 ms
    CHECK(s2.is<Idle>());

    using big_machine = bsc::machine<decltype(big_chart), bsc::scan_policy>;
    static_assert(bsc::saved_size<big_machine> > 147 * sizeof(int));
    big b_start{};
    b_start.m140 = 999;
    big_machine b{big_chart, b_start};
    b.context().in.set(1);
    b.step(0ms);
    big_machine b2{big_chart, big{}};
    REQUIRE(bsc::restore(b2, bsc::save(b)));
    CHECK(b2.context().m140 == 999);
    CHECK(b2.context().out.get() == 147);
    CHECK(b2.is<Busy>());
}

TEST_CASE("hana: the explorer encodes the members of a Hana context") {
    using machine = bsc::machine<decltype(counter_chart)>;
    bsc::verify::explorer ex{bsc::verify::event_model<machine, go, back>{machine{counter_chart, counter{0}}}};
    auto const& st = ex.run();
    CHECK(st.complete);
    CHECK(st.states == 7);  // (A,0) (B,1) (A,1) (B,2) (A,2) (C,2) (B,0): n is part of the state
    CHECK(st.key_bytes == (2 + 8 * sizeof(int) + 7) / 8);
    auto const c = bsc::verify::reachable(ex, "C", [](auto const& m) { return m.template is<C>(); });
    CHECK(c.holds());
}

TEST_CASE("hana: the VCD recorder writes the members by their Hana names") {
    bsc::machine<decltype(press_chart), bsc::scan_policy> p{press_chart, press{2}};
    std::ostringstream out;
    {
        bsc::vcd_recorder vcd{out, p};
        p.context().request(true);
        p.step(0ms);
        vcd.sample();
    }
    CHECK(data_variables(out.str()) ==
          std::vector<std::string>{"wire 1 start", "integer 32 shown", "dwell", "wire 1 running", "wire 1 expired",
                                   "integer 64 elapsed", "upscope", "integer 32 strokes", "integer 32 limit"});

    bsc::machine<decltype(station_chart), bsc::scan_policy> s{station_chart, station{200ms}};
    std::ostringstream wave;
    {
        bsc::vcd_recorder vcd{wave, s};
        s.step(0ms);
        vcd.sample();
    }
    CHECK(data_variables(wave.str()) == std::vector<std::string>{"wire 1 enable", "integer 32 faults", "wire 1 lamp",
                                                                 "blink", "wire 1 running", "wire 1 expired",
                                                                 "integer 64 elapsed", "upscope", "integer 32 cycles"});

    bsc::machine<decltype(big_chart), bsc::scan_policy> b{big_chart, big{}};
    std::ostringstream big_wave;
    {
        bsc::vcd_recorder vcd{big_wave, b};
        b.step(0ms);
        vcd.sample();
    }
    auto const variables = data_variables(big_wave.str());
    REQUIRE(variables.size() == 147 + 2 + 5);
    CHECK(variables[0] == "integer 32 m0");
    CHECK(variables[146] == "integer 32 m146");
    CHECK(variables[147] == "integer 32 in");
    CHECK(variables[149] == "wait");
}
