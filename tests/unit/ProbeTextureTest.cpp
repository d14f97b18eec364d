// ProbeTexture::make: every texel 0, also when the texture is zeroed on several threads in a
// block the huge-page allocator kept from an earlier texture (its bytes are the old texels).
#include "core/HugePages.h"
#include "probes/ProbeLayout.h"

#include <algorithm>
#include <gtest/gtest.h>

using namespace pb::probes;

TEST(ProbeTexture, AParallelMakeZeroesABlockAnEarlierTextureLeftFull) {
    // 64 x 8 x 64 probes: 32 MiB of irradiance texels, several of make()'s parallel chunks.
    const TextureShape shape = irradianceShape({64, 8, 64});
    const float* reused = nullptr;
    pb::releaseKeptHugeBlocks(); // so that the block kept below is the one the cache holds
    {
        ProbeTexture full = ProbeTexture::make(shape);
        std::fill(full.texels.begin(), full.texels.end(), 7.0f);
        reused = full.texels.data();
    } // its block is kept (core/HugePages.h) ...
    const ProbeTexture t = ProbeTexture::make(shape, 2);
    ASSERT_EQ(t.texels.data(), reused) << "... and serves the next texture of its size";
    ASSERT_EQ(t.texels.size(), shape.floatCount());
    EXPECT_EQ(std::count(t.texels.begin(), t.texels.end(), 0.0f), std::ptrdiff_t(t.texels.size()));
}

TEST(ProbeTexture, ASmallTextureIsZeroedOnAnyThreadCount) {
    const TextureShape shape = visibilityShape({2, 2, 2});
    for (int threads : {1, 2, 0}) {
        const ProbeTexture t = ProbeTexture::make(shape, threads);
        EXPECT_EQ(t.texels.size(), shape.floatCount());
        EXPECT_EQ(std::count(t.texels.begin(), t.texels.end(), 0.0f),
                  std::ptrdiff_t(t.texels.size()));
    }
}
