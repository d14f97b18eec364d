// Sparse bakes under the SH technique (issue 19). By default sparse storage keeps no SH for the
// probes it leaves out, and a lookup must not read that absence as black in any gi.sh_leak
// mode - in particular not under `none`, which ignores validity. The SH sampler reads an absent
// probe as its nearest stored one (probes/sh/ShAbsentFill.h). Measured here: the mean luminance
// of mid-air lookups (where absent corners are) of the sparse set against the dense bake of the
// same grid, per mode, and the same without the fill (absent corners as zeros), which must fail
// the tolerance - or the test could not catch the bug it guards against. With
// FreeSpace::Irradiance the probes left out keep their SH (irradiance-only probes): lookups
// equal the dense set's.
#include "DenseAndSparseBake.h"
#include "probes/sh/ShSampler.h"
#include "raytrace/StaticTriangles.h"
#include "probes/bake/Baker.h"
#include "probes/bake/MidAirSamples.h"
#include "raytrace/RayScene.h"
#include "probes/placement/AutoVolume.h"
#include "probes/store/SparseStorage.h"
#include "scene/SceneLoader.h"

#include <algorithm>
#include <cstdio>
#include <gtest/gtest.h>

using namespace pb::probes;

namespace {

// The sparse lookups that read an absent probe may be this much darker than the dense ones
// (summed luminance, relative): the stand-in is up to a cell from the probe it replaces, and
// next to the Cornell box's ceiling panel the light changes by more than that within a cell
// (MidAirLookupTest). Without the fill they are about half as bright.
constexpr double kDarkerTolerance = 0.08;

double shSparseLookupLuminance(const glm::vec3& c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

using pb::test::bakeDenseAndSparse;
using pb::test::DenseAndSparse;

// The sparse set as the sampler saw it before the fill: every absent probe marked stored
// (so nothing is filled), still invalid and with zero SH.
ProbeSet withoutFill(ProbeSet set) {
    for (auto& vs : set.states)
        for (ProbeState& s : vs)
            s.stored = true;
    return set;
}

// The alternative the fill was chosen over: absence carried as weight 0 even under `none`
// (lighting and weight blended and divided): here the `weight` lookup of a set whose stored
// probes are all valid and whose absent probes are invalid and not filled.
ProbeSet absenceAsWeight(ProbeSet set) {
    for (auto& vs : set.states)
        for (ProbeState& s : vs) {
            s.valid = s.stored;
            s.insideAtLattice = false;
            s.stored = true;
        }
    return set;
}

const glm::vec3 kShSparseLookupAxes[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                          {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};

// Mid-air points x 6 normals (a dynamic object's sides) of the lookups that read an absent
// probe (those where the unfilled sparse set differs from the dense one): the sparse set's
// summed luminance over the dense one's, and the mean relative error per lookup (relative to
// the dense value, or to a tenth of the mean where that is darker: MidAirLookupTest's measure).
struct Darkening {
    double ratio = 0, meanError = 0;
    int lookups = 0;
};

Darkening sparseOverDense(const DenseAndSparse& b, const ProbeSet& sparse, ShLeak leak, int n) {
    const pb::raytrace::RayScene rs(b.scene);
    const ProbeSet unfilled = withoutFill(b.sparse);
    const ShSampler d(b.dense, 0, "dense"), s(sparse, 0, "sparse"), z(unfilled, 0, "unfilled");
    ShSampleOptions o;
    o.coefficients = kShL2Coefficients;
    o.leak = leak;
    std::vector<std::pair<double, double>> pairs;
    double sumD = 0, sumS = 0, all = 0;
    int count = 0;
    for (const glm::vec3& p :
         midAirSamples(rs, b.dense.volumes, n, b.dense.volumes[0].minCellSize()))
        for (const glm::vec3& a : kShSparseLookupAxes) {
            const double ld = shSparseLookupLuminance(d.sample(p, a, a, o).irradiance);
            all += ld;
            ++count;
            if (z.sample(p, a, a, o).irradiance == d.sample(p, a, a, o).irradiance) continue;
            pairs.emplace_back(ld, shSparseLookupLuminance(s.sample(p, a, a, o).irradiance));
            sumD += ld;
            sumS += pairs.back().second;
        }
    Darkening r;
    r.lookups = int(pairs.size());
    r.ratio = sumD > 0 ? sumS / sumD : 0.0;
    const double floor = 0.1 * all / std::max(count, 1);
    for (const auto& [ld, ls] : pairs)
        r.meanError += std::abs(ls - ld) / std::max(ld, floor) / double(pairs.size());
    return r;
}

class ShSparse : public testing::TestWithParam<const char*> {};

// The leak modes that weigh validity: there the probes sparse storage drops whole (inside
// geometry) count for nothing in both sets. (Under `none` such a probe's SH still counts: the
// dense set has it, the sparse set reads a stand-in.)
TEST_P(ShSparse, IrradianceOnlyProbesKeepTheDenseSh) {
    const DenseAndSparse b = bakeDenseAndSparse(GetParam(), 1500, FreeSpace::Irradiance);
    ASSERT_TRUE(b.sparse.hasSh());
    ASSERT_GT(b.sparse.probeCount() - b.sparse.storedCount() - b.sparse.invalidCount(), 0u)
        << "no irradiance-only probe: vacuous";
    const pb::raytrace::RayScene rs(b.scene);
    const ShSampler d(b.dense, 0, "dense"), s(b.sparse, 0, "sparse");
    int lookups = 0;
    for (ShLeak leak : {ShLeak::Weight, ShLeak::ValidityMask}) {
        ShSampleOptions o;
        o.coefficients = kShL2Coefficients;
        o.leak = leak;
        for (const glm::vec3& p :
             midAirSamples(rs, b.dense.volumes, 200, b.dense.volumes[0].minCellSize()))
            for (const glm::vec3& a : kShSparseLookupAxes) {
                EXPECT_EQ(s.sample(p, a, a, o).irradiance, d.sample(p, a, a, o).irradiance)
                    << "leak mode #" << int(leak);
                ++lookups;
            }
    }
    EXPECT_GT(lookups, 100);
}

TEST_P(ShSparse, AbsentProbesDoNotDarkenMidAirLookupsInAnyLeakMode) {
    const DenseAndSparse b = bakeDenseAndSparse(GetParam(), 1500, FreeSpace::StandIns);
    ASSERT_TRUE(b.sparse.hasSh());
    ASSERT_LT(b.sparse.storedCount(), b.sparse.probeCount()) << "nothing absent: vacuous";
    const Darkening zeros = sparseOverDense(b, withoutFill(b.sparse), ShLeak::None, 300);
    std::printf("[ sh sparse ] %s: %zu of %zu probes stored; %d mid-air lookups read an absent "
                "probe; sparse / dense luminance (mean relative error): none without the fill "
                "%.4f (%.4f)",
                GetParam(), b.sparse.storedCount(), b.sparse.probeCount(), zeros.lookups,
                zeros.ratio, zeros.meanError);
    ASSERT_GT(zeros.lookups, 100) << "too few lookups read an absent probe: vacuous";
    EXPECT_LT(zeros.ratio, 1.0 - kDarkerTolerance) << "absent probes never darkened: vacuous";
    for (ShLeak leak : {ShLeak::None, ShLeak::Weight, ShLeak::ValidityMask}) {
        const Darkening r = sparseOverDense(b, b.sparse, leak, 300);
        std::printf(", %s %.4f (%.4f)",
                    leak == ShLeak::None     ? "none"
                    : leak == ShLeak::Weight ? "weight"
                                             : "mask",
                    r.ratio, r.meanError);
        EXPECT_GE(r.ratio, 1.0 - kDarkerTolerance) << "leak mode #" << int(leak);
    }
    const Darkening w = sparseOverDense(b, absenceAsWeight(b.sparse), ShLeak::Weight, 300);
    std::printf("; none with absence as weight 0: %.4f (%.4f)\n", w.ratio, w.meanError);
}

INSTANTIATE_TEST_SUITE_P(Builtin, ShSparse, testing::Values("cornell", "rooms"));

} // namespace
