#pragma once
// bsc::scxml::value: the value of a variable of an SCXML document's C++ datamodel where the
// document declares no type for it (bsc-scxml, docs/scxml.md), and of an event's data. Dynamic,
// as SCXML's data is: undefined until bound, then a number, a string, a boolean, an array or an
// object (named fields, in the order they were set).

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <bsc/detail/config.hpp>
#include <bsc/scxml/execution_error.hpp>

namespace bsc::scxml {

/// A dynamically typed value. Arithmetic (`+ - * / %`) works on numbers (and `+` on strings,
/// which concatenates); comparisons order numbers and strings and compare everything else for
/// equality; a value tests as `true` unless it is undefined, null, false, 0 or the empty string.
/// What has no meaning (a number minus a string, an element of a number) throws
/// bsc::scxml::execution_error, which the machine turns into SCXML's error.execution.
class value {
public:
    enum class kind : std::uint8_t { undefined, null, boolean, number, string, array, object };
    using member = std::pair<std::string, value>;

    value() = default;
    // Out of line: a machine's dispatch inlines what it calls (docs/performance.md), and a
    // value's copies and destruction, inlined into every row, cost more to compile than they save.
    BSC_DETAIL_NOINLINE value(value const&) = default;
    BSC_DETAIL_NOINLINE value(value&&) noexcept = default;
    BSC_DETAIL_NOINLINE value& operator=(value const&) = default;
    BSC_DETAIL_NOINLINE value& operator=(value&&) noexcept = default;
    BSC_DETAIL_NOINLINE ~value() = default;
    value(bool b) : kind_{kind::boolean}, number_{b ? 1.0 : 0.0} {}
    value(int n) : kind_{kind::number}, number_{static_cast<double>(n)} {}
    value(long n) : kind_{kind::number}, number_{static_cast<double>(n)} {}
    value(long long n) : kind_{kind::number}, number_{static_cast<double>(n)} {}
    value(unsigned n) : kind_{kind::number}, number_{static_cast<double>(n)} {}
    value(unsigned long n) : kind_{kind::number}, number_{static_cast<double>(n)} {}
    value(double n) : kind_{kind::number}, number_{n} {}
    value(char const* s) : kind_{kind::string}, text_{s} {}
    value(std::string s) : kind_{kind::string}, text_{std::move(s)} {}
    value(std::string_view s) : kind_{kind::string}, text_{s} {}

    /// An array of the values given: `value::array({1, 2, 3})`.
    static value array(std::initializer_list<value> items = {}) {
        value v;
        v.kind_ = kind::array;
        v.items_.assign(items.begin(), items.end());
        return v;
    }
    /// An object without fields, filled by `set`.
    static value object() {
        value v;
        v.kind_ = kind::object;
        return v;
    }
    /// JSON's null.
    static value null() {
        value v;
        v.kind_ = kind::null;
        return v;
    }

    [[nodiscard]] kind type() const noexcept { return kind_; }
    [[nodiscard]] bool is_undefined() const noexcept { return kind_ == kind::undefined; }
    [[nodiscard]] bool is_number() const noexcept { return kind_ == kind::number; }
    [[nodiscard]] bool is_string() const noexcept { return kind_ == kind::string; }
    [[nodiscard]] bool is_array() const noexcept { return kind_ == kind::array; }
    [[nodiscard]] bool is_object() const noexcept { return kind_ == kind::object; }

    explicit operator bool() const noexcept {
        switch (kind_) {
            case kind::undefined:
            case kind::null: return false;
            case kind::boolean:
            case kind::number: return number_ != 0.0 && !std::isnan(number_);
            case kind::string: return !text_.empty();
            default: return true;
        }
    }

    /// The number; throws unless the value is one.
    [[nodiscard]] double number() const {
        if (kind_ != kind::number && kind_ != kind::boolean) throw execution_error("not a number: " + to_string());
        return number_;
    }
    /// The string; throws unless the value is one.
    [[nodiscard]] std::string const& string() const {
        if (kind_ != kind::string) throw execution_error("not a string: " + to_string());
        return text_;
    }
    /// The elements of an array; throws unless the value is one.
    [[nodiscard]] std::vector<value> const& elements() const {
        if (kind_ != kind::array) throw execution_error("not an array: " + to_string());
        return items_;
    }
    std::vector<value>& elements() {
        if (kind_ != kind::array) throw execution_error("not an array: " + to_string());
        return items_;
    }
    /// The fields of an object, in the order they were first set.
    [[nodiscard]] std::vector<member> const& fields() const {
        if (kind_ != kind::object) throw execution_error("not an object: " + to_string());
        return fields_;
    }

    /// The field `name` of an object (undefined if it has none, or if this is not an object).
    [[nodiscard]] value const& operator[](std::string_view name) const {
        if (kind_ == kind::object)
            for (auto const& [key, field] : fields_)
                if (key == name) return field;
        return undefined_value();
    }
    /// Element `index` of an array; throws if there is none.
    [[nodiscard]] value const& operator[](std::size_t index) const {
        if (index >= elements().size()) throw execution_error("no element " + std::to_string(index));
        return items_[index];
    }
    /// Sets field `name` (an undefined value becomes an object first).
    value& set(std::string_view name, value field) {
        if (kind_ == kind::undefined) kind_ = kind::object;
        if (kind_ != kind::object) throw execution_error("not an object: " + to_string());
        for (auto& [key, existing] : fields_)
            if (key == name) return existing = std::move(field);
        fields_.emplace_back(std::string(name), std::move(field));
        return fields_.back().second;
    }
    /// Whether an object has field `name`.
    [[nodiscard]] bool has(std::string_view name) const noexcept {
        if (kind_ == kind::object)
            for (auto const& f : fields_)
                if (f.first == name) return true;
        return false;
    }
    /// Appends to an array.
    void push_back(value item) { elements().push_back(std::move(item)); }

    /// As SCXML's `<log>` writes it: numbers without a fraction as integers, strings as they
    /// are, arrays `[1,2]`, objects `{"a":1}`.
    [[nodiscard]] std::string to_string() const {
        switch (kind_) {
            case kind::undefined: return "undefined";
            case kind::null: return "null";
            case kind::boolean: return number_ != 0.0 ? "true" : "false";
            case kind::number: {
                if (std::trunc(number_) == number_ && std::fabs(number_) < 1e15)
                    return std::to_string(static_cast<long long>(number_));
                char text[32];
                std::snprintf(text, sizeof text, "%g", number_);
                return text;
            }
            case kind::string: return text_;
            case kind::array: {
                std::string out = "[";
                for (std::size_t i = 0; i < items_.size(); ++i) out += (i ? "," : "") + items_[i].quoted();
                return out + "]";
            }
            case kind::object: {
                std::string out = "{";
                for (std::size_t i = 0; i < fields_.size(); ++i)
                    out += (i ? ",\"" : "\"") + fields_[i].first + "\":" + fields_[i].second.quoted();
                return out + "}";
            }
        }
        return {};
    }

    friend bool operator==(value const& a, value const& b) {
        if (a.kind_ != b.kind_) {
            // true == 1, as ECMAScript's loose equality has it: a boolean is a number here.
            bool const numeric_a = a.kind_ == kind::number || a.kind_ == kind::boolean;
            bool const numeric_b = b.kind_ == kind::number || b.kind_ == kind::boolean;
            return numeric_a && numeric_b && a.number_ == b.number_;
        }
        switch (a.kind_) {
            case kind::undefined:
            case kind::null: return true;
            case kind::boolean:
            case kind::number: return a.number_ == b.number_;
            case kind::string: return a.text_ == b.text_;
            case kind::array: return a.items_ == b.items_;
            case kind::object: return a.fields_ == b.fields_;
        }
        return false;
    }
    friend bool operator<(value const& a, value const& b) {
        if (a.kind_ == kind::string && b.kind_ == kind::string) return a.text_ < b.text_;
        return a.number() < b.number();
    }
    friend bool operator>(value const& a, value const& b) { return b < a; }
    friend bool operator<=(value const& a, value const& b) { return !(b < a); }
    friend bool operator>=(value const& a, value const& b) { return !(a < b); }

    friend value operator+(value const& a, value const& b) {
        if (a.kind_ == kind::string || b.kind_ == kind::string) return value(a.to_string() + b.to_string());
        return value(a.number() + b.number());
    }
    friend value operator-(value const& a, value const& b) { return value(a.number() - b.number()); }
    friend value operator*(value const& a, value const& b) { return value(a.number() * b.number()); }
    friend value operator/(value const& a, value const& b) { return value(a.number() / b.number()); }
    friend value operator%(value const& a, value const& b) { return value(std::fmod(a.number(), b.number())); }
    value operator-() const { return value(-number()); }
    value& operator+=(value const& b) { return *this = *this + b; }
    value& operator-=(value const& b) { return *this = *this - b; }
    value& operator++() { return *this = *this + value(1); }
    value& operator--() { return *this = *this - value(1); }

private:
    static value const& undefined_value() noexcept {
        static value const none;
        return none;
    }
    [[nodiscard]] std::string quoted() const { return kind_ == kind::string ? "\"" + text_ + "\"" : to_string(); }

    kind kind_ = kind::undefined;
    double number_ = 0.0;
    std::string text_;
    std::vector<value> items_;
    std::vector<member> fields_;
};

}  // namespace bsc::scxml
