// A machining unit's module input as a value the job model can hold without
// knowing the module kinds: copied as a value (copies share the input until
// one is changed, model/erased.h), compared by value, converted
// between length units. Each kind's input struct lives in its own folder
// (core/modules/<kind>/) and everything else about the kind sits behind its
// door (core/modules/module_kind.h).
//
// A module input struct T provides:
//   static constexpr const char* kName;             // "M4": the job file's "module"
//   void convertLengths(const LengthMap& f);         // every length through f
//   friend bool operator==(const T&, const T&);
#pragma once

#include "model/erased.h"

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace taiwa {

// One length conversion (mm -> inch and back): applied to every length of a
// module input, never to angles, codes or counts.
using LengthMap = std::function<double(double)>;

namespace detail {

class ModuleData {
public:
    virtual ~ModuleData() = default;
    virtual const char* name() const = 0;
    virtual std::unique_ptr<ModuleData> clone() const = 0;
    virtual bool equals(const ModuleData& other) const = 0;
    virtual void convertLengths(const LengthMap& f) = 0;
};

template <class T>
class ModuleDataOf final : public Holding<ModuleData, T, ModuleDataOf<T>> {
public:
    using Holding<ModuleData, T, ModuleDataOf<T>>::Holding;
    void convertLengths(const LengthMap& f) override { this->value.convertLengths(f); }
};

}  // namespace detail

class ModuleInput {
public:
    ModuleInput() = default;  // no module (a unit being built); name() is ""
    template <class T, class = std::enable_if_t<!std::is_same_v<std::decay_t<T>, ModuleInput>>>
    ModuleInput(T value)  // NOLINT(google-explicit-constructor): a module struct is a module input
        : data_(std::in_place_type<detail::ModuleDataOf<std::decay_t<T>>>, std::move(value))
    {
    }

    bool empty() const { return !data_.get(); }
    // "M4", "M2D"; "" when empty.
    const char* name() const { return data_.get() ? data_.get()->name() : ""; }

    template <class T>
    const T* getIf() const
    {
        const auto* d = data_.as<detail::ModuleDataOf<T>>();
        return d ? &d->value : nullptr;
    }
    // For changing the input (a copy sharing it keeps what it had).
    template <class T>
    T* getIf()
    {
        auto* d = data_.asMut<detail::ModuleDataOf<T>>();
        return d ? &d->value : nullptr;
    }
    template <class T>
    bool is() const
    {
        return getIf<T>() != nullptr;
    }
    // The input as T; throws std::logic_error when it is another kind.
    template <class T>
    const T& as() const
    {
        if (const T* v = getIf<T>()) return *v;
        throw std::logic_error(std::string("module input is ") + name() + ", not " + T::kName);
    }
    template <class T>
    T& as()
    {
        if (T* v = getIf<T>()) return *v;
        throw std::logic_error(std::string("module input is ") + name() + ", not " + T::kName);
    }

    void convertLengths(const LengthMap& f)
    {
        if (data_.get()) data_.mut()->convertLengths(f);
    }

    friend bool operator==(const ModuleInput& a, const ModuleInput& b) { return a.data_ == b.data_; }

private:
    detail::Erased<detail::ModuleData> data_;
};

}  // namespace taiwa
