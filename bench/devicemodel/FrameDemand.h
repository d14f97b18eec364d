#pragma once
// What each pass of one frame asks of the GPU (PassModel.h's PassDemand), built from figures the
// testbed counts exactly. One row per pass, in frame order; the rules, in one place:
//
//   shadow        fragments = the shadow maps' texels (depth-only; each map is written whole);
//                 writes 4 B per texel; one draw per mesh per map.
//   gbuffer       fragments = covered pixels (the cost model's share of GI pixels, times the
//                 frame); texture samples = the program's texture instructions per fragment;
//                 writes every pixel's GBuffer bytes; one draw per mesh.
//   gi-depth-copy (gi.multi_volume=stencil) the cost model's depth-copy fetches; writes 4 B per
//                 GI-target pixel.
//   gi-apply      the cost model's replay of the pass (renderer/costmodel): fragments = evaluated
//                 pixels, samples by kind (depth, normal, flags, state, visibility: 32-bit or
//                 point; irradiance RGBA16F: 64-bit bilinear; SH coefficients: 64-bit trilinear
//                 3D), bytes read = the fetch stream's misses in a cache of the device's L2
//                 geometry, for the variant's probe order and loops; writes = the GI target
//                 cleared and written (gi.target_format's bytes); draws: naive one per volume
//                 drawn, stencil a fill, a mark and an apply per volume plus the clear.
//                 ALU: the program's cost (ShaderCost.h); with gi.loops=split the fused twin's,
//                 because the compilers count a loop's body once and split reorders the same
//                 arithmetic.
//   upsample      (gi.resolution half or quarter) fragments = frame pixels; reads the GI target,
//                 its depth, the frame's depth (and with temporal the history) once; writes
//                 RGBA16F.
//   direct        fragments = frame pixels; reads the GBuffer and the GI target once; writes the
//                 RGBA16F radiance.
//   composite     fragments = frame pixels; reads the radiance once; writes RGBA8.
//   other passes  (gi-dynamic-sh: the worst-case views have no dynamic object) not modelled: a
//                 zero row with a note.
//
// Texture samples of passes other than gi-apply: ir3's texture-instruction count of the same
// program (ShaderCost.h textureInstructions) per fragment, as 32-bit bilinear samples; their
// reads are their inputs read once (full-screen passes read in screen order: each texel
// reaches the cache once). Vertex work, early-Z overdraw and tile-based resolve are not modelled.
#include "PassModel.h"
#include "costmodel/CostModel.h"
#include "profile/Profile.h"

#include <map>
#include <string>
#include <vector>

namespace pb::devicemodel {

// One pass's fragment program on the device's compiler (ShaderCost.h).
struct PassProgram {
    double aluCyclesPerFragment = 0;
    std::string aluBasis;
    double textureInstructions = -1; // ir3's count per fragment; -1: unknown (0 samples)
};

// The renderer's fixed facts the rules need (filled where the renderer is linked).
struct FrameFacts {
    int gbufferBytesPerPixel = 0; // every GBuffer channel and the depth-stencil
    // The sun's depth maps (render::ShadowPass: the view map and the whole-scene map), texels
    // per side of each; empty: no shadow pass.
    std::vector<int> shadowMapSizes;
    int meshes = 0;               // draws of the gbuffer and shadow passes
};

struct FrameDemandInputs {
    int width = 0, height = 0; // the frame (GBuffer)
    profile::Profile switches;
    // The cost model's replay of this variant's GI apply pass at this size, with `l2Cache`
    // among its caches (runCostModel with the device's L2).
    const costmodel::CostReport* cost = nullptr;
    std::string l2Cache;
    std::vector<std::string> passes;              // the passes the frame runs, in order
    std::map<std::string, PassProgram> programs;  // per pass (absent: no ALU figure, noted)
    FrameFacts facts;
};

// Bytes per pixel of gi.target_format: rgba16f 8, r11g11b10f 4, rgba32f 16.
int giTargetBytes(profile::GiTargetFormat f);

// One demand per pass of `in.passes`. Throws pb::Error when the cost report lacks the variant
// or the cache a rule needs.
std::vector<PassDemand> frameDemand(const FrameDemandInputs& in);

} // namespace pb::devicemodel
