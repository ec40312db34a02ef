#pragma once
// How a machine catches what its guards and actions throw. Each call of a guard or an action is
// one block: if it throws, the rest of it is skipped and the failure goes to the machine
// (detail::run_control::fail), which raises bsc::action_failed or keeps it for the caller. Built
// without exceptions, these are plain calls.

#include <exception>
#include <type_traits>
#include <utility>

namespace bsc::detail {

// A machine's record of a failure, kept as a pointer so that a machine stays a literal type
// (std::exception_ptr is not one) and usable in constant expressions, where nothing can
// throw. It is allocated only when something has thrown.
class failure_slot {
public:
    constexpr failure_slot() = default;
    constexpr failure_slot(failure_slot const& other) {
        if (!std::is_constant_evaluated() && other.error_ != nullptr) error_ = copy(*other.error_);
    }
    constexpr failure_slot& operator=(failure_slot const& other) {
        if (this != &other) {
            reset();
            if (!std::is_constant_evaluated() && other.error_ != nullptr) error_ = copy(*other.error_);
        }
        return *this;
    }
    constexpr ~failure_slot() { reset(); }

    constexpr explicit operator bool() const { return error_ != nullptr; }
    // Keeps the first failure; later ones of the same run are dropped (the first caused them).
    void keep(std::exception_ptr error) {
        if (error_ == nullptr) error_ = copy(std::move(error));
    }
    std::exception_ptr get() const { return error_ != nullptr ? *error_ : nullptr; }
    std::exception_ptr take() {
        std::exception_ptr error = get();
        reset();
        return error;
    }
    constexpr void reset() {
        if (!std::is_constant_evaluated() && error_ != nullptr) destroy(error_);
        error_ = nullptr;
    }

private:
    static std::exception_ptr* copy(std::exception_ptr error) { return new std::exception_ptr(std::move(error)); }
    static void destroy(std::exception_ptr* error) { delete error; }

    std::exception_ptr* error_ = nullptr;
};

// Where the table engine's thunks report a failure: the machine and its fail().
struct failure_sink {
    void* machine = nullptr;
    void (*report)(void* machine, std::exception_ptr error) = nullptr;
};

// Runs a block; a failure goes to on_failure(std::exception_ptr).
template <class Block, class OnFailure>
constexpr void run_block(Block&& block, OnFailure&& on_failure) {
#if defined(__cpp_exceptions)
    try {
        block();
    } catch (...) {
        on_failure(std::current_exception());
    }
#else
    (void)on_failure;
    block();
#endif
}

}  // namespace bsc::detail
