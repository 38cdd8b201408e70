#include "mbmodel/Parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <optional>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>
#include <thread>
#include <vector>

namespace rockroll {

void parallelFor(std::size_t count, int threads, const std::function<void(std::size_t)>& job) {
    if (count == 0) return;
    // The stack std::thread gave the jobs before (8 MB), for TBB's workers too.
    static const tbb::global_control stack(tbb::global_control::thread_stack_size, 8u << 20);
    std::vector<std::exception_ptr> errors(count);
    std::atomic<std::size_t> next{0};
    auto worker = [&] {
        for (std::size_t i = next++; i < count; i = next++) {
            try {
                job(i);
            } catch (...) {
                errors[i] = std::current_exception();
            }
        }
    };
    const bool nested = threads <= 0;
    const int limit = nested ? tbb::this_task_arena::max_concurrency() : threads;
    const int n = int(std::min<std::size_t>(std::size_t(std::max(1, limit)), count));
    auto run = [&] {
        tbb::task_group group;
        for (int k = 1; k < n; ++k) group.run(worker);
        worker();  // the calling thread is one of the n
        group.wait();
    };
    if (n == 1) {
        worker();
    } else if (nested) {
        run();  // in the enclosing arena: its limit holds
    } else {
        // TBB allows one thread per core by default; --jobs may ask for more.
        std::optional<tbb::global_control> allow;
        if (std::size_t(n) > tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism))
            allow.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(n));
        tbb::task_arena arena(n);
        arena.execute(run);
    }
    for (const auto& e : errors)
        if (e) std::rethrow_exception(e);
}

int resolveJobCount(int requested) {
    return requested > 0 ? requested : int(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace rockroll
