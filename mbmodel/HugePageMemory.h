#pragma once
// Memory for large, long-lived buffers, in whole 2 MB blocks advised MADV_HUGEPAGE.
//
// On the virtual machines measured (bench/README.md, "Bespoke models") the first touch of a
// fresh 4 KB page costs about 11 µs and that of a 2 MB huge page about 130 µs, so a buffer of
// more than a dozen pages is cheaper as huge pages. A run's history (the reduced model's
// 20 s: 4 001 samples of 25 values, 200 pages) and the truck-mode cache's factorizations
// live in such blocks. The advice is only advice: where the system gives no huge pages
// (transparent huge pages "never") the blocks are ordinary pages.
#include <algorithm>
#include <cstddef>
#include <mutex>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace rockroll {

inline constexpr std::size_t kHugePageBytes = std::size_t(2) << 20;
/// The smallest buffer allocateLargeBuffer puts in huge pages (at most 8 times the memory
/// it asks for; at least 64 first touches of 4 KB pages saved).
inline constexpr std::size_t kLargeBufferBytes = std::size_t(256) << 10;

/// A buffer of at least `bytes`, aligned to 64 bytes: from kLargeBufferBytes on, whole
/// 2 MB blocks, 2 MB-aligned, with huge-page advice; below it, the heap's. Release it
/// with std::free. Throws std::bad_alloc.
void* allocateLargeBuffer(std::size_t bytes);
/// What allocateLargeBuffer(bytes) gives, in bytes (`bytes` or whole 2 MB blocks).
std::size_t getLargeBufferCapacity(std::size_t bytes);

/// Objects kept as long as the arena, bump-allocated in 2 MB huge-page blocks. Thread-safe.
class HugePageArena {
public:
    HugePageArena() = default;
    ~HugePageArena();
    HugePageArena(const HugePageArena&) = delete;
    HugePageArena& operator=(const HugePageArena&) = delete;
    /// `bytes` (at most kHugePageBytes) aligned to `alignment` (a power of two ≤ 4096),
    /// uninitialized.
    void* allocate(std::size_t bytes, std::size_t alignment = 64);
    /// A T made from `args` (default-initialized without them) on its own cache line, or on
    /// T's alignment if larger, kept until the arena goes: T must need no destructor.
    template <class T, class... Args>
    T* make(Args&&... args) {
        static_assert(std::is_trivially_destructible_v<T>, "the arena frees its blocks without destructors");
        void* p = allocate(sizeof(T), std::max<std::size_t>(alignof(T), 64));
        if constexpr (sizeof...(Args) == 0)
            return new (p) T;
        else
            return new (p) T(std::forward<Args>(args)...);
    }
    /// n value-initialized Ts, one after another, as make.
    template <class T>
    T* makeArray(std::size_t n) {
        static_assert(std::is_trivially_destructible_v<T>, "the arena frees its blocks without destructors");
        const std::size_t alignment = std::max<std::size_t>(alignof(T), 64);
        T* first = static_cast<T*>(allocate(std::max<std::size_t>(1, n) * sizeof(T), alignment));
        for (std::size_t i = 0; i < n; ++i) new (first + i) T();
        return first;
    }
    std::size_t getBlockCount() const;

private:
    mutable std::mutex mutex_;
    std::vector<void*> blocks_;
    std::size_t used_ = kHugePageBytes;  ///< bytes taken in the last block
};

}  // namespace rockroll
