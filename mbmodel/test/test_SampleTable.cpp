#include "mbmodel/SampleTable.h"

#include "mbmodel/HugePageMemory.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <stdexcept>
#include <vector>

using namespace rockroll;

namespace {
std::vector<double> makeRow(std::size_t k, std::size_t width) {
    std::vector<double> r(width);
    for (std::size_t j = 0; j < width; ++j) r[j] = double(k) + 0.001 * double(j);
    return r;
}
}  // namespace

TEST(SampleTable, KeepsRowsInOrderAcrossGrowth) {
    // No reserve: the table grows by doubling from 64 rows; every row stays as appended.
    SampleTable t;
    const std::size_t width = 7, rows = 1000;
    for (std::size_t k = 0; k < rows; ++k) {
        const std::vector<double> r = makeRow(k, width);
        const SampleTable::Row stored = t.append(r[0], SampleTable::Row(r).subspan(1));
        ASSERT_EQ(toVector(stored), r);
    }
    ASSERT_EQ(t.size(), rows);
    ASSERT_EQ(t.getWidth(), width);
    std::size_t k = 0;
    for (const auto& row : t) EXPECT_EQ(toVector(row), makeRow(k++, width));
    EXPECT_EQ(k, rows);
    EXPECT_EQ(t.end() - t.begin(), std::ptrdiff_t(rows));
    EXPECT_EQ(toVector(t.front()), makeRow(0, width));
    EXPECT_EQ(toVector(t.back()), makeRow(rows - 1, width));
    EXPECT_EQ(t.data() + 5 * width, t[5].data());  // one block, rows one after another
}

TEST(SampleTable, ReservedLargeTableLivesInWholeHugePages) {
    // The reduced model's 20 s: 4 001 rows of 25 values, 800 KB.
    SampleTable t;
    t.reserve(4001, 25);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(t.data()) % kHugePageBytes, 0u);
    const double* first = t.data();
    for (std::size_t k = 0; k < 4001; ++k) t.push_back(makeRow(k, 25));
    EXPECT_EQ(t.data(), first);  // no reallocation within the reservation
    EXPECT_EQ(toVector(t[4000]), makeRow(4000, 25));
}

TEST(SampleTable, RowsOfAnotherWidthAreRefused) {
    SampleTable t{{0, 1, 2}, {1, 2, 3}};
    EXPECT_THROW(t.push_back({1, 2}), std::invalid_argument);
    EXPECT_THROW(t.reserve(10, 4), std::invalid_argument);
    EXPECT_THROW(t.set(0, {1, 2, 3, 4}), std::invalid_argument);
    EXPECT_THROW(t.set(2, {1, 2, 3}), std::invalid_argument);
    EXPECT_THROW(SampleTable().push_back(std::vector<double>{}), std::invalid_argument);
    EXPECT_EQ(t.size(), 2u);
    t.set(1, {5, 6, 7});
    EXPECT_EQ(toVector(t[1]), (std::vector<double>{5, 6, 7}));
}

TEST(SampleTable, CopiesAreEqualAndIndependent) {
    SampleTable a;
    for (std::size_t k = 0; k < 100; ++k) a.push_back(makeRow(k, 3));
    SampleTable b = a;
    EXPECT_EQ(a, b);
    EXPECT_NE(a.data(), b.data());
    b.set(50, {0, 0, 0});
    EXPECT_FALSE(a == b);
    EXPECT_EQ(toVector(a[50]), makeRow(50, 3));
    SampleTable c = std::move(b);
    EXPECT_TRUE(b.empty());
    EXPECT_EQ(toVector(c[50]), (std::vector<double>{0, 0, 0}));
    c = a;
    EXPECT_EQ(c, a);
    EXPECT_FALSE(c == SampleTable({{0, 1, 2}}));
    EXPECT_EQ(SampleTable(), SampleTable());
}

TEST(SampleTable, AppendsAndSetsItsOwnRowsAcrossGrowth) {
    // Rows of the table appended to it, each from an earlier row, while it moves to larger
    // blocks (at 64, 128 and 256 rows), by push_back and by append; then a row set from
    // another. Under the sanitize build a row read after its block was freed is reported.
    for (const bool byAppend : {false, true}) {
        SampleTable t;
        t.push_back({0, 1, 2});
        for (std::size_t k = 1; k < 300; ++k) {
            const SampleTable::Row from = t[k / 2];
            if (byAppend)
                t.append(from[0] + 1000, from.subspan(1));
            else
                t.push_back(from);
        }
        ASSERT_EQ(t.size(), 300u);
        for (std::size_t k = 1; k < 300; ++k) {
            const double expected = t[k / 2][0] + (byAppend ? 1000 : 0);
            EXPECT_EQ(toVector(t[k]), (std::vector<double>{expected, 1, 2}))
                << k << (byAppend ? " append" : " push_back");
        }
        t.set(7, t[8]);
        EXPECT_EQ(toVector(t[7]), toVector(t[8]));
        t.set(7, t[7]);
        EXPECT_EQ(toVector(t[7]), toVector(t[8]));
    }
}

TEST(SampleTable, KeepsItsWidthWhenCopiedEmptyAndRefusesImpossibleSizes) {
    SampleTable t;
    t.reserve(10, 4);
    const SampleTable copy = t;
    EXPECT_EQ(copy.getWidth(), 4u);
    SampleTable c = copy;
    EXPECT_THROW(c.push_back({1, 2}), std::invalid_argument);
    EXPECT_THROW(t.reserve(std::size_t(-1) / 4, 4), std::length_error);
    EXPECT_TRUE(t.empty());
    static_assert(std::random_access_iterator<SampleTable::const_iterator>);
}

TEST(HugePageMemory, LargeBuffersAreWholeAlignedBlocks) {
    EXPECT_EQ(getLargeBufferCapacity(1000), 1000u);
    EXPECT_EQ(getLargeBufferCapacity(kLargeBufferBytes - 1), kLargeBufferBytes - 1);
    EXPECT_EQ(getLargeBufferCapacity(kLargeBufferBytes), kHugePageBytes);
    EXPECT_EQ(getLargeBufferCapacity(kHugePageBytes + 1), 2 * kHugePageBytes);
    const std::size_t sizes[] = {0, 8, 1000, kLargeBufferBytes, 3 * kHugePageBytes};
    for (std::size_t bytes : sizes) {
        void* p = allocateLargeBuffer(bytes);
        const std::size_t alignment = bytes >= kLargeBufferBytes ? kHugePageBytes : 64;
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % alignment, 0u) << bytes;
        static_cast<char*>(p)[getLargeBufferCapacity(bytes) > 0 ? getLargeBufferCapacity(bytes) - 1 : 0] = 1;
        std::free(p);
    }
}

TEST(HugePageMemory, ArenaGivesAlignedDisjointStorage) {
    HugePageArena empty;
    EXPECT_NE(empty.allocate(0), nullptr);  // a fresh arena's first request makes its first block
    EXPECT_EQ(empty.getBlockCount(), 1u);
    HugePageArena arena;
    EXPECT_EQ(arena.getBlockCount(), 0u);
    std::vector<std::pair<char*, std::size_t>> taken;
    for (std::size_t k = 0; k < 300; ++k) {
        const std::size_t bytes = 1000 + 70 * k, alignment = std::size_t(1) << (k % 8);
        char* p = static_cast<char*>(arena.allocate(bytes, alignment));
        EXPECT_EQ(reinterpret_cast<std::uintptr_t>(p) % alignment, 0u);
        for (const auto& [q, n] : taken) ASSERT_TRUE(p + bytes <= q || q + n <= p) << "overlap at " << k;
        std::fill(p, p + bytes, char(k));
        taken.emplace_back(p, bytes);
    }
    // 300 allocations of 1 000–22 000 bytes, 3.4 MB in all: two blocks or more.
    EXPECT_GE(arena.getBlockCount(), 2u);
    for (std::size_t k = 0; k < taken.size(); ++k)
        for (std::size_t i = 0; i < taken[k].second; ++i) ASSERT_EQ(taken[k].first[i], char(k));
    // Objects on their own cache lines; arrays value-initialized.
    std::atomic<const int*>* slots = arena.makeArray<std::atomic<const int*>>(1000);
    for (int i = 0; i < 1000; ++i) ASSERT_EQ(slots[i].load(), nullptr);
    const std::pair<int, double>* pair = arena.make<std::pair<int, double>>(3, 0.5);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(slots) % 64, 0u);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(pair) % 64, 0u);
    EXPECT_EQ(*pair, std::make_pair(3, 0.5));
    EXPECT_NO_THROW(arena.allocate(kHugePageBytes));
    EXPECT_THROW(arena.allocate(kHugePageBytes + 1), std::invalid_argument);
    EXPECT_THROW(arena.allocate(8, 3), std::invalid_argument);
    EXPECT_THROW(arena.allocate(8, 8192), std::invalid_argument);
}
