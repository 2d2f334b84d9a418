// A text that many values may hold the same of — a step's reason for its
// tool (model/tool.h), the same sentence for every unit of a size — kept
// once: copies share one immutable string, == compares the text. A
// TextPool makes equal texts made apart one (the planner passes every
// step's reason through one), so 100,000 alike units hold a few hundred
// sentences, not 400,000.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>

namespace taiwa {

class SharedText {
public:
    SharedText() = default;
    SharedText(std::string s)  // NOLINT(google-explicit-constructor): a text is a shared text
        : p_(s.empty() ? nullptr : std::make_shared<const std::string>(std::move(s)))
    {
    }
    SharedText(const char* s) : SharedText(std::string(s)) {}  // NOLINT(google-explicit-constructor)

    const std::string& str() const
    {
        static const std::string none;
        return p_ ? *p_ : none;
    }
    operator const std::string&() const { return str(); }  // NOLINT(google-explicit-constructor)
    bool empty() const { return !p_; }

    friend bool operator==(const SharedText& a, const SharedText& b) { return a.p_ == b.p_ || a.str() == b.str(); }

private:
    std::shared_ptr<const std::string> p_;
};

// Equal texts made one: share(t) gives t the first text equal to it that
// the pool saw (and keeps t's own when it is the first).
class TextPool {
public:
    void share(SharedText& t)
    {
        if (t.empty()) return;
        const auto [it, fresh] = texts_.insert(t);
        if (!fresh) t = *it;
    }

private:
    struct Hash {
        std::size_t operator()(const SharedText& t) const { return std::hash<std::string_view>()(t.str()); }
    };
    std::unordered_set<SharedText, Hash> texts_;
};

}  // namespace taiwa
