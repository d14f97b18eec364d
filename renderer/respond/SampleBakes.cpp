#include "respond/SampleBakes.h"

#include "core/Error.h"
#include "probes/ProbeLayout.h"
#include "probes/store/ProbeFile.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace pb::respond {

probes::BakeRequest bakeRequestFor(const World& world, const probes::ProbeSet& original) {
    probes::BakeRequest r;
    r.volumes = original.volumes;
    r.scenarios = {world.scenario};
    r.settings = original.settings;
    r.sparse = false;
    return r;
}

bool bakeInputsDiffer(const World& a, const World& b, const probes::ProbeSet& original) {
    return probes::bakeInputHash(a.scene, bakeRequestFor(a, original)) !=
           probes::bakeInputHash(b.scene, bakeRequestFor(b, original));
}

SampleBakes::SampleBakes(const World& world, const probes::ProbeSet& original, int raysPerUpdate,
                         int count, const std::function<void(const std::string&)>& progress) {
    if (raysPerUpdate < 1) throw Error("--rays-per-update: must be at least 1");
    double cpu = 0, probes = 0;
    int passes = 1;
    for (int k = 0; k < count; ++k) {
        probes::BakeRequest r = bakeRequestFor(world, original);
        r.settings.raysPerProbe = raysPerUpdate;
        // Probes must sit where the file's bake put them (relocation follows the rays).
        r.geometryRays = original.settings.raysPerProbe;
        r.settings.noiseTarget = 0.0f;
        r.settings.seed = original.settings.seed + 1 + std::uint64_t(k);
        r.settings.format = probes::StorageFormat::Rgba32f;
        if (progress)
            progress("sample bake " + std::to_string(k + 1) + "/" + std::to_string(count) + " (" +
                     std::to_string(raysPerUpdate) + " rays per probe and pass)");
        probes::BakeStats st;
        bakes_.push_back(probes::bakeProbes(world.scene, r, &st));
        // The radiance passes' cost (the geometry pass only re-derives the file's geometry).
        for (const probes::BakePhase& ph : st.phases)
            if (ph.name != "geometry") cpu += ph.cpuSeconds;
        probes += double(st.probes - st.invalidProbes);
        if (!st.passes.empty()) passes = st.passes[0];
    }
    // The rays of every pass the sample bakes ran (later passes trace fewer: Baker.h).
    raysPerUpdate_ = 0.0;
    for (int pass = 1; pass <= passes; ++pass)
        raysPerUpdate_ += double(probes::passRays(raysPerUpdate, pass));
    if (probes > 0) {
        cpuMsPerUpdate_ = 1000.0 * cpu / probes;
    }
}

void SampleBakes::sample(const ProbeRef& p, int sampleNo, float* rgb) const {
    using namespace probes;
    const ProbeSet& b = bakes_[std::size_t(sampleNo) % bakes_.size()];
    const ProbeTexture& tex = b.irradiance[0][std::size_t(p.volume)];
    const glm::ivec3 c = b.volumes[std::size_t(p.volume)].probeCoords(p.probe);
    for (int j = 0; j < kIrradianceInterior; ++j)
        for (int i = 0; i < kIrradianceInterior; ++i) {
            const float* t =
                tex.at(c.x * kIrradianceTile + 1 + i, c.z * kIrradianceTile + 1 + j, c.y);
            for (int ch = 0; ch < 3; ++ch)
                rgb[3 * (j * kIrradianceInterior + i) + ch] = t[ch];
        }
}

probes::ProbeSet convergedBake(const World& world, const probes::ProbeSet& original,
                               const std::string& cacheDir, std::string* note) {
    probes::BakeRequest r = bakeRequestFor(world, original);
    r.settings.raysPerProbe = std::min(65536, original.settings.raysPerProbe * kReferenceRayFactor);
    r.geometryRays = original.settings.raysPerProbe;
    const std::uint64_t hash = probes::bakeInputHash(world.scene, r);
    char name[64];
    std::snprintf(name, sizeof name, "respond-%016llx.probes",
                  static_cast<unsigned long long>(hash));
    const std::string path =
        cacheDir.empty() ? "" : (std::filesystem::path(cacheDir) / name).string();
    if (!path.empty())
        if (auto cached = probes::readCachedProbeFile(path, hash)) {
            if (note) *note = "read from the cache " + path;
            return std::move(*cached);
        }
    probes::ProbeSet set = probes::bakeProbes(world.scene, r);
    if (!path.empty()) {
        std::filesystem::create_directories(cacheDir);
        probes::writeProbeFile(path, set);
        if (note) *note = "baked and cached as " + path;
    } else if (note)
        *note = "baked (no cache)";
    return set;
}

} // namespace pb::respond
