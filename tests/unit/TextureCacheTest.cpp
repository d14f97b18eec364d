// The set-associative LRU cache of the cost model against hand-computed hit/miss sequences:
// conflict misses with little associativity, LRU victim choice, capacity misses, line size;
// the presets and their validation.
#include "costmodel/TextureCache.h"
#include "core/Error.h"
#include "costmodel/CachePresets.h"

#include <gtest/gtest.h>

using namespace pb::costmodel;

namespace {

// "H" / "M" per access.
std::string textureCacheRun(LruCache& c, const std::vector<std::uint64_t>& addresses) {
    std::string out;
    for (std::uint64_t a : addresses)
        out += c.access(a) ? 'H' : 'M';
    return out;
}

CacheConfig cfg(std::uint64_t size, int line, int ways) {
    return {"test", size, line, ways, "test"};
}

} // namespace

TEST(LruCache, DirectMappedLinesOnTheSameSetEvictEachOther) {
    // 256 B, 64 B lines, 1 way: 4 sets; 0 and 256 share set 0, 64 has set 1.
    LruCache c(cfg(256, 64, 1));
    EXPECT_EQ(textureCacheRun(c, {0, 256, 0, 256, 64, 64, 0}), "MMMMMHM");
}

TEST(LruCache, TwoWaysHoldTwoConflictingLinesAndEvictTheLeastRecentlyUsed) {
    // 512 B, 64 B lines, 2 ways: 4 sets; 0, 256, 512 all map to set 0.
    LruCache c(cfg(512, 64, 2));
    EXPECT_EQ(textureCacheRun(c, {0, 256, 0, 256}), "MMHH");
    // 256 is the most recent: 512 evicts 0.
    EXPECT_EQ(textureCacheRun(c, {512, 256, 0}), "MHM");
    // Set 0 holds 0 (most recent) and 256: 256 hits, 512 evicts 0, 0 evicts 256.
    EXPECT_EQ(textureCacheRun(c, {256, 512, 0}), "HMM");
}

TEST(LruCache, CapacityMissesWhenTheCycleExceedsTheCache) {
    // Fully associative, 4 lines of 64 B.
    LruCache fits(cfg(256, 64, 4));
    EXPECT_EQ(textureCacheRun(fits, {0, 64, 128, 192, 0, 64, 128, 192}), "MMMMHHHH");
    // A cycle of 5 lines through 4: LRU always evicts the next one needed.
    LruCache thrash(cfg(256, 64, 4));
    EXPECT_EQ(textureCacheRun(thrash, {0, 64, 128, 192, 256, 0, 64, 128, 192, 256}), "MMMMMMMMMM");
}

TEST(LruCache, LineSizeDecidesWhichNeighboursComeForFree) {
    std::vector<std::uint64_t> walk;
    for (std::uint64_t a = 0; a < 128; a += 16)
        walk.push_back(a);
    LruCache wide(cfg(1024, 64, 4));
    EXPECT_EQ(textureCacheRun(wide, walk), "MHHHMHHH");
    LruCache narrow(cfg(1024, 32, 4));
    EXPECT_EQ(textureCacheRun(narrow, walk), "MHMHMHMH");
    LruCache clearMe(cfg(1024, 32, 4));
    textureCacheRun(clearMe, walk);
    clearMe.clear();
    EXPECT_EQ(textureCacheRun(clearMe, {0}), "M");
}

// A set count that is not a power of two indexes by remainder: with 3 direct-mapped sets, lines
// 0 and 3 share set 0, lines 0 and 1 do not.
TEST(LruCache, NonPowerOfTwoSetsIndexByRemainder) {
    LruCache three(cfg(192, 64, 1));
    EXPECT_EQ(textureCacheRun(three, {0, 192, 0}), "MMM");
    three.clear();
    EXPECT_EQ(textureCacheRun(three, {0, 64, 128, 0, 64, 128}), "MMMHHH");
}

TEST(LruCache, ConfigurationsAreValidated) {
    EXPECT_EQ(cfg(16384, 64, 4).sets(), 64);
    EXPECT_NO_THROW(cfg(16384, 64, 4).validate());
    EXPECT_THROW(cfg(16384, 48, 4).validate(), pb::Error); // line not a power of two
    EXPECT_THROW(cfg(12000, 64, 4).validate(), pb::Error); // not a whole number of sets
    EXPECT_THROW(cfg(128, 64, 4).validate(), pb::Error);   // smaller than one set
    EXPECT_THROW(cfg(16384, 64, 0).validate(), pb::Error); // no ways
    EXPECT_THROW(cfg(16384, 64, 3).validate(), pb::Error); // not a whole number of sets
    EXPECT_NO_THROW(cfg(24576, 128, 4).validate());        // Maxwell's 24 KiB: 48 sets
    EXPECT_EQ(cfg(24576, 128, 4).sets(), 48);
    EXPECT_EQ(cfg(16384, 64, 4).describe(), "16 KiB, 64 B lines, 4-way");
}

TEST(CachePresets, EveryProfileHasAValidPresetAndUnknownNamesAreErrors) {
    for (const char* name : {"handheld", "console-base", "pc-low", "pc-high"}) {
        const CacheConfig c = cachePresetFor(name);
        EXPECT_EQ(c.name, name);
        EXPECT_NO_THROW(c.validate()) << name;
        EXPECT_FALSE(c.source.empty()) << name;
    }
    EXPECT_LT(cachePresetFor("handheld").sizeBytes, cachePresetFor("pc-high").sizeBytes);
    try {
        cachePresetFor("switch");
        FAIL() << "no error";
    } catch (const pb::Error& e) {
        EXPECT_NE(std::string(e.what()).find("handheld"), std::string::npos) << e.what();
    }
}
