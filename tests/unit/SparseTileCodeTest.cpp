// The tile code in the probe state's w (probes/store/SparseLayout.h TileCode, decoded by ddgiTile in
// shaders/common_ddgi_tile.glsl): column, row and layer as bit fields, exact in the RGBA32F
// state texture up to 24 bits (23 for the fields, the top bit flags an irradiance-only probe),
// a clear error beyond, and the one encoding GpuProbes uploads and the cost model's tile layout
// agree on.
#include "core/Error.h"
#include "probes/ProbeVolume.h"
#include "probes/store/SparseLayout.h"

#include <gtest/gtest.h>

using namespace pb::probes;

namespace {

// Encodes then decodes as the shader does, and checks that w is the integer code + 1 with the
// validity as its sign.
void expectRoundTrip(const TileCode& c, const glm::ivec3& tile) {
    for (bool valid : {true, false})
        for (bool ownVisibility : {true, false}) {
            const float w = c.encode(tile, valid, ownVisibility);
            EXPECT_EQ(w > 0.0f, valid);
            EXPECT_GE(std::abs(w), 1.0f) << "w = 0 is an absent probe";
            EXPECT_LE(std::abs(w), 16777216.0f) << "beyond the floats' exact integers";
            EXPECT_EQ(std::abs(w), std::floor(std::abs(w))) << "not an integer";
            EXPECT_EQ(c.decode(w), tile) << tile.x << "," << tile.y << "," << tile.z;
            EXPECT_EQ(TileCode::ownsVisibility(w), ownVisibility);
        }
}

} // namespace

TEST(SparseTileCode, FieldsAreAsWideAsTheGridNeeds) {
    const TileCode one = tileCode({1, 1, 1}, "v"); // columns, layers, rows as packedCounts
    EXPECT_EQ(one.columnBits + one.rowBits + one.layerBits, 0);
    EXPECT_EQ(one.encode({0, 0, 0}, true), 1.0f);
    const TileCode c = tileCode({5, 9, 2}, "v"); // 5 columns, 2 rows, 9 layers
    EXPECT_EQ(c.columnBits, 3);
    EXPECT_EQ(c.rowBits, 1);
    EXPECT_EQ(c.layerBits, 4);
    EXPECT_EQ(tileCode({4, 1, 1}, "v").columnBits, 2); // 0..3 in 2 bits, no more
    for (int x = 0; x < 5; ++x)
        for (int y = 0; y < 2; ++y)
            for (int z = 0; z < 9; ++z)
                expectRoundTrip(c, {x, y, z});
}

TEST(SparseTileCode, ExactAtTheTwentyThreeBitLimit) {
    // 256 x 128 x 256 tiles: 23 bits; the last flagged tile's w is 2^24, the largest float
    // integer below which every integer is exact, and its neighbour 2^24 - 1 stays distinct.
    const TileCode c = tileCode({256, 128, 256}, "v");
    EXPECT_EQ(c.columnBits + c.rowBits + c.layerBits, kTileCodeBits - 1);
    EXPECT_EQ(c.encode({255, 255, 127}, true, false), 16777216.0f);
    EXPECT_EQ(c.encode({254, 255, 127}, false, false), -16777215.0f);
    EXPECT_EQ(c.encode({255, 255, 127}, true), 8388608.0f);
    for (glm::ivec3 t : {glm::ivec3(255, 255, 127), glm::ivec3(254, 255, 127),
                         glm::ivec3(0, 0, 127), glm::ivec3(255, 0, 0), glm::ivec3(0, 255, 0),
                         glm::ivec3(0, 0, 0), glm::ivec3(128, 127, 64)})
        expectRoundTrip(c, t);
    // Lopsided grids at the limit: every field still decodes at its extremes.
    for (glm::ivec3 grid :
         {glm::ivec3(1 << 12, 1, 1 << 11), glm::ivec3(2, 1 << 21, 2), glm::ivec3(1024, 512, 16)}) {
        const TileCode l = tileCode(grid, "v");
        EXPECT_EQ(l.columnBits + l.rowBits + l.layerBits, kTileCodeBits - 1);
        const glm::ivec3 last(grid.x - 1, grid.z - 1, grid.y - 1); // column, row, layer
        expectRoundTrip(l, last);
        expectRoundTrip(l, {last.x, 0, last.z});
        expectRoundTrip(l, {0, last.y, 0});
    }
}

TEST(SparseTileCode, BeyondTwentyThreeBitsIsAClearError) {
    for (glm::ivec3 grid :
         {glm::ivec3(257, 128, 256), glm::ivec3(256, 129, 256), glm::ivec3(256, 128, 257),
          glm::ivec3(256, 256, 256), glm::ivec3(1 << 23, 2, 1), glm::ivec3(1024, 1024, 1024)}) {
        try {
            tileCode(grid, "probe volume 'big'");
            ADD_FAILURE() << "no error for " << grid.x << "x" << grid.y << "x" << grid.z;
        } catch (const pb::Error& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find("probe volume 'big'"), std::string::npos) << m;
            EXPECT_NE(m.find("23"), std::string::npos) << m;
            EXPECT_NE(m.find("RGBA32F"), std::string::npos) << m;
        }
    }
}

TEST(SparseTileCode, EveryVolumeWithinTheGridLimitsFits) {
    // volumeProblem's limits (kMaxProbesPerAxis per axis, kMaxProbesPerVolume in all): the
    // worst shapes sit just above powers of two, where each field needs one bit more.
    int widest = 0;
    for (int a = 0; (1 << a) + 1 <= kMaxProbesPerAxis; ++a)
        for (int b = 0; (1 << b) + 1 <= kMaxProbesPerAxis; ++b)
            for (int c = 0; (1 << c) + 1 <= kMaxProbesPerAxis; ++c) {
                const glm::ivec3 n((1 << a) + 1, (1 << b) + 1, (1 << c) + 1);
                if ((long long)n.x * n.y * n.z > kMaxProbesPerVolume) continue;
                ProbeVolume v;
                v.name = "v";
                v.counts = n;
                ASSERT_EQ(volumeProblem(v), "");
                const TileCode code = tileCode(n, "v");
                widest = std::max(widest, code.columnBits + code.rowBits + code.layerBits);
            }
    EXPECT_LE(widest, kTileCodeBits - 1); // the flag keeps the top bit
    EXPECT_GE(widest, 18); // the loop did reach large grids
}

TEST(SparseTileCode, StateWDecodesToTheTileTheCostModelReplays) {
    ProbeVolume v;
    v.name = "v";
    v.counts = {7, 4, 5};
    std::vector<ProbeState> states(std::size_t(v.probeCount()));
    for (std::size_t i = 0; i < states.size(); ++i) {
        states[i].valid = i % 5 != 0;
        states[i].stored = i % 3 != 0; // absent probes: every third
    }
    for (bool sparse : {false, true}) {
        std::vector<ProbeState> s = states;
        if (!sparse)
            for (ProbeState& p : s)
                p.stored = true;
        const TileLayout t = tileLayout(v, s);
        ASSERT_EQ(t.sparse, sparse);
        int absent = 0;
        for (int i = 0; i < v.probeCount(); ++i) {
            const glm::ivec3 q = v.probeCoords(i);
            const float w = t.stateW(std::size_t(i), s[size_t(i)].valid);
            if (!s[size_t(i)].stored) {
                EXPECT_EQ(w, 0.0f);
                EXPECT_EQ(t.tileOf(q), glm::ivec3(-1));
                ++absent;
                continue;
            }
            EXPECT_EQ(w > 0.0f, s[size_t(i)].valid);
            EXPECT_EQ(t.code.decode(w), t.tileOf(q)) << "probe " << i;
            if (!sparse) {
                EXPECT_EQ(t.tileOf(q), glm::ivec3(q.x, q.z, q.y));
            }
        }
        EXPECT_EQ(absent > 0, sparse);
    }
}
