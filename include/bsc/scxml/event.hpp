#pragma once
// bsc::scxml::event: the base of the event types bsc-scxml declares for a document. It carries
// what SCXML's _event holds besides the name, which is the event type's own (its static `name`).

#include <string>
#include <string_view>
#include <type_traits>

#include <bsc/scxml/value.hpp>

namespace bsc::scxml {

/// The fields of an SCXML event that vary from one occurrence to the next: `<send>` and
/// `<raise>` fill them. A generated event type derives from it and adds its name:
/// `struct foo_bar : foo { static constexpr std::string_view name = "foo.bar"; ... };`, where
/// `foo` is the family the descriptor `foo` names (docs/semantics.md, "Event families").
struct event {
    /// The dotted name of the event as sent (a row on a family sees the family's type, and
    /// this the full name).
    std::string sent_name;
    /// "internal" (`<raise>`, `<send target="#_internal">`), "external" (`<send>`), or
    /// "platform" (the done events and error.execution).
    std::string_view type = "internal";
    value sendid;
    value origin;
    value origintype;
    value invokeid;
    value data;
};

/// A system variable (`_sessionid`, `_name`, `_ioprocessors`): read like a value, and an
/// assignment to it fails with error.execution, as SCXML says.
class system_variable : public value {
public:
    using value::value;
    system_variable(value v) : value(std::move(v)) {}
    system_variable(system_variable const&) = default;
    system_variable& operator=(system_variable const&) = default;
    template <class T>
        requires(!std::is_same_v<std::remove_cvref_t<T>, system_variable>)
    system_variable& operator=(T&&) { throw execution_error("a system variable is read-only"); }
};

/// `_event`: the event being processed, as the document reads it (`_event.name`,
/// `_event.data`, ...). A document cannot assign it or its fields (`<assign location="_event">`,
/// `location="_event.name"`): that fails with error.execution.
struct event_fields {
    system_variable name;
    system_variable type;
    system_variable sendid;
    system_variable origin;
    system_variable origintype;
    system_variable invokeid;
    system_variable data;

    event_fields() = default;
    event_fields(value name_, value type_, value sendid_, value origin_, value origintype_, value invokeid_,
                 value data_)
        : name(std::move(name_)),
          type(std::move(type_)),
          sendid(std::move(sendid_)),
          origin(std::move(origin_)),
          origintype(std::move(origintype_)),
          invokeid(std::move(invokeid_)),
          data(std::move(data_)) {}
    event_fields(event_fields const&) = default;
    event_fields& operator=(event_fields const&) = default;
    template <class T>
        requires(!std::is_same_v<std::remove_cvref_t<T>, event_fields>)
    event_fields& operator=(T&&) { throw execution_error("_event is read-only"); }

    /// Before the first event, _event is unbound.
    [[nodiscard]] bool is_undefined() const noexcept { return name.is_undefined(); }
    /// As an object with the fields SCXML names (`<assign location="v" expr="_event"/>`).
    operator value() const {
        value v = value::object();
        v.set("name", name);
        v.set("type", type);
        v.set("sendid", sendid);
        v.set("origin", origin);
        v.set("origintype", origintype);
        v.set("invokeid", invokeid);
        v.set("data", data);
        return v;
    }
};

/// Whether `_event` has every field SCXML names: the C++ type says so.
constexpr bool has_event_fields(event_fields const&) noexcept {
    return requires(event_fields f) { f.name, f.type, f.sendid, f.origin, f.origintype, f.invokeid, f.data; };
}

}  // namespace bsc::scxml
