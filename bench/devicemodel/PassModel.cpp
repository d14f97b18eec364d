#include "PassModel.h"

namespace pb::devicemodel {

nlohmann::json PassPrediction::toJson() const {
    const PassDemand& d = demand;
    return {{"pass", pass},
            {"predicted_ms", ms},
            {"bound", bound},
            {"predicted_unit_ms",
             {{"alu", aluMs}, {"texture", textureMs}, {"memory", memoryMs}, {"rop", ropMs},
              {"draws", drawMs}}},
            {"demand",
             {{"fragments", d.fragments},
              {"alu_cycles_per_fragment", d.aluCyclesPerFragment},
              {"alu_basis", d.aluBasis},
              {"samples", d.samples},
              {"wide_samples", d.wideSamples},
              {"trilinear_3d_samples", d.trilinear3dSamples},
              {"wide_trilinear_3d_samples", d.wideTrilinear3dSamples},
              {"bytes_read", d.bytesRead},
              {"bytes_written", d.bytesWritten},
              {"pixels_written", d.pixelsWritten},
              {"draws", d.draws}}}};
}

PassPrediction predictPass(const DeviceSpec& dev, const PassDemand& d) {
    PassPrediction p;
    p.pass = d.pass;
    p.demand = d;
    const double hz = dev.clockHz();
    // ALU: core cycles per fragment spread over every core.
    p.aluMs = double(d.fragments) * d.aluCyclesPerFragment / (double(dev.cores) * hz) * 1e3;
    // Texture units: one bilinear 32-bit texel per unit per clock; wider or 3D costs more.
    const double unitClocks = double(d.samples) + double(d.wideSamples) / dev.wideTexelRate +
                              double(d.trilinear3dSamples) / dev.trilinear3dRate +
                              double(d.wideTrilinear3dSamples) /
                                  (dev.trilinear3dRate * dev.wideTexelRate);
    p.textureMs = unitClocks / (double(dev.cores) * dev.textureUnitsPerCore * hz) * 1e3;
    p.memoryMs = double(d.bytesRead + d.bytesWritten) / (dev.bandwidthGBs * 1e9) * 1e3;
    p.ropMs = double(d.pixelsWritten) / (double(dev.ropPixelsPerClock) * hz) * 1e3;
    p.drawMs = double(d.draws) * dev.drawOverheadUs * 1e-3;
    // The largest demand bounds the pass; ties go to the first named (alu, texture, memory, rop).
    p.bound = "alu";
    double top = p.aluMs;
    const std::pair<const char*, double> others[] = {
        {"texture", p.textureMs}, {"memory", p.memoryMs}, {"rop", p.ropMs}};
    for (const auto& [name, ms] : others)
        if (ms > top) {
            top = ms;
            p.bound = name;
        }
    if (p.drawMs > top) p.bound = "draws";
    p.ms = top + p.drawMs;
    return p;
}

const PassPrediction* FramePrediction::pass(const std::string& name) const {
    for (const PassPrediction& p : passes)
        if (p.pass == name) return &p;
    return nullptr;
}

nlohmann::json FramePrediction::toJson() const {
    nlohmann::json ps = nlohmann::json::array();
    for (const PassPrediction& p : passes)
        ps.push_back(p.toJson());
    return {{"predicted_ms", totalMs}, {"passes", ps}};
}

FramePrediction predictFrame(const DeviceSpec& device, const std::vector<PassDemand>& demands) {
    FramePrediction f;
    for (const PassDemand& d : demands) {
        f.passes.push_back(predictPass(device, d));
        f.totalMs += f.passes.back().ms;
    }
    return f;
}

} // namespace pb::devicemodel
