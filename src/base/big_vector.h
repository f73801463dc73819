#pragma once
// Big arrays (BVH nodes, a mesh's triangles and blocks, the build's temporaries) on 2 MB pages
// where the kernel allows it, as Embree allocates its own. With 4 KB pages every first touch is a
// page fault; on this project's virtual machine those faults were most of a 1M-triangle build
// (0.56 s, of which 0.11 s filling the build's own 32 MB of references alone; bench/RESULTS.md).
// Linux gives transparent huge pages to ranges marked with madvise (Debian's default "madvise"
// mode); elsewhere, or below 2 MB, this is the ordinary allocator.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>
#ifdef __linux__
#include <sys/mman.h>
#endif

namespace whitted {

template <class T>
struct HugePageAllocator {
    using value_type = T;
    static constexpr std::size_t kHugePage = std::size_t(2) << 20;

    HugePageAllocator() = default;
    template <class U>
    HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        if (n > (std::size_t(PTRDIFF_MAX) - kHugePage) / sizeof(T)) throw std::bad_array_new_length();
        const std::size_t bytes = n * sizeof(T);
        if (bytes < kHugePage) return std::allocator<T>().allocate(n);
        // Aligned, so that every whole 2 MB stretch of the array can be one page; only the array's
        // own bytes are marked (the part of a last page it does not fill stays small pages).
        void* p = std::aligned_alloc(kHugePage, (bytes + kHugePage - 1) / kHugePage * kHugePage);
        if (!p) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
        madvise(p, bytes / kHugePage * kHugePage, MADV_HUGEPAGE);  // advice: failure changes nothing
#endif
        return static_cast<T*>(p);
    }
    void deallocate(T* p, std::size_t n) noexcept {
        if (n * sizeof(T) < kHugePage) std::allocator<T>().deallocate(p, n);
        else std::free(p);
    }
    template <class U>
    bool operator==(const HugePageAllocator<U>&) const noexcept { return true; }
};

template <class T>
using BigVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace whitted
