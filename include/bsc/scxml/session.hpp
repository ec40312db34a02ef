#pragma once
// bsc::scxml::session: what a generated chart's datamodel keeps besides the document's own data:
// the ids of pending `<send>`s and the helpers the generated executable content calls.

#include <cctype>
#include <chrono>
#include <cstddef>
#include <exception>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <bsc/duration.hpp>
#include <bsc/events.hpp>
#include <bsc/scxml/event.hpp>
#include <bsc/scxml/execution_error.hpp>
#include <bsc/scxml/value.hpp>

namespace bsc::scxml {

/// The processor type a `<send>` names for an SCXML session (SCXML's event I/O processor).
inline constexpr std::string_view scxml_processor = "http://www.w3.org/TR/scxml/#SCXMLEventProcessor";

/// What `_ioprocessors` holds for a session with this id: the SCXML processor's location.
inline value io_processors(value const& session_id) {
    value location = value::object();
    location.set("location", value("#_scxml_") + session_id);
    value processors = value::object();
    processors.set(scxml_processor, location);
    processors.set("scxml", location);
    return processors;
}

/// A location that is none (an assignment to it fails with error.execution), for a document
/// whose `location` names nothing the datamodel has.
[[noreturn]] inline value& invalid_location() { throw execution_error("not a location of the datamodel"); }

/// An expression that fails: SCXML's error.execution where a document's expression is
/// malformed or cannot be evaluated.
[[noreturn]] inline value invalid_expression() { throw execution_error("an expression that cannot be evaluated"); }

/// Whether the string `text` starts with `prefix` (an undefined prefix: no).
inline bool starts_with(value const& text, value const& prefix) {
    if (prefix.is_undefined() || text.is_undefined()) return false;
    std::string const t = text.to_string();
    std::string const p = prefix.to_string();
    return t.rfind(p, 0) == 0;
}

/// `array` with `item` appended (the array is copied: a `<foreach>` iterates a copy).
inline value appended(value array, value item) {
    array.push_back(std::move(item));
    return array;
}

/// A CSS2 time ("2s", "500ms", ".5s") as a duration; throws execution_error for anything else.
inline duration parse_delay(std::string_view text) {
    // (A delay beyond bsc::duration is refused before the conversion, which would be undefined.)
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
    std::size_t digits = 0;
    while (digits < text.size() && (std::isdigit(static_cast<unsigned char>(text[digits])) || text[digits] == '.'))
        ++digits;
    std::string const number(text.substr(0, digits));
    std::string_view const unit = text.substr(digits);
    if (number.empty() || number == "." || (unit != "s" && unit != "ms"))
        throw execution_error("not a delay: '" + std::string(text) + "' (write 2s or 500ms)");
    double const amount = std::stod(number);
    std::chrono::duration<double, std::nano> const length =
        unit == "s" ? std::chrono::duration<double, std::nano>(std::chrono::duration<double>(amount))
                    : std::chrono::duration<double, std::nano>(std::chrono::duration<double, std::milli>(amount));
    if (!(length.count() < static_cast<double>(duration::max().count())))
        throw execution_error("a delay longer than bsc::duration holds: '" + std::string(text) + "'");
    return std::chrono::duration_cast<duration>(length);
}
/// A delay read from the datamodel (`delayexpr`): a string in CSS2 notation.
inline duration parse_delay(value const& v) { return parse_delay(std::string_view(v.string())); }

/// Fails a `<send>`: error.execution, whose `_event.sendid` is the send's id.
[[noreturn]] inline void send_error(std::string const& what, value const& id) {
    throw execution_error(what, id.is_undefined() ? std::string() : id.to_string());
}

/// The send id an error.execution carries (`_event.sendid`): the failed `<send>`'s, or none.
inline value send_id_of(action_failed const& failure) {
    try {
        if (failure.error) std::rethrow_exception(failure.error);
    } catch (execution_error const& e) {
        if (!e.send_id().empty()) return value(e.send_id());
    } catch (...) {
    }
    return {};
}

/// Where a `<send>` goes.
enum class route : std::uint8_t { external, internal, other_session };

/// The session of one machine: its id and name, and the ids under which its `<send>`s are
/// pending, numbered for bsc's delayed events (bsc::raise_after's int ids).
class session {
public:
    /// The number under which a `<send>` with this id (`id`, `idlocation`, `sendidexpr`) is
    /// scheduled and cancelled: the same for the same id, never 0. The ids `fresh_id` made are
    /// numbered by themselves (negative); the others the session keeps, one entry per distinct
    /// id a document sends under.
    int number_of(value const& id) {
        if (int const known = find(id); known != 0) return known;
        ids_.push_back(id.to_string());
        return static_cast<int>(ids_.size());
    }
    /// A fresh id for a `<send idlocation>`: "send.N".
    value fresh_id() {
        fresh_ = fresh_ == max_fresh ? 1 : fresh_ + 1;
        return value("send." + std::to_string(fresh_));
    }

    /// Sends `e` where `to` says: the internal queue (`<raise>`, `<send target="#_internal">`),
    /// or the external one, after `delay` (`<send>`), under `id` if it is bound.
    template <class Raise, class E>
    void deliver(Raise& raise, E e, route to, duration delay, value const& id) {
        if (to == route::internal) return raise_internal(raise, std::move(e));
        e.type = "external";
        e.sendid = id;
        e.origin = value("#_scxml_") + id_;
        e.origintype = value(scxml_processor);
        if (delay < duration::zero()) send_error("a negative delay", id);
        (void)raise.schedule(delay, e, id.is_undefined() ? 0 : number_of(id));
    }
    /// Raises `e` on the internal queue.
    template <class Raise, class E>
    static void raise_internal(Raise& raise, E e) {
        e.type = "internal";
        raise(std::move(e));
    }
    /// Cancels the pending `<send>` with this id (`<cancel>`); one that is not pending: nothing
    /// (and an id never sent under is not kept).
    template <class Raise>
    void cancel(Raise& raise, value const& id) {
        if (int const known = find(id); known != 0) raise.cancel(known);
    }
    /// Where a `<send>`'s target (`target`, `targetexpr`) leads; throws execution_error (with
    /// the send's id) for a target that is not an SCXML session's.
    [[nodiscard]] route route_of(value const& target, value const& send_id) const {
        std::string const t = target.to_string();
        if (t == "#_internal") return route::internal;
        if (t == "#_scxml_" + id_.to_string()) return route::external;
        if (t.rfind("#_scxml_", 0) == 0) return route::other_session;
        send_error("a <send> target bsc cannot reach: '" + t + "'", send_id);
    }
    /// Checks a `<send>`'s type (`type`, `typeexpr`): only SCXML sessions are reached.
    static void check_type(value const& type) {
        std::string const t = type.to_string();
        if (t != scxml_processor && t != "scxml") throw execution_error("a <send> type bsc does not support: " + t);
    }

    value const& id() const noexcept { return id_; }
    void set_id(value id) { id_ = std::move(id); }

private:
    static constexpr int max_fresh = 1 << 30;
    // The number of an id sent under before (or made by fresh_id); 0 for one never seen.
    [[nodiscard]] int find(value const& id) const {
        if (int const fresh = fresh_number(id); fresh != 0) return fresh;
        std::string const key = id.to_string();
        for (std::size_t i = 0; i < ids_.size(); ++i)
            if (ids_[i] == key) return static_cast<int>(i) + 1;
        return 0;
    }
    // -N for "send.N", an id fresh_id made; 0 for any other.
    static int fresh_number(value const& id) {
        if (!id.is_string()) return 0;
        std::string const& text = id.string();
        if (text.rfind("send.", 0) != 0 || text.size() == 5 || text.size() > 15) return 0;
        long long n = 0;
        for (std::size_t i = 5; i < text.size(); ++i) {
            if (text[i] < '0' || text[i] > '9') return 0;
            n = n * 10 + (text[i] - '0');
        }
        return n >= 1 && n <= max_fresh ? -static_cast<int>(n) : 0;
    }

    value id_ = value("bsc");
    std::vector<std::string> ids_;
    int fresh_ = 0;
};

}  // namespace bsc::scxml
