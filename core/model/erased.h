// The holder behind the model's type-erased values (a unit's module input,
// model/module.h; a step's payload, model/step_payload.h): a struct the
// model does not know, held on the heap with value semantics — copies clone
// it, == compares it by value. `Data` is the value's interface; it provides
//   std::unique_ptr<Data> clone() const;  bool equals(const Data&) const;
// and `Of<T>` (a class of Data holding a T as `value`) the typed access.
#pragma once

#include <memory>
#include <utility>

namespace taiwa::detail {

template <class Data>
class Erased {
public:
    Erased() = default;
    explicit Erased(std::unique_ptr<Data> d) : d_(std::move(d)) {}
    Erased(const Erased& o) : d_(o.d_ ? o.d_->clone() : nullptr) {}
    Erased(Erased&&) noexcept = default;
    Erased& operator=(const Erased& o)
    {
        if (this != &o) d_ = o.d_ ? o.d_->clone() : nullptr;
        return *this;
    }
    Erased& operator=(Erased&&) noexcept = default;

    Data* get() const { return d_.get(); }
    // The held value when it is of class Of (a Data holding a T), else nullptr.
    template <class Of>
    Of* as() const
    {
        return dynamic_cast<Of*>(d_.get());
    }

    friend bool operator==(const Erased& a, const Erased& b)
    {
        if (!a.d_ || !b.d_) return !a.d_ && !b.d_;
        return a.d_->equals(*b.d_);
    }

private:
    std::unique_ptr<Data> d_;
};

}  // namespace taiwa::detail
