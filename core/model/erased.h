// The holder behind the model's type-erased values (a unit's module input,
// model/module.h; a step's payload, model/step_payload.h): a struct the
// model does not know, held on the heap with value semantics — == compares
// it by value, and a copy behaves as a copy of its own. Copies share the
// held value until one of them is changed (`mut` clones a shared value
// first), so the job held as typed and in mm, a plan's steps and the
// station's cached ones keep one copy of what none of them changes. `Data`
// is the value's interface; it provides
//   const char* name() const;  std::unique_ptr<Data> clone() const;
//   bool equals(const Data&) const;
// and `Of<T>` (a class of Data holding a T as `value`, made over Holding
// below) the typed access.
#pragma once

#include <memory>
#include <utility>  // std::in_place_type

namespace taiwa::detail {

template <class Data>
class Erased {
public:
    Erased() = default;
    // A new value of class Of (a Data holding a T) made from `args`, the
    // value and its share count in one allocation (std::make_shared): a
    // plan holds one payload for each of its hundreds of thousands of steps.
    template <class Of, class... Args>
    explicit Erased(std::in_place_type_t<Of>, Args&&... args) : d_(std::make_shared<Of>(std::forward<Args>(args)...))
    {
    }

    const Data* get() const { return d_.get(); }
    // The held value for changing it: a value shared with a copy is cloned
    // first, so that the copy keeps what it had.
    Data* mut()
    {
        if (d_ && d_.use_count() > 1) d_ = std::shared_ptr<Data>(d_->clone());
        return d_.get();
    }
    // The held value when it is of class Of (a Data holding a T), else nullptr.
    template <class Of>
    const Of* as() const
    {
        return dynamic_cast<const Of*>(d_.get());
    }
    template <class Of>
    Of* asMut()
    {
        // The kind tested once; the copy mut() may make is of the same kind.
        return dynamic_cast<Of*>(d_.get()) ? static_cast<Of*>(mut()) : nullptr;
    }

    friend bool operator==(const Erased& a, const Erased& b)
    {
        if (!a.d_ || !b.d_) return !a.d_ && !b.d_;
        return a.d_ == b.d_ || a.d_->equals(*b.d_);
    }

private:
    std::shared_ptr<Data> d_;
};

// The part of every `Of<T>` that is the same: the T held as `value`, its
// name (T::kName), its clone and its comparison. `Of` is the final class
// (it may add what its Data asks more of, as a module input its length
// conversion).
template <class Data, class T, class Of>
class Holding : public Data {
public:
    explicit Holding(T v) : value(std::move(v)) {}
    const char* name() const override { return T::kName; }
    std::unique_ptr<Data> clone() const override { return std::make_unique<Of>(static_cast<const Of&>(*this)); }
    bool equals(const Data& other) const override
    {
        const auto* o = dynamic_cast<const Of*>(&other);
        return o && o->value == value;
    }
    T value;
};

}  // namespace taiwa::detail
