// What a step's module makes of it (model/step.h): a milling step's
// geometry (model/milling_geometry.h: outline or region, depths,
// allowances), alone or with the module's own data — a side-milling step's
// contour and passes, a face's pass angle, an area's drawn points, a hole
// pattern's centres, an inclined face — or a turning step's path and
// speeds; held by the step without the model knowing the module. Copied as
// a value (copies share one struct until one of them is changed, model/erased.h),
// compared by value, the way ModuleInput holds a unit's input
// (model/module.h). Each payload struct lives in its module's folder (M2D's
// inclined face beside the pocket modules' shared code that reads it;
// TURN's TurnStep in model/turn_path.h, for the stages that read it) and
// provides
//   static constexpr const char* kName;   // "SIDE passes", for messages
//   friend bool operator==(const T&, const T&);
// and, for a milling module's step, its geometry: T is MillingGeometry
// itself, or holds one as its member `milling`.
#pragma once

#include "model/erased.h"
#include "model/milling_geometry.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace taiwa {

class StepPayload {
public:
    StepPayload() = default;  // a step with no data of its module's own
    template <class T, class = std::enable_if_t<!std::is_same_v<std::decay_t<T>, StepPayload>>>
    StepPayload(T value)  // NOLINT(google-explicit-constructor): a payload struct is a payload
        : data_(std::in_place_type<Of<std::decay_t<T>>>, std::move(value))
    {
        // The stages find a milling step's geometry as the payload itself or
        // as its member `milling` (millingIn): a payload deriving from it
        // would hold a geometry none of them sees.
        static_assert(std::is_same_v<std::decay_t<T>, MillingGeometry> ||
                          !std::is_base_of_v<MillingGeometry, std::decay_t<T>>,
                      "a step payload holds its milling geometry as its member `milling`, not as a base");
    }

    bool empty() const { return !data_.get(); }
    const char* name() const { return data_.get() ? data_.get()->name() : "nothing"; }

    // The milling geometry the payload holds (itself, or its member
    // `milling`); nullptr for a payload without (a turning step's).
    const MillingGeometry* milling() const { return data_.get() ? data_.get()->milling() : nullptr; }
    // The same for changing it (a payload shared with a copy is cloned first).
    MillingGeometry* editMilling()
    {
        if (!data_.get() || !data_.get()->milling()) return nullptr;
        return data_.mut()->milling();
    }

    template <class T>
    const T* getIf() const
    {
        const auto* d = data_.as<Of<T>>();
        return d ? &d->value : nullptr;
    }
    // The payload as T; throws std::logic_error when the step holds another
    // (a step handed to a module that did not make it).
    template <class T>
    const T& as() const
    {
        if (const T* v = getIf<T>()) return *v;
        throw std::logic_error(std::string("step holds ") + name() + ", not " + T::kName);
    }

    friend bool operator==(const StepPayload& a, const StepPayload& b) { return a.data_ == b.data_; }

private:
    struct Data {
        virtual ~Data() = default;
        virtual const char* name() const = 0;
        virtual std::unique_ptr<Data> clone() const = 0;
        virtual bool equals(const Data& other) const = 0;
        virtual const MillingGeometry* milling() const = 0;
        virtual MillingGeometry* milling() = 0;
    };
    template <class T>
    struct Of final : detail::Holding<Data, T, Of<T>> {
        using detail::Holding<Data, T, Of<T>>::Holding;
        const MillingGeometry* milling() const override { return millingIn(this->value); }
        MillingGeometry* milling() override { return millingIn(this->value); }
    };
    template <class V>
    static auto* millingIn(V& v)
    {
        using G = std::conditional_t<std::is_const_v<V>, const MillingGeometry, MillingGeometry>;
        if constexpr (std::is_same_v<std::remove_const_t<V>, MillingGeometry>)
            return &v;
        else if constexpr (requires { v.milling; })
            return static_cast<G*>(&v.milling);
        else
            return static_cast<G*>(nullptr);
    }
    detail::Erased<Data> data_;
};

}  // namespace taiwa
