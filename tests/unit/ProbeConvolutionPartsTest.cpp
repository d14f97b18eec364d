// ProbeConvolution's parts: the radiance passes build it without visibility weights
// (Parts::IrradianceOnly), which must give the same irradiance as the full build and refuse a
// visibility convolution instead of returning nothing; the rays' SH basis values it keeps for
// RadianceSlab::projectSh are shBasis of each ray's direction.
#include "probes/ProbeLayout.h"
#include "probes/sh/ShIrradiance.h"
#include "probes/bake/ProbeConvolution.h"
#include "probes/bake/RayDirections.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

using namespace pb::probes;

TEST(ProbeConvolutionParts, IrradianceOnlyConvolvesTheSameAndRefusesVisibility) {
    const std::vector<glm::vec3> dirs = passDirections(64, 3);
    const ProbeConvolution full(dirs);
    const ProbeConvolution irradianceOnly(dirs, ProbeConvolution::Parts::IrradianceOnly);
    // Some radiance that varies with the direction (RGB + unused per ray).
    std::vector<float> rgbx;
    for (const glm::vec3& d : dirs)
        rgbx.insert(rgbx.end(), {1.0f + d.x, 2.0f + d.y * d.y, 0.5f + d.z, 0.0f});
    std::vector<float> a(kIrradianceInteriorTexels * 3), b(a.size());
    full.irradiance(rgbx.data(), a.data());
    irradianceOnly.irradiance(rgbx.data(), b.data());
    EXPECT_EQ(a, b);

    const std::vector<float> dist(dirs.size(), 0.5f);
    std::vector<float> vis(std::size_t(kVisibilityInterior * kVisibilityInterior) * 2, -1.0f);
    full.visibility(dist.data(), vis.data());
    EXPECT_FLOAT_EQ(vis[0], 0.5f); // the mean distance of a uniform distance
    EXPECT_THROW(irradianceOnly.visibility(dist.data(), vis.data()), std::logic_error);
}

TEST(ProbeConvolutionParts, KeepsEachRaysShBasis) {
    const std::vector<glm::vec3> dirs = passDirections(32, 5);
    const ProbeConvolution conv(dirs, ProbeConvolution::Parts::IrradianceOnly);
    for (int r = 0; r < int(dirs.size()); ++r) {
        float y[kShL2Coefficients];
        shBasis(dirs[std::size_t(r)], y);
        for (int k = 0; k < kShL2Coefficients; ++k)
            EXPECT_EQ(conv.shBasisOfRay(r)[k], y[k]) << "ray " << r << ", coefficient " << k;
    }
}
