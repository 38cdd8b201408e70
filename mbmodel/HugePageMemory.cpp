#include "mbmodel/HugePageMemory.h"

#include <algorithm>
#include <cstdlib>
#include <new>
#include <stdexcept>
#include <sys/mman.h>

namespace rockroll {

namespace {
void* allocateHugePageBlocks(std::size_t bytes) {
    void* p = std::aligned_alloc(kHugePageBytes, bytes);
    if (!p) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    ::madvise(p, bytes, MADV_HUGEPAGE);  // advice only: 4 KB pages if refused
#endif
    return p;
}
}  // namespace

std::size_t getLargeBufferCapacity(std::size_t bytes) {
    if (bytes < kLargeBufferBytes) return bytes;
    return (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
}

void* allocateLargeBuffer(std::size_t bytes) {
    if (bytes >= kLargeBufferBytes) return allocateHugePageBlocks(getLargeBufferCapacity(bytes));
    void* p = std::aligned_alloc(64, std::max<std::size_t>(64, (bytes + 63) / 64 * 64));
    if (!p) throw std::bad_alloc();
    return p;
}

HugePageArena::~HugePageArena() {
    for (void* block : blocks_) std::free(block);
}

void* HugePageArena::allocate(std::size_t bytes, std::size_t alignment) {
    if (bytes > kHugePageBytes || alignment == 0 || (alignment & (alignment - 1)) != 0 || alignment > 4096)
        throw std::invalid_argument("HugePageArena::allocate: at most 2 MB, aligned to a power of two up to 4096");
    const std::lock_guard<std::mutex> lock(mutex_);
    std::size_t at = (used_ + alignment - 1) & ~(alignment - 1);
    if (blocks_.empty() || at + bytes > kHugePageBytes) {
        blocks_.reserve(blocks_.size() + 1);  // then push_back cannot throw: no leaked block
        blocks_.push_back(allocateHugePageBlocks(kHugePageBytes));
        at = 0;
    }
    used_ = at + bytes;
    return static_cast<char*>(blocks_.back()) + at;
}

std::size_t HugePageArena::getBlockCount() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return blocks_.size();
}

}  // namespace rockroll
