#pragma once
// The frame-time model of one pass on one device (issue 40): the pass's demand on each unit -
// ALU cycles, texture samples by filter and width, bytes from memory, pixels written - divided
// by the device's rate for that unit; the pass takes the largest of them (the units overlap, the
// slowest bounds) plus a fixed cost per draw. The bound unit is named. Every demand is a figure
// the testbed counts exactly (FrameDemand.h); every rate a figure of the device file
// (DeviceSpec.h). Deterministic: the same inputs give the same bits on any machine (no libm, a
// fixed order of operations). GL-free.
#include "DeviceSpec.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace pb::devicemodel {

// What one pass asks of the GPU in one frame.
struct PassDemand {
    std::string pass;            // the frame section ("gi-apply", "upsample", ...)
    std::uint64_t fragments = 0; // fragments that run the pass's program
    double aluCyclesPerFragment = 0; // core cycles per fragment (ShaderCost.h)
    // Texture samples by what a texture unit pays for them: point or bilinear 32-bit texels (1),
    // bilinear 64-bit texels (1 / wide_texel_rate), trilinear 3D (1 / trilinear_3d_rate; with
    // 64-bit texels both).
    std::uint64_t samples = 0, wideSamples = 0, trilinear3dSamples = 0, wideTrilinear3dSamples = 0;
    std::uint64_t bytesRead = 0;      // from memory: the last-level cache's misses
    std::uint64_t bytesWritten = 0;   // render targets, cleared and written
    std::uint64_t pixelsWritten = 0;  // in 32-bit pixel units (a 64-bit pixel counts 2)
    int draws = 0;
    std::string aluBasis; // where the ALU figure comes from (ShaderCost::basis)
};

struct PassPrediction {
    std::string pass;
    double ms = 0;
    std::string bound; // "alu", "texture", "memory", "rop" (the largest), or "draws"
    double aluMs = 0, textureMs = 0, memoryMs = 0, ropMs = 0, drawMs = 0;
    PassDemand demand;
    nlohmann::json toJson() const;
};

PassPrediction predictPass(const DeviceSpec& device, const PassDemand& demand);

struct FramePrediction {
    std::vector<PassPrediction> passes; // in frame order
    double totalMs = 0;
    const PassPrediction* pass(const std::string& name) const; // null when absent
    nlohmann::json toJson() const;
};

FramePrediction predictFrame(const DeviceSpec& device, const std::vector<PassDemand>& demands);

} // namespace pb::devicemodel
