#include "ShaderCost.h"

#include "core/Error.h"

#include <cstdio>

namespace pb::devicemodel {

AluCost aluCost(const shaders::StageStatistics& s, const std::string& driver,
                const DeviceSpec& device, bool fp16) {
    AluCost c;
    char buf[160];
    if (s.has("cycles")) {
        // Mali: the compiler's per-unit bounds; texture ("texture", "t") is costed elsewhere.
        static const char* units[] = {"arith", "fma", "cvt", "sfu", "v", "vary", "ls", "ldst"};
        std::string used;
        double top = -1;
        for (const char* u : units)
            if (s.has(u)) {
                top = std::max(top, s.field(u));
                used += std::string(used.empty() ? "" : ", ") + u;
            }
        if (top < 0) {
            top = s.field("cycles");
            used = "cycles";
        }
        c.cyclesPerFragment = top;
        std::snprintf(buf, sizeof buf, "%s: max(%s) = %.4g cycles", device.compiler.c_str(),
                      used.c_str(), top);
        c.basis = buf;
        if (fp16 && driver != "panfrost" && device.fp16Rate > 1) c.cyclesPerFragment /= device.fp16Rate;
        return c;
    }
    const double inst = s.instructions();
    if (inst < 0) throw Error(device.compiler + ": the compiler reported neither cycles nor instructions");
    c.cyclesPerFragment = inst / double(device.fp32LanesPerCore);
    std::snprintf(buf, sizeof buf, "%s: %.0f inst / %d lanes", device.compiler.c_str(), inst,
                  device.fp32LanesPerCore);
    c.basis = buf;
    if (fp16 && driver != "panfrost" && device.fp16Rate > 1) {
        c.cyclesPerFragment /= device.fp16Rate;
        std::snprintf(buf, sizeof buf, " / fp16 rate %.3g", device.fp16Rate);
        c.basis += buf;
    }
    return c;
}

double textureInstructions(const shaders::StageStatistics& s) {
    return s.has("cat5") ? s.field("cat5") : -1;
}

} // namespace pb::devicemodel
