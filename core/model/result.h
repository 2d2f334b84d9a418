// How a function says that what it was given is refused, or that its work
// failed: Result<T> holds the value or a Failure, one sentence naming the
// thing and what is wrong, and the Place it is at. Refusal is the one
// exception type for what the operator must fix, thrown deep inside a reader
// or an evaluator and caught at that reader's door, where it becomes a
// Failure, a Diagnostic or a figure error.
//
// The kinds of trouble and how each is told (docs/decisions.md):
// - what the operator must fix in the job: a Diagnostic (model/diagnostic.h),
//   naming unit and field, collected, never thrown;
// - what the operator must fix elsewhere (a command-line option, a machine,
//   dialect, technology or tool file, a STEP, DXF or figure text), and what
//   the machine or its files refuse: a Failure in a Result, carrying its
//   Place; inside a reader, a Refusal until its door;
// - a broken invariant, i.e. a bug: std::logic_error, caught at the top and
//   reported as an internal failure. Never for anything the operator typed.
#pragma once

#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <variant>

namespace taiwa {

// Where the operator finds what is refused: a file and its line, column and
// key, a text's line and column, an option, or a unit's field. Every part
// may be empty; text() writes the parts there are.
struct Place {
    std::string file;  // a file's path or a document's name ("materials.json", "--resolution")
    int line = 0;      // 1-based; 0 when not known
    int column = 0;    // 1-based; 0 when not known
    std::string key;   // a data file's key ("dialects/haas.json: blockNumbers"), or a unit's field
    int unit = 0;      // 1-based unit of the job; 0 for none

    // A file's path or name, its line and its key ("haas.json", 12, "lineLength").
    static Place inFile(std::string path, int line = 0, std::string key = {})
    {
        Place p;
        p.file = std::move(path), p.line = line, p.key = std::move(key);
        return p;
    }
    // A text's line and column (a figure's statement).
    static Place inText(int line, int column)
    {
        Place p;
        p.line = line, p.column = column;
        return p;
    }
    // A key of a data file, or a job's field, the file not named.
    static Place atKey(std::string key)
    {
        Place p;
        p.key = std::move(key);
        return p;
    }

    bool empty() const { return file.empty() && line == 0 && key.empty() && unit == 0; }
    // "haas.json:12:3: lineLength", "line 4, column 7", "unit 2: depth";
    // empty for an empty place.
    std::string text() const;
    friend bool operator==(const Place&, const Place&) = default;
};

struct Failure {
    std::string message;  // the whole sentence, with its place in words
    Place place{};        // the same place, for a program to go to
};

// What the operator must fix, on its way from deep inside a reader to that
// reader's door. what() is the message with its place in front
// ("machines/x.json: turret.slots: must be a positive number").
class Refusal : public std::exception {
public:
    explicit Refusal(std::string message, Place place = {});
    const char* what() const noexcept override { return text_.c_str(); }
    const std::string& message() const { return message_; }  // without the place
    const Place& place() const { return place_; }
    // As a Failure: what() and the place.
    Failure failure() const { return Failure{text_, place_}; }

private:
    std::string message_;
    Place place_;
    std::string text_;
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
    // Why it failed, where, and both; only when !ok().
    const std::string& error() const { return std::get<1>(v_).message; }
    const Place& place() const { return std::get<1>(v_).place; }
    const Failure& failure() const { return std::get<1>(v_); }

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
    const Place& place() const { return f_->place; }
    const Failure& failure() const { return *f_; }

private:
    std::optional<Failure> f_;
};

// (No alias such as "Status": X11's headers #define Status.)

}  // namespace taiwa
