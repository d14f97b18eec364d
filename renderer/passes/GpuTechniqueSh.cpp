#include "passes/GpuTechniqueSh.h"

#include "passes/GpuProbes.h"
#include "passes/GpuShTextures.h"

namespace pb::render {

std::size_t GpuTechniqueSh::volumeBytes(const probes::ProbeSet& set, int vi) const {
    return shBytesPerProbe(technique_) * std::size_t(set.volumes[size_t(vi)].probeCount());
}

void GpuTechniqueSh::uploadVolume(GpuProbeVolume& g, const probes::ProbeSet& set, int scenario,
                                  int vi, const std::string& what) const {
    g.textures = uploadShVolume(set, scenario, vi, technique_, leak_, what);
}

void GpuTechniqueSh::bindTextures(const gl::Program& program, const GpuProbeVolume& g,
                                  int firstUnit) const {
    const std::size_t coefficients = g.textures.size() - 1; // the last one is the validity
    for (std::size_t t = 0; t < coefficients; ++t) {
        g.textures[t].bind(firstUnit + int(t));
        program.set("u_shCoefficients" + std::to_string(t), firstUnit + int(t));
    }
    g.textures.back().bind(firstUnit + kShUnitsPerVolume - 1);
    program.set("u_shValidity", firstUnit + kShUnitsPerVolume - 1);
}

} // namespace pb::render
