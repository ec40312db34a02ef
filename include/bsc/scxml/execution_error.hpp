#pragma once
// bsc::scxml::execution_error: what a generated chart's executable content throws where SCXML
// raises error.execution.

#include <stdexcept>
#include <string>
#include <utility>

namespace bsc::scxml {

/// Thrown by an expression, a location or an element that SCXML says fails (an undefined
/// field used as a number, an assignment to a system variable, a `<send>` to a target bsc
/// cannot reach). The machine contains it as it contains any failure of an action
/// (docs/semantics.md, "Failures in guards and actions"): the rest of the block is skipped and
/// bsc::action_failed is raised, which a generated chart takes as SCXML's `error.execution`.
class execution_error : public std::runtime_error {
public:
    explicit execution_error(std::string const& what) : std::runtime_error(what) {}
    /// An error of a `<send>`: its id, which the error event's `_event.sendid` carries.
    execution_error(std::string const& what, std::string send_id)
        : std::runtime_error(what), send_id_(std::move(send_id)) {}

    [[nodiscard]] std::string const& send_id() const noexcept { return send_id_; }

private:
    std::string send_id_;
};

}  // namespace bsc::scxml
