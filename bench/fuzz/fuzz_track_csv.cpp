// libFuzzer harness: a measured track's CSV (mbmodel/TrackInput.h readTrackCsv), and the
// track built from the rows it accepts, sampled along its length.
#include "bench/fuzz/FuzzFiles.h"
#include "mbmodel/TrackInput.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace rockroll;
    std::vector<MeasuredTrackSample> rows;
    try {
        rows = readTrackCsv(fuzz::asText(data, size), "<fuzz>", 6.096);
    } catch (const std::invalid_argument&) {
        return 0;
    }
    TrackSpec spec;
    spec.measured = rows;
    try {
        const TrackInput track(spec);
        const double end = rows.back().distance + 2 * spec.taper;
        for (int i = 0; i <= 64; ++i) {
            const RailPoint p = track.calcRails(end * i / 64);
            if (!std::isfinite(p.z[0]) || !std::isfinite(p.z[1])) std::abort();  // accepted rows, non-finite rails
        }
    } catch (const std::invalid_argument&) {
    }
    return 0;
}
