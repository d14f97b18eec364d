#pragma once
// `--volumes auto`: one axis-aligned root volume fitted to the static scene bounds.
// The box is the bounds grown by 0.1% of the largest extent per side (so floors and walls at
// the bounds lie strictly inside, at full weight), and any axis thinner than one spacing is
// widened to one spacing. Counts per axis: ceil(size / spacing) + 1, so the real spacing is
// at most the requested one. Default spacing: the cube root of (box volume / 4096), i.e.
// about 4096 probes. A spacing that would need more than maxProbes is enlarged until it fits,
// and `note` says so.
//
// Lattice: FitBounds puts the outermost probe planes on that box, i.e. on the floors and walls
// that bound the scene (the naive uniform grid, `auto-uniform`, the placement benchmark's
// baseline). HalfCellMargin (what `--volumes auto` uses) adds one probe per axis and moves the
// outer planes half a cell beyond the box, so a boundary surface lies mid-cell with a probe
// plane on each side of it instead of one on it: such probes sit on the surface, half
// inside it, and leak or need relocation (studies/findings/probe-placement.md "Probe placement" measures it).
// `subdivisions`: the lattice will be split 2^subdivisions times per axis (adaptive
// placement's finer tiers); the margin is then half a cell of the finest split, so no plane of
// any tier lies on a boundary.
#include "probes/ProbeVolume.h"
#include "scene/Scene.h"

#include <string>

namespace pb::probes {

constexpr long long kAutoTargetProbes = 4096;
constexpr long long kAutoMaxProbes = 65536;

enum class AutoLattice { FitBounds, HalfCellMargin };

struct AutoVolume {
    ProbeVolume volume;
    float spacing = 0.0f; // the spacing used (after any cap)
    std::string note;     // non-empty when the requested spacing was capped
};

// spacing <= 0: default. Throws pb::Error for empty bounds (nothing to fit).
AutoVolume fitAutoVolume(const scene::Bounds& staticBounds, float spacing,
                         long long maxProbes = kAutoMaxProbes,
                         AutoLattice lattice = AutoLattice::FitBounds, int subdivisions = 0);

} // namespace pb::probes
