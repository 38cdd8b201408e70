// The program's one thread pool (mbmodel/Parallel.h): every job runs once, results
// stored by index do not depend on the number of threads, errors are rethrown by
// lowest index, and nested loops share the enclosing limit.
#include "mbmodel/Parallel.h"

#include <atomic>
#include <gtest/gtest.h>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace rockroll;

TEST(Parallel, EveryJobRunsOnceAndResultsDoNotDependOnThreads) {
    auto compute = [](int threads) {
        std::vector<double> out(200);
        parallelFor(out.size(), threads, [&](size_t i) {
            double x = 0;
            for (int k = 1; k < 2000; ++k) x += 1.0 / (double(i) + k);
            out[i] = x;
        });
        return out;
    };
    const auto one = compute(1);
    for (int threads : {2, 3, 8}) EXPECT_EQ(compute(threads), one) << threads;
    parallelFor(0, 4, [](size_t) { FAIL() << "no job to run"; });
}

TEST(Parallel, AtMostTheGivenNumberOfThreadsAtOnce) {
    for (int threads : {1, 2, 5}) {
        std::atomic<int> running{0}, most{0};
        parallelFor(40, threads, [&](size_t) {
            const int now = ++running;
            int m = most;
            while (now > m && !most.compare_exchange_weak(m, now)) {
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
            --running;
        });
        EXPECT_LE(most.load(), threads);
        if (threads == 5) {
            EXPECT_GT(most.load(), 1) << "--jobs above the core count must still run in parallel";
        }
    }
}

TEST(Parallel, AllJobsRunAndTheLowestFailedIndexIsRethrown) {
    std::atomic<int> ran{0};
    try {
        parallelFor(30, 3, [&](size_t i) {
            ++ran;
            if (i == 25 || i == 7 || i == 12) throw std::invalid_argument("job " + std::to_string(i));
        });
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_EQ(std::string(e.what()), "job 7");
    }
    EXPECT_EQ(ran.load(), 30);
}

TEST(Parallel, NestedLoopsStayWithinTheEnclosingLimit) {
    std::mutex m;
    std::set<std::thread::id> ids;
    std::vector<std::vector<int>> out(4, std::vector<int>(50));
    parallelFor(4, 2, [&](size_t i) {
        parallelFor(50, 0, [&](size_t k) {
            {
                std::lock_guard<std::mutex> lock(m);
                ids.insert(std::this_thread::get_id());
            }
            out[i][k] = int(i * 100 + k);
        });
    });
    EXPECT_LE(ids.size(), 2u);
    for (size_t i = 0; i < 4; ++i)
        for (int k = 0; k < 50; ++k) EXPECT_EQ(out[i][k], int(i * 100 + k));
}
