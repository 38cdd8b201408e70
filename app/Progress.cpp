#include "app/Progress.h"

#include <algorithm>
#include <cstdio>
#include <fmt/format.h>
#include <unistd.h>

namespace rockroll::app {

SweepProgress::SweepProgress(std::string label, size_t total)
    : label_(std::move(label)), total_(total), terminal_(isatty(STDERR_FILENO) == 1),
      start_(std::chrono::steady_clock::now()) {}

std::string SweepProgress::formatLine(size_t done, size_t total, const SweepPoint& p, double etaS) {
    const std::string result = p.failed ? "FAILED: " + p.error.substr(0, p.error.find('\n'))
                                        : fmt::format("{}, max roll {:.2f} deg", p.summary.regime, p.summary.maxRollDeg);
    return fmt::format("{}/{} speeds: {:.2f} mph {} ({}): {}; ETA {:.0f} s", done, total, p.speedMph, p.direction,
                       p.start, result, etaS);
}

void SweepProgress::operator()(const SweepPoint& p) {
    ++done_;
    failed_ += p.failed ? 1 : 0;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double eta = elapsed / double(done_) * double(total_ - std::min(done_, total_));
    if (!terminal_) {
        fmt::print(stderr, "{}: {}\n", label_, formatLine(done_, total_, p, eta));
        return;
    }
    const int width = 30, filled = int(width * std::min(done_, total_) / std::max<size_t>(total_, 1));
    fmt::print(stderr, "\r{}: [{}{}] {}/{} speeds{}, ETA {:.0f} s ", label_, std::string(filled, '#'),
               std::string(width - filled, '-'), done_, total_, failed_ ? fmt::format(", {} failed", failed_) : "", eta);
    if (done_ == total_) fmt::print(stderr, "\n");
}

}  // namespace rockroll::app
