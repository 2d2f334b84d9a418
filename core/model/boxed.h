// An optional value kept on the heap: what std::optional<T> is to a step
// (model/step.h), at the size of one pointer while it is absent. A step
// carries its tool path this way, and its geometry its outline and region: a
// plan of 100,000 units holds some 400,000 steps, most with one of the
// three, and none with a path in `taiwa check`. The same value semantics
// as std::optional — a copy is a copy, == compares the values, * and ->
// reach the value, value() throws std::bad_optional_access when there is
// none — so code written for an optional reads it unchanged.
#pragma once

#include <memory>
#include <optional>
#include <utility>

namespace taiwa {

template <class T>
class Boxed {
public:
    Boxed() = default;
    Boxed(std::nullopt_t) {}                                         // NOLINT(google-explicit-constructor)
    Boxed(const T& v) : p_(std::make_unique<T>(v)) {}                // NOLINT(google-explicit-constructor)
    Boxed(T&& v) : p_(std::make_unique<T>(std::move(v))) {}          // NOLINT(google-explicit-constructor)
    Boxed(const std::optional<T>& v) : p_(v ? std::make_unique<T>(*v) : nullptr) {}  // NOLINT(google-explicit-constructor)
    Boxed(std::optional<T>&& v) : p_(v ? std::make_unique<T>(std::move(*v)) : nullptr) {}  // NOLINT(google-explicit-constructor)
    Boxed(const Boxed& o) : p_(o.p_ ? std::make_unique<T>(*o.p_) : nullptr) {}
    Boxed(Boxed&&) noexcept = default;
    Boxed& operator=(const Boxed& o)
    {
        if (this != &o) p_ = o.p_ ? std::make_unique<T>(*o.p_) : nullptr;
        return *this;
    }
    Boxed& operator=(Boxed&&) noexcept = default;
    Boxed& operator=(std::nullopt_t)
    {
        p_.reset();
        return *this;
    }
    Boxed& operator=(const T& v)
    {
        if (p_) *p_ = v;
        else p_ = std::make_unique<T>(v);
        return *this;
    }
    Boxed& operator=(T&& v)
    {
        if (p_) *p_ = std::move(v);
        else p_ = std::make_unique<T>(std::move(v));
        return *this;
    }
    Boxed& operator=(const std::optional<T>& v) { return v ? *this = *v : *this = std::nullopt; }

    template <class... Args>
    T& emplace(Args&&... args)
    {
        p_ = std::make_unique<T>(std::forward<Args>(args)...);
        return *p_;
    }
    void reset() noexcept { p_.reset(); }

    bool has_value() const noexcept { return p_ != nullptr; }
    explicit operator bool() const noexcept { return p_ != nullptr; }
    T& operator*() { return *p_; }
    const T& operator*() const { return *p_; }
    T* operator->() { return p_.get(); }
    const T* operator->() const { return p_.get(); }
    T& value()
    {
        if (!p_) throw std::bad_optional_access();
        return *p_;
    }
    const T& value() const
    {
        if (!p_) throw std::bad_optional_access();
        return *p_;
    }
    template <class U>
    T value_or(U&& other) const
    {
        return p_ ? *p_ : static_cast<T>(std::forward<U>(other));
    }
    // The value as a std::optional (a copy), for code that keeps one.
    std::optional<T> optional() const { return p_ ? std::optional<T>(*p_) : std::nullopt; }

    friend bool operator==(const Boxed& a, const Boxed& b)
    {
        if (!a.p_ || !b.p_) return !a.p_ && !b.p_;
        return *a.p_ == *b.p_;
    }
    friend bool operator==(const Boxed& a, std::nullopt_t) { return !a.p_; }

private:
    std::unique_ptr<T> p_;
};

}  // namespace taiwa
