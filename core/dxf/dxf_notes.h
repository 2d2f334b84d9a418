// The warnings a DXF import collects, kept to a readable number: after the
// first hundred only a count of the rest. Internal to core/dxf/.
#pragma once

#include "model/translate_noop.h"

#include <fmt/format.h>

#include <string>
#include <vector>

namespace taiwa::dxf::detail {

class Notes {
public:
    void add(std::string text)
    {
        if (list_.size() < kMax) list_.push_back(std::move(text));
        else ++suppressed_;
    }
    std::vector<std::string> take()
    {
        if (suppressed_ > 0)
            list_.push_back(fmt::format(TAIWA_TRANSLATE_NOOP("taiwa::msg", "… and {} more warnings like these"), suppressed_));
        suppressed_ = 0;
        return std::move(list_);
    }

private:
    static constexpr std::size_t kMax = 100;
    std::vector<std::string> list_;
    std::size_t suppressed_ = 0;
};

}  // namespace taiwa::dxf::detail
