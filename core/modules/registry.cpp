// The registration of the module kinds: one line in TAIWA_MODULES a module,
// naming the function `<name>Module()` its folder defines
// (core/modules/<name>/<name>_kind.cpp). See docs/modules.md.
#include "modules/registry.h"

#include <stdexcept>

#define TAIWA_MODULES(X) \
    X(m4)                \
    X(m2d)               \
    X(probe)             \
    X(turn)              \
    X(cp)                \
    X(holes)             \
    X(area)              \
    X(face)              \
    X(side)

namespace taiwa {

#define TAIWA_DECLARE_MODULE(name) const ModuleKind& name##Module();
TAIWA_MODULES(TAIWA_DECLARE_MODULE)
#undef TAIWA_DECLARE_MODULE

const std::vector<const ModuleKind*>& moduleKinds()
{
#define TAIWA_LIST_MODULE(name) &name##Module(),
    static const std::vector<const ModuleKind*> kinds{TAIWA_MODULES(TAIWA_LIST_MODULE)};
#undef TAIWA_LIST_MODULE
    return kinds;
}

const ModuleKind* findModuleKind(std::string_view name)
{
    for (const ModuleKind* k : moduleKinds())
        if (name == k->name()) return k;
    return nullptr;
}

const ModuleKind& moduleKind(const ModuleInput& m)
{
    if (const ModuleKind* k = findModuleKind(m.name())) return *k;
    throw std::logic_error(std::string("no module kind named '") + m.name() + "'");
}

std::vector<std::string> moduleNames()
{
    std::vector<std::string> names;
    for (const ModuleKind* k : moduleKinds()) names.emplace_back(k->name());
    return names;
}

}  // namespace taiwa
