#pragma once
// The dotted name of a member during a named walk of a context (detail/members.hpp): "axis.position",
// "dwell.running". The explorer's codec names the fields of a state with it, the trace names the
// members it samples, and the inspector finds the input a page sets by it. Its own header: the
// machines' walks name nothing and need no strings.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace bsc::detail {

class member_path {
public:
    /// Enters the scope `name` (an unnamed one, the walk's root, adds nothing); each is left again
    /// in order.
    void enter(std::string_view name) {
        starts_.push_back(text_.size());
        if (name.empty()) return;
        if (!text_.empty()) text_ += '.';
        text_ += name;
    }
    void leave() {
        if (starts_.empty()) return;
        text_.resize(starts_.back());
        starts_.pop_back();
    }
    /// The full name of the member `name` in the present scope (of "" the scope's own).
    std::string of(std::string_view name) const {
        if (text_.empty()) return std::string{name};
        return name.empty() ? text_ : text_ + "." + std::string{name};
    }
    /// Back to no scope, keeping the memory, so that a walk after the first allocates nothing.
    void clear() {
        text_.clear();
        starts_.clear();
    }

private:
    std::string text_;
    std::vector<std::size_t> starts_;  // text_'s length before each scope entered
};

}  // namespace bsc::detail
