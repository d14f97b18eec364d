// The bake cache key: a hash of everything the probe data depends on. Thread count is not in
// it (it never changes the result). Bump kBakeAlgorithmVersion whenever the bake's output
// changes for the same inputs, so stale files are re-baked rather than reused.
#include "probes/bake/BakeHash.h"

#include "probes/bake/Baker.h"
#include "probes/store/SparseStorage.h"
#include "core/Hash.h"
#include "probes/store/ProbeFile.h"
#include "raytrace/SceneHash.h"
#include "raytrace/RayScene.h"

#include <algorithm>
#include <string_view>
#include <type_traits>

namespace pb::probes {
namespace {

// 7: the radiance passes shade with the hit's normal and barycentrics as Embree returns them
// (last-bit changes, RayScene.h RayHit); 6: the SH record from the ray samples; 5: relocation
// stays inside the volume's box, and the nesting blend leaves relocated ring probes alone and
// looks the parent up without surface bias (issue 24); 4: lit-surface samples; 3: emitter
// sampling (MIS) at the probe; 2: far scenes bake in a moved frame. (Sparse storage's
// free-space lattice changed only sparse files: bakeInputHash hashes its step for sparse
// requests, so dense files kept their hash.)
constexpr std::uint32_t kBakeAlgorithmVersion = 8;

void hashScene(Hasher& h, const scene::Scene& s) {
    const auto mats = raytrace::summariseMaterials(s);
    h.pod(std::uint64_t(mats.size()));
    for (const raytrace::MaterialSummary& m : mats) {
        h.pod(m.albedo);
        h.pod(m.emissive);
        h.pod(std::uint8_t(m.doubleSided));
        h.pod(std::uint8_t(m.invisible));
    }
    // Geometry through the instances that are baked: primitive data + transform.
    std::uint64_t baked = 0;
    for (const scene::Instance& inst : s.instances) {
        if (inst.dynamic || inst.primitive < 0 || inst.primitive >= int(s.primitives.size()))
            continue;
        const scene::Primitive& p = s.primitives[size_t(inst.primitive)];
        ++baked;
        h.pod(inst.transform);
        raytrace::hashPrimitiveGeometry(h, p);
    }
    h.pod(baked);
    raytrace::hashLights(h, s.lights);
}

} // namespace

// The volume's fields as ProbeVolume::forEachField lists them, with one exception kept so that
// every existing probe file keeps its hash (the gate's committed bake among them): `parent` was
// hashed after `counts`, before the list existed.
void hashVolume(Hasher& h, const ProbeVolume& v) {
    ProbeVolume::forEachField(v, [&h, &v](std::string_view label, const auto& field) {
        using T = std::decay_t<decltype(field)>;
        if (label == "parent") return;
        if (label == "edge blend") h.str(v.parent);
        if constexpr (std::is_same_v<T, std::string>)
            h.str(field);
        else
            h.pod(field);
    });
}

void hashBakeVersionsAndScene(Hasher& h, const scene::Scene& scene) {
    h.pod(kBakeAlgorithmVersion);
    h.pod(kProbeFileContentVersion);
    hashScene(h, scene);
}

std::uint64_t bakeInputHash(const scene::Scene& scene, const BakeRequest& r) {
    Hasher h;
    hashBakeVersionsAndScene(h, scene);
    h.pod(std::uint64_t(r.volumes.size()));
    for (const ProbeVolume& v : r.volumes)
        hashVolume(h, v);
    h.pod(std::uint64_t(r.scenarios.size()));
    for (const Scenario& s : r.scenarios) {
        h.str(s.name);
        raytrace::hashSun(h, s.sun);
        h.pod(s.sky.radiance);
    }
    const BakeSettings& b = r.settings;
    h.pod(std::int32_t(b.raysPerProbe));
    h.pod(std::int32_t(b.bounces));
    h.pod(b.seed);
    h.pod(std::uint32_t(b.format));
    h.pod(std::uint8_t(b.relocate));
    h.pod(b.backfaceThreshold);
    h.pod(std::int32_t(b.emitterSamples));
    h.pod(std::int32_t(b.litSamples));
    h.pod(b.noiseTarget);
    h.pod(std::int32_t(kMaxNoiseRounds));
    h.pod(std::uint8_t(r.sparse));
    // What sparse storage keeps changed with the free-space lattice (issue 18): sparse files
    // from before it lack the lattice and must be re-baked. Dense bakes (the gate's committed
    // file among them) keep their hash.
    if (r.sparse) h.pod(std::uint32_t(kFreeSpaceLatticeStep));
    // ... and what the probes it leaves out keep (not hashed for stand-ins, so files from
    // before the choice keep their hash); Ranked's choice depends on its budget.
    if (r.sparse && r.freeSpace == FreeSpace::Irradiance) h.pod(std::uint32_t(2));
    if (r.sparse && r.freeSpace == FreeSpace::Ranked) {
        h.pod(std::uint32_t(3));
        h.pod(std::max(r.freeSpaceBudgetBytes, 0.0)); // ProbeSet::freeSpaceBudgetBytes
    }
    // Only set by the update engine's sample bakes: every other bake keeps its hash.
    if (r.geometryRays > 0) h.pod(std::int32_t(r.geometryRays));
    return h.value();
}

} // namespace pb::probes
