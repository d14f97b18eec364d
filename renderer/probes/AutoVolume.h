#pragma once
// `--volumes auto`: one axis-aligned root volume fitted to the static scene bounds.
// The box is the bounds grown by 0.1% of the largest extent per side (so floors and walls at
// the bounds lie strictly inside, at full weight), and any axis thinner than one spacing is
// widened to one spacing. Counts per axis: ceil(size / spacing) + 1, so the real spacing is
// at most the requested one. Default spacing: the cube root of (box volume / 4096), i.e.
// about 4096 probes. A spacing that would need more than maxProbes is enlarged until it fits,
// and `note` says so.
#include "probes/ProbeVolume.h"
#include "scene/Scene.h"

#include <string>

namespace pb::probes {

constexpr long long kAutoTargetProbes = 4096;
constexpr long long kAutoMaxProbes = 65536;

struct AutoVolume {
    ProbeVolume volume;
    float spacing = 0.0f; // the spacing used (after any cap)
    std::string note;     // non-empty when the requested spacing was capped
};

// spacing <= 0: default. Throws pb::Error for empty bounds (nothing to fit).
AutoVolume fitAutoVolume(const scene::Bounds& staticBounds, float spacing,
                         long long maxProbes = kAutoMaxProbes);

} // namespace pb::probes
