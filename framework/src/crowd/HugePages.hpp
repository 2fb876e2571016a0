#pragma once
// Large arrays the crowd step reads all over on every step (the ground maps,
// the agents), moved onto 2 MiB pages where the system allows it. A step at
// 10,000 agents reads texels in some thousand 4 KiB pages of a 2048 x 2048
// height map; each look-up that misses the TLB walks the page tables (twice
// over under a hypervisor), which cost more than the look-up itself. The
// values stay what they were: only where they lie changes. Private to
// framework/src/crowd.

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace stoa {

constexpr std::size_t kHugePage = std::size_t{2} << 20;

/// Asks for huge pages for the whole 2 MiB pages in [data, data + bytes), before they are first written.
inline void adviseHugePages(const void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const auto begin = (reinterpret_cast<std::uintptr_t>(data) + kHugePage - 1) & ~(kHugePage - 1);
    const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHugePage - 1);
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);   // a hint: failure is fine
#else
    (void)data;
    (void)bytes;
#endif
}

/// `values` copied into storage of `capacity` elements (at least its size)
/// advised onto huge pages first; arrays under 2 MiB stay as they are.
template <typename T>
void moveOntoHugePages(std::vector<T>& values, std::size_t capacity = 0) {
    capacity = capacity > values.size() ? capacity : values.size();
    if (capacity * sizeof(T) < kHugePage) return;
    std::vector<T> moved;
    moved.reserve(capacity);
    adviseHugePages(moved.data(), capacity * sizeof(T));
    moved.assign(values.begin(), values.end());
    values.swap(moved);
}

} // namespace stoa
