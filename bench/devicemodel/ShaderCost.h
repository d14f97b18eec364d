#pragma once
// One compiled fragment program's cost on a device, from the statistics of the compiler that
// stands in for the device's (DeviceSpec::compiler):
//   - Mali (panfrost) reports per-unit cycle bounds already normalised to one shader core of its
//     family (Bifrost: arith = arithmetic tuples / the core's lanes); the ALU figure is the largest
//     non-texture unit (arithmetic, load/store - spills land there - varyings). The device's lanes
//     are not used again for it.
//   - Adreno (freedreno), Tegra/Maxwell (nouveau), VideoCore (v3d) report instructions per
//     fragment; one instruction is one lane-cycle, so a core needs instructions / lanes per core.
//   - fp16 programs (GI_PRECISION_FP16) on a device with double-rate fp16: Mali's compilers pack
//     fp16 pairs into their counts already; the others count an fp16 instruction like an fp32 one,
//     so their cost is divided by the device's fp16 rate.
// Texture sampling is costed from the counted fetches (FrameDemand.h), never from these units.
// GL-free.
#include "DeviceSpec.h"
#include "bench/shaders/DriverStatistics.h"

#include <string>

namespace pb::devicemodel {

struct AluCost {
    double cyclesPerFragment = 0; // core cycles per fragment
    std::string basis;            // "mali-g52: max(arith, ls, vary) cycles" or "tegra-x1: 580 inst / 128 lanes"
};

// `driver`: the Mesa driver of the compiler (freedreno, panfrost, v3d, nouveau); `fp16`: the
// program was built with GI_PRECISION_FP16. Throws pb::Error when the statistics carry neither
// cycles nor instructions.
AluCost aluCost(const shaders::StageStatistics& fragment, const std::string& driver,
                const DeviceSpec& device, bool fp16);

// Texture instructions of a program as ir3 (freedreno) counts them (its cat5 category: what the
// source asks for, loops counted once); -1 when the statistics are not freedreno's.
double textureInstructions(const shaders::StageStatistics& fragment);

} // namespace pb::devicemodel
