#pragma once
// The program's one thread pool: oneTBB's. Every parallel loop of rockroll (validate's
// sections, speed sweeps, the describing function's stability checks) goes through
// parallelFor. Jobs are taken in index order and each job writes its result into its
// own slot by index, so results are bitwise the same for any number of threads.
#include <cstddef>
#include <functional>

namespace rockroll {

/// Runs job(0) … job(count − 1) on at most `threads` threads, taking them in index
/// order (put long jobs first). threads > 0 (a --jobs option): exactly that limit, more
/// threads than cores included. threads <= 0: the limit of the enclosing parallelFor
/// when called from one of its jobs (nested loops share its threads instead of adding
/// their own), else one thread per core. Every job runs even when another throws; then
/// the exception of the failed job with the lowest index is rethrown, whatever the
/// order they finished in.
void parallelFor(std::size_t count, int threads, const std::function<void(std::size_t)>& job);

/// A --jobs option's thread count: `requested` when positive, else one per core (at least 1).
int resolveJobCount(int requested);

}  // namespace rockroll
