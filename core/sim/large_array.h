// Filling a large vector of grid values (a height field, the verifier's
// gouge limits) on memory the kernel may back with 2 MB pages: a 12 M-cell
// grid is 48 MB, and faulting it in 4 KB pages costs more than filling it.
// The vector is reserved (not touched), the kernel is told the range may
// use transparent huge pages (madvise; ignored where they are off), then
// filled. The values are the same as with assign(); only the faults change.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <sys/mman.h>

namespace taiwa::sim {

template <class T>
void assignLarge(std::vector<T>& v, std::size_t n, const T& value)
{
    constexpr std::size_t kHuge = std::size_t{2} << 20;
    v.clear();
    v.shrink_to_fit();
    v.reserve(n);
    const auto begin = reinterpret_cast<std::uintptr_t>(v.data());
    const std::uintptr_t first = (begin + kHuge - 1) & ~(kHuge - 1), end = (begin + n * sizeof(T)) & ~(kHuge - 1);
    if (end > first) madvise(reinterpret_cast<void*>(first), end - first, MADV_HUGEPAGE);
    v.assign(n, value);
}

}  // namespace taiwa::sim
