// A module's unit in the job file as one table (docs/job-format.md): each key
// of the unit's JSON object, how it is read, what it is when absent, and when
// it is written. The table is the one place a key is named: the module's
// reader reads the keys in its order, its writer writes them in the same
// order, and the list of known keys that a stray key is refused against
// ("unknown field; module SIDE has module, name, contour, …") is made from
// it. So no key can be written that is not read back, nor read and refused.
// Used by the modules' doors (modules/*/*_kind.cpp); a unit whose format is
// a grammar of its own (TURN's profile table and its versions) keeps its
// reader. An entry of one plain member also names that member, so that the
// module's form binds its field by the same key (modules/form_binding.h).
#pragma once

#include "io/json_fields.h"
#include "io/json_write.h"

#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace taiwa::io {

// One entry of a unit's table: the keys it reads and writes (most entries
// one; a named region two, "outline" and "islands"), how, and whether the
// writer writes it for a given unit (by default always).
template <class U>
struct UnitKey {
    // The member an entry of one plain value reads and writes (none for
    // the tool pins and a module's own grammar). A module's form binds its
    // field by it (modules/form_binding.h), by its type: a text as the name
    // of a contour of the job's figure; a door binds any other text itself
    // (HOLES' pattern and hole, ModuleKindOf::ownField).
    using Member = std::variant<std::monostate, double U::*, std::optional<double> U::*, int U::*, std::string U::*,
                                Point2 U::*>;

    std::vector<std::string> keys;
    std::function<void(const ObjectFields&, U&)> read;
    std::function<void(const U&, ordered&)> write;
    Member member{};

    // Written only when `pred(unit)` holds (an optional value that is set, a
    // value that is not its default, a key the unit's variant uses).
    template <class Pred>
    UnitKey when(Pred pred) &&
    {
        write = [w = std::move(write), pred](const U& u, ordered& j) {
            if (pred(u)) w(u, j);
        };
        return std::move(*this);
    }
};

// The entries, by the kind of value (io::keys::required("depth", &M::depth)).
namespace keys {

// A number the unit must have: absent, it is reported and read as 0.
template <class U>
UnitKey<U> required(const char* key, double U::*m)
{
    return {{key},
            [key, m](const ObjectFields& f, U& u) { u.*m = f.number(key).value_or(0.0); },
            [key, m](const U& u, ordered& j) { j[key] = io::number(u.*m); },
            m};
}

// A number that is `fallback` when absent.
template <class U>
UnitKey<U> number(const char* key, double U::*m, double fallback)
{
    return {{key},
            [key, m, fallback](const ObjectFields& f, U& u) { u.*m = f.number(key, fallback); },
            [key, m](const U& u, ordered& j) { j[key] = io::number(u.*m); },
            m};
}

// A number the operator may leave empty; written only when given.
template <class U>
UnitKey<U> optional(const char* key, std::optional<double> U::*m)
{
    return {{key},
            [key, m](const ObjectFields& f, U& u) { u.*m = f.optionalNumber(key); },
            [key, m](const U& u, ordered& j) {
                if (u.*m) j[key] = io::number(*(u.*m));
            },
            m};
}

// A whole number (a code) the unit must have: absent, it is reported and
// read as 0.
template <class U>
UnitKey<U> requiredWhole(const char* key, int U::*m)
{
    return {{key},
            [key, m](const ObjectFields& f, U& u) { u.*m = f.whole(key).value_or(0); },
            [key, m](const U& u, ordered& j) { j[key] = u.*m; },
            m};
}

// A whole number that is `fallback` when absent.
template <class U>
UnitKey<U> whole(const char* key, int U::*m, int fallback)
{
    return {{key},
            [key, m, fallback](const ObjectFields& f, U& u) { u.*m = f.whole(key, fallback); },
            [key, m](const U& u, ordered& j) { j[key] = u.*m; },
            m};
}

// A text the unit must have: absent, it is reported and read as "".
template <class U>
UnitKey<U> text(const char* key, std::string U::*m)
{
    return {{key},
            [key, m](const ObjectFields& f, U& u) { u.*m = f.string(key).value_or(""); },
            [key, m](const U& u, ordered& j) { j[key] = u.*m; },
            m};
}

// A point [x, y] the unit must have: absent, it is reported and read as
// (0, 0).
template <class U>
UnitKey<U> point(const char* key, Point2 U::*m)
{
    return {{key},
            [key, m](const ObjectFields& f, U& u) { u.*m = f.point(key).value_or(Point2{}); },
            [key, m](const U& u, ordered& j) { j[key] = io::point(u.*m); },
            m};
}

// The operator's tool pins, "tools": {"roughing": 3}; written when any.
template <class U>
UnitKey<U> pins(ToolPins U::*m)
{
    return {{"tools"},
            [m](const ObjectFields& f, U& u) { u.*m = f.wholeMap("tools"); },
            [m](const U& u, ordered& j) {
                if (!(u.*m).empty()) j["tools"] = io::pins(u.*m);
            }};
}

// An entry of the module's own grammar (an array of corners, of touches...).
template <class U, class Read, class Write>
UnitKey<U> custom(std::initializer_list<const char*> keys, Read read, Write write)
{
    return {{keys.begin(), keys.end()}, std::move(read), std::move(write)};
}

}  // namespace keys

// A module's table: its keys in the file's order, then "cutting" (the
// operator's S and F, read by the job reader, job/job_file_read.cpp) when
// the module's steps take them.
template <class U>
class UnitKeys {
public:
    enum class Cutting { Taken, None };

    UnitKeys(std::vector<UnitKey<U>> entries, Cutting cutting = Cutting::Taken) : entries_(std::move(entries))
    {
        known_ = {"module", "name"};
        for (const UnitKey<U>& e : entries_) known_.insert(known_.end(), e.keys.begin(), e.keys.end());
        if (cutting == Cutting::Taken) known_.push_back("cutting");
    }

    // The entry that reads `key`, or null.
    const UnitKey<U>* find(std::string_view key) const
    {
        for (const UnitKey<U>& e : entries_)
            for (const std::string& k : e.keys)
                if (k == key) return &e;
        return nullptr;
    }

    // The unit read from its object: a key the table does not have is
    // reported, then every entry is read in turn.
    U read(const ObjectFields& f) const
    {
        U u{};
        f.rejectUnknown(std::string("module ") + U::kName, known_);
        for (const UnitKey<U>& e : entries_) e.read(f, u);
        return u;
    }

    void write(const U& u, ordered& j) const
    {
        for (const UnitKey<U>& e : entries_) e.write(u, j);
    }

private:
    std::vector<UnitKey<U>> entries_;
    std::vector<std::string> known_;
};

}  // namespace taiwa::io
