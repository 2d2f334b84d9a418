// Boxed<T>: an optional value kept on the heap, for a member that few
// objects have and that would make every object large if held in place
// (a Step's turning data: 392 bytes that milling steps, nearly all the
// steps of a large job, do not use). Copies copy the value; it reads like
// std::optional (has_value, *, ->, ==, = value, = std::nullopt).
#pragma once

#include <memory>
#include <optional>
#include <utility>

namespace taiwa {

template <class T>
class Boxed {
public:
    Boxed() = default;
    Boxed(std::nullopt_t) {}
    Boxed(T value) : p_(std::make_unique<T>(std::move(value))) {}
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
    ~Boxed() = default;

    bool has_value() const { return p_ != nullptr; }
    explicit operator bool() const { return has_value(); }
    T& operator*() { return *p_; }
    const T& operator*() const { return *p_; }
    T* operator->() { return p_.get(); }
    const T* operator->() const { return p_.get(); }

    friend bool operator==(const Boxed& a, const Boxed& b) { return a.p_ ? b.p_ && *a.p_ == *b.p_ : !b.p_; }

private:
    std::unique_ptr<T> p_;
};

}  // namespace taiwa
