// The one way a function says that the program's own work failed: a file that
// cannot be written, a database that cannot be opened, a picture that cannot
// be drawn. Result<T> holds the value or a Failure, one sentence naming the
// thing and what is wrong.
//
// The three kinds of trouble and how each is told (docs/decisions.md):
// - what the operator must fix in the job: a Diagnostic (model/diagnostic.h),
//   naming unit and field, collected, never thrown;
// - what the machine or its files refuse: a Failure in a Result;
// - a broken invariant, i.e. a bug: std::logic_error, caught at the top and
//   reported as an internal failure.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace taiwa {

struct Failure {
    std::string message;
};

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : v_(std::in_place_index<0>, std::move(value)) {}  // NOLINT: a value is a result
    Result(Failure f) : v_(std::in_place_index<1>, std::move(f)) {}    // NOLINT: so is a failure

    bool ok() const { return v_.index() == 0; }
    explicit operator bool() const { return ok(); }
    T& value() & { return std::get<0>(v_); }
    const T& value() const& { return std::get<0>(v_); }
    T&& value() && { return std::get<0>(std::move(v_)); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }
    // Why it failed; only when !ok().
    const std::string& error() const { return std::get<1>(v_).message; }

private:
    std::variant<T, Failure> v_;
};

template <>
class [[nodiscard]] Result<void> {
public:
    Result() = default;
    Result(Failure f) : f_(std::move(f)) {}  // NOLINT: a failure is a result

    bool ok() const { return !f_; }
    explicit operator bool() const { return ok(); }
    const std::string& error() const { return f_->message; }

private:
    std::optional<Failure> f_;
};

// (No alias such as "Status": X11's headers #define Status.)

}  // namespace taiwa
