// The measured lattice search (renderer/probes/placement/LatticeShiftSearch.h) against synthetic error
// functions: it finds a bowl's minimum axis by axis, ignores gains under the margin, skips
// shifts that do not fit, and moves nested volumes together.
#include "probes/placement/LatticeShiftSearch.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>
#include <gtest/gtest.h>

using namespace pb::probes;

namespace {

const glm::vec3 kCell{2.0f, 1.0f, 0.5f};

std::vector<ProbeVolume> nested() {
    ProbeVolume outer;
    outer.name = "outer";
    outer.center = glm::vec3(1.0f, 2.0f, 3.0f);
    outer.halfExtents = glm::vec3(8.0f, 4.0f, 2.0f);
    outer.counts = glm::ivec3(9, 9, 9);
    ProbeVolume child = outer;
    child.name = "child";
    child.parent = "outer";
    child.center += glm::vec3(1.0f, 0.5f, 0.25f);
    child.halfExtents *= 0.25f;
    return {outer, child};
}

// The shift of `v` from nested(), in cells.
glm::vec3 shiftOf(const std::vector<ProbeVolume>& v) {
    return (v[0].center - nested()[0].center) / kCell;
}

bool fitsAll(const std::vector<ProbeVolume>&) {
    return true;
}

} // namespace

TEST(LatticeShiftSearch, FindsABowlsMinimumAndMovesEveryVolume) {
    // The bowl's lowest tenth of a cell along x (-0.3) lies between two coarse steps: the coarse
    // stage lands on -0.4 (nearer), the fine stage tries -0.3 (-0.5 would reach past the range).
    const glm::vec3 best{-0.32f, 0.2f, 0.0f};
    auto bowl = [&](const std::vector<ProbeVolume>& v, int) {
        const glm::vec3 d = shiftOf(v) - best;
        return 1.0 + 4.0 * double(glm::dot(d, d));
    };
    std::vector<ProbeVolume> v = nested();
    const LatticeShift s = searchLatticeShift(v, kCell, bowl, fitsAll);
    EXPECT_NEAR(s.cells.x, -0.3f, 1e-5f);
    EXPECT_NEAR(s.cells.y, best.y, 1e-5f);
    EXPECT_NEAR(s.cells.z, 0.0f, 1e-5f);
    // x: 4 coarse + 1 fine (-0.4 clears the margin, so only its neighbour); y: 4 + 2 (around
    // 0.2, which clears it); z: 4 + 2 (no coarse step beats the current shift: its neighbours).
    EXPECT_EQ(s.trials, 5 + 6 + 6);
    EXPECT_NEAR(s.errorBefore, 1.0 + 4.0 * (0.32 * 0.32 + 0.04), 1e-5);
    EXPECT_NEAR(s.errorAfter, 1.0 + 4.0 * 0.02 * 0.02, 1e-5);
    // Both volumes moved by the same world offset: the nesting is unchanged.
    const glm::vec3 moved = s.cells * kCell;
    EXPECT_NEAR(glm::length(v[0].center - (nested()[0].center + moved)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(v[1].center - (nested()[1].center + moved)), 0.0f, 1e-5f);
    EXPECT_EQ(v[1].halfExtents, nested()[1].halfExtents);
}

TEST(LatticeShiftSearch, TheFineStepsAroundTheCurrentShiftFindANarrowDip) {
    // A dip at x +0.1 too narrow for any coarse step to see, on a slope that makes every coarse
    // step worse than the unshifted lattice: the fine stage tries the tenths either side of it
    // and finds the dip.
    auto dip = [](const std::vector<ProbeVolume>& v, int) {
        const double x = double(shiftOf(v).x), d = (x - 0.1) / 0.03;
        return 1.0 + 0.1 * std::abs(x) - 0.6 * std::exp(-d * d);
    };
    std::vector<ProbeVolume> v = nested();
    const LatticeShift s = searchLatticeShift(v, kCell, dip, fitsAll);
    EXPECT_NEAR(s.cells.x, 0.1f, 1e-5f);
    EXPECT_NEAR(s.errorAfter, 0.41, 1e-5);
    EXPECT_EQ(s.trials, 3 * (4 + 2)); // every axis: 4 coarse, the 2 tenths around the current
}

TEST(LatticeShiftSearch, AGainUnderTheMarginAlsoRefinesAroundTheCurrentShift) {
    // Two minima along x: a shallow one at +0.2 (0.5% better, under the margin: maybe the
    // estimate's noise) that the coarse stage sees, and a deeper one at -0.1 between the coarse
    // steps. The fine stage tries the neighbours of both, and keeps -0.1.
    auto twoDips = [](const std::vector<ProbeVolume>& v, int) {
        const double x = double(shiftOf(v).x);
        auto near = [&](double at) { return std::abs(x - at) < 1e-3; };
        return near(0.2) ? 0.995 : near(-0.1) ? 0.9 : 1.0;
    };
    std::vector<ProbeVolume> v = nested();
    const LatticeShift s = searchLatticeShift(v, kCell, twoDips, fitsAll);
    EXPECT_NEAR(s.cells.x, -0.1f, 1e-5f);
    EXPECT_NEAR(s.errorAfter, 0.9, 1e-9);
    // x: 4 coarse + 3 fine (0.1 and 0.3 beside +0.2, -0.1 and 0.1 beside the current: 3 distinct);
    // y and z: flat, 4 + 2 each.
    EXPECT_EQ(s.trials, 7 + 6 + 6);
}

TEST(LatticeShiftSearch, GainsUnderTheMarginAreNotTaken) {
    // Half the margin better, 0.4 of a cell along x: within the estimate's noise, so the
    // lattice stays.
    auto betterAtXBy = [&](double gain) {
        return [gain](const std::vector<ProbeVolume>& v, int) {
            return std::abs(shiftOf(v).x - 0.4f) < 1e-3f ? 1.0 - gain : 1.0;
        };
    };
    std::vector<ProbeVolume> v = nested();
    const LatticeShift s = searchLatticeShift(v, kCell, betterAtXBy(0.5 * kLatticeShiftMargin),
                                              fitsAll);
    EXPECT_EQ(s.cells, glm::vec3(0.0f));
    EXPECT_EQ(v[0].center, nested()[0].center);
    EXPECT_EQ(s.errorAfter, s.errorBefore);
    // 1.5 times the margin better is taken.
    EXPECT_NEAR(searchLatticeShift(v, kCell, betterAtXBy(1.5 * kLatticeShiftMargin), fitsAll)
                    .cells.x,
                0.4f, 1e-5f);
}

TEST(LatticeShiftSearch, ShiftsThatDoNotFitAreNeverTried) {
    // The best error lies at negative x, but only shifts with x >= 0 fit the budget.
    auto slope = [&](const std::vector<ProbeVolume>& v, int) { return 2.0 + double(shiftOf(v).x); };
    int tried = 0;
    auto fitsRight = [&](const std::vector<ProbeVolume>& v) {
        ++tried;
        return shiftOf(v).x >= -1e-4f;
    };
    std::vector<ProbeVolume> v = nested();
    const LatticeShift s = searchLatticeShift(v, kCell, slope, fitsRight);
    EXPECT_GE(s.cells.x, -1e-4f);
    EXPECT_EQ(s.cells, glm::vec3(0.0f)); // every fitting x shift is worse
    // Along x: the 4 coarse steps and, as none beat the unshifted lattice, the fine steps
    // either side of it; y and z the same. The 3 negative x shifts were not baked.
    EXPECT_EQ(tried, 3 * (4 + 2));
    EXPECT_EQ(s.trials, tried - 3);
}

TEST(LatticeShiftSearch, TrialsScoredSideBySideChooseAsOneByOne) {
    // An axis's trials may run on threads of their own: the result, errors and trial count must
    // be those of scoring them one by one, ties included (the first of equal errors wins).
    auto ridge = [](const std::vector<ProbeVolume>& v, int = 1) {
        const glm::vec3 s = shiftOf(v);
        // Equal minima at x -0.2 and +0.2, a step in y, a flat z.
        return 1.0 + std::abs(std::abs(double(s.x)) - 0.2) + (s.y > 0.05f ? -0.3 : 0.0);
    };
    std::vector<ProbeVolume> one = nested();
    const LatticeShift a = searchLatticeShift(one, kCell, ridge, fitsAll, 1);
    std::atomic<int> running{0}, most{0};
    auto watched = [&](const std::vector<ProbeVolume>& v, int) {
        const int now = ++running;
        int seen = most.load();
        while (now > seen && !most.compare_exchange_weak(seen, now)) {
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
        --running;
        return ridge(v);
    };
    std::vector<ProbeVolume> four = nested();
    const LatticeShift b = searchLatticeShift(four, kCell, watched, fitsAll, 4);
    EXPECT_EQ(a.cells, b.cells);
    EXPECT_NEAR(a.cells.x, -0.2f, 1e-5f); // the first of the two equal minima
    EXPECT_GT(a.cells.y, 0.05f);
    EXPECT_EQ(a.errorBefore, b.errorBefore);
    EXPECT_EQ(a.errorAfter, b.errorAfter);
    EXPECT_EQ(a.trials, b.trials);
    EXPECT_EQ(one[0].center, four[0].center);
    EXPECT_GT(most.load(), 1); // they did run side by side
}

TEST(LatticeShiftSearch, TheLastTrialsOfAStageShareTheCores) {
    // On 4 cores the first axis's coarse stage has 5 bakes (the unshifted one and 4 steps): 4 run
    // side by side on one thread each, the fifth alone on all 4. The fine stage's 2 bakes (either
    // side of the unshifted lattice, which stays) run on 2 threads each.
    std::mutex lock;
    std::vector<int> threads;
    auto flat = [&](const std::vector<ProbeVolume>&, int t) {
        const std::lock_guard<std::mutex> guard(lock);
        threads.push_back(t);
        return 1.0;
    };
    std::vector<ProbeVolume> v = nested();
    const LatticeShift s = searchLatticeShift(v, kCell, flat, fitsAll, 4);
    EXPECT_EQ(s.cells, glm::vec3(0.0f));
    ASSERT_EQ(threads.size(), std::size_t(1 + 3 * (4 + 2))); // flat: the current's 2 tenths
    EXPECT_EQ(std::count(threads.begin(), threads.begin() + 4, 1), 4);
    EXPECT_EQ(threads[4], 4);
    EXPECT_EQ(threads[5], 2);
    EXPECT_EQ(threads[6], 2);
    // The other axes: 4 coarse bakes, one per core; 2 fine ones, 2 threads each.
    EXPECT_EQ(std::count(threads.begin() + 7, threads.end(), 1), 8);
    EXPECT_EQ(std::count(threads.begin() + 7, threads.end(), 2), 4);
}
