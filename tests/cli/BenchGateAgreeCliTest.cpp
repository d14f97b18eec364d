// The bench and the gate time the same thing the same way (issue 41): a profile's frame over the
// reference's, steady frames after an untimed switch frame, interleaved rounds, the same timing
// method. Run both on one small case (cornell, 64x36, handheld against the reference) and their
// ratios agree within their intervals. Timings are never asserted, only their agreement: each
// side's interval is its own (the bench's paired delta at its confidence level, the gate's
// per-round ratios at 99%), and an interval widens on a noisy machine rather than moves.
// Both run llvmpipe on one thread (LP_NUM_THREADS=0): with its worker threads the ratio moves
// with the cores that other tests leave free (the half-resolution profile has a larger serial
// share than the reference), and the two runs are minutes apart under different loads (a
// fresh clone's run saw gate 1.72-1.82 against bench 1.40-1.48). On one thread a shared core
// slows both profiles of a round alike.
#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

namespace pb::test {
namespace {

namespace fs = std::filesystem;

nlohmann::json agreeReadJson(const fs::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in, nullptr, false);
}

// A distribution-free interval for the median of `x` (order statistics, binomial coverage at
// least `level`).
std::pair<double, double> agreeMedianInterval(std::vector<double> x, double level) {
    std::sort(x.begin(), x.end());
    const int n = int(x.size());
    for (int k = n / 2; k >= 0; --k) { // widen symmetric ranks until the coverage is reached
        // P(x_(k+1) <= median <= x_(n-k)) = 1 - 2 P(Binomial(n, 1/2) <= k)
        double tail = 0, c = 1;
        for (int i = 0; i <= k; ++i) {
            if (i > 0) c = c * double(n - i + 1) / i;
            tail += c * std::pow(0.5, n);
        }
        if (1 - 2 * tail >= level || k == 0) return {x[size_t(k)], x[size_t(n - 1 - k)]};
    }
    return {x.front(), x.back()};
}

const char* kAgreeCamera = "0,1,0.9,0,1.2,-1,80";

TEST(BenchGateAgree, HandheldOverReferenceAgreesWithinTheirIntervals) {
    ::setenv("LP_NUM_THREADS", "0", 1); // inherited by both commands (see the file's comment)
    const fs::path dir = outputDir();
    const fs::path cache = dir / "cache";
    // The gate's per-round ratios: a tiny baseline's recording run (30 rounds).
    const fs::path baseline = dir / "tiny.json";
    const CommandResult g = runProbebench(
        {"gate", "--baseline", baseline.string(), "--update", "--no-shaders", "--scene", "cornell",
         "--volumes", "auto", "--camera", kAgreeCamera, "--width", "64", "--height", "36",
         "--profiles", "reference,handheld", "--cache-dir", cache.string()});
    ASSERT_EQ(g.exitCode, 0) << g.output;
    const nlohmann::json base = agreeReadJson(baseline);
    std::vector<double> ratios;
    for (const nlohmann::json& p : base["profiles"])
        if (p["name"] == "handheld") ratios = p["ratio_samples"].get<std::vector<double>>();
    ASSERT_GE(ratios.size(), 9u) << base.dump().substr(0, 300);
    const auto [gateLow, gateHigh] = agreeMedianInterval(ratios, 0.99);

    // The bench's: the same frame, the gate's timing method, its frames per round.
    const fs::path json = dir / "bench.json";
    const CommandResult b = runProbebench({"bench",
                                           "--scene",
                                           "cornell",
                                           "--volumes",
                                           "auto",
                                           "--camera",
                                           kAgreeCamera,
                                           "--width",
                                           "64",
                                           "--height",
                                           "36",
                                           "--profiles",
                                           "handheld",
                                           "--rounds",
                                           "15",
                                           "--frames",
                                           "3",
                                           "--timing",
                                           base["suite"]["timing"]["method"].get<std::string>(),
                                           "--no-floor",
                                           "--no-cache-model",
                                           "--cache-dir",
                                           cache.string(),
                                           "--json",
                                           json.string()});
    ASSERT_EQ(b.exitCode, 0) << b.output;
    const nlohmann::json r = agreeReadJson(json);
    const nlohmann::json& p = r["profiles"][0];
    const double ref = p["reference_frame_ms"]["median"];
    const nlohmann::json& d = p["vs_reference"]["delta_ms"];
    const double benchLow = (ref + d["ci_low"].get<double>()) / ref;
    const double benchHigh = (ref + d["ci_high"].get<double>()) / ref;
    const double benchRatio = (ref + d["estimate"].get<double>()) / ref;
    // Agreement within twice the gate's ratio threshold (2 x 10%) of the gate's interval. Each
    // interval is of one process; from process to process the ratio itself moves more than
    // that (JIT code and memory placement): nine quiet runs of this test on one thread gave
    // gate medians of 1.63-1.86 and a bench at most 0.14 above the gate's interval. What
    // this catches is the disagreement issue 41 found (bench 1.46x the reference, gate 0.88x).
    const double slack = 2 * base["suite"]["timing"]["ratio_threshold"].get<double>() *
                         0.5 * (gateLow + gateHigh);
    std::printf("[ agree ] gate ratio median interval [%.4f, %.4f] (%zu rounds); bench %.4f "
                "[%.4f, %.4f]; slack %.4f\n",
                gateLow, gateHigh, ratios.size(), benchRatio, benchLow, benchHigh, slack);
    EXPECT_LE(benchLow, gateHigh + slack) << "the bench's handheld is faster than the gate's";
    EXPECT_GE(benchHigh, gateLow - slack) << "the bench's handheld is slower than the gate's";
}

} // namespace
} // namespace pb::test
