// Uses the installed bsc::hana: a context class with private members and a constructor, adapted
// with Boost.Hana, whose input, output and timer the machine drives.
#include <bsc/adapt/hana.hpp>
#include <bsc/bsc.hpp>

#include <boost/hana/define_struct.hpp>

#include <chrono>

using namespace std::chrono_literals;

namespace lamp {
struct Lamp;
struct Off;
struct On;

class panel {
public:
    explicit panel(bsc::duration on_time) : timer{on_time} {}
    void press(bool down) const { button.set(down); }  // the environment's: on the const context
    bool pressed() const { return button.get(); }
    void light(bool on) {
        light_out.set(on);
        if (on)
            timer.start();
        else
            timer.reset();
    }
    bool lit() const { return light_out.get(); }
    bool timed_out() const { return timer.tm(); }

private:
    BOOST_HANA_DEFINE_STRUCT(panel, (bsc::input<bool>, button), (bsc::output<bool>, light_out), (bsc::timer, timer));
    template <class, class>
    friend struct boost::hana::accessors_impl;
};

inline constexpr auto chart = bsc::make_chart<panel>(
    bsc::composite<Lamp>(bsc::initial<Off>, bsc::state<On>),
    bsc::state<Off>[([](panel const& p) { return p.pressed(); })] / [](panel& p) { p.light(true); } = bsc::state<On>,
    bsc::state<On>[([](panel const& p) { return p.timed_out(); })] /
        [](panel& p) { p.light(false); } = bsc::state<Off>);
}  // namespace lamp

int main() {
    bsc::machine<bsc::chart_ref<lamp::chart>, bsc::scan_policy> m{lamp::chart, lamp::panel{200ms}};
    m.context().press(true);
    m.step(0ms);  // the button latched: on
    bool ok = m.is<lamp::On>() && m.context().lit();
    m.context().press(false);
    m.step(100ms);  // the timer times from here
    m.step(300ms);  // expired: off
    ok = ok && m.is<lamp::Off>() && !m.context().lit();
    return ok ? 0 : 1;
}
