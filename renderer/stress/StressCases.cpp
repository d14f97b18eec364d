#include "stress/StressCases.h"

#include "core/Error.h"
#include "probes/bake/Baker.h"
#include "probes/Octahedral.h"
#include "probes/StorageScale.h"
#include "stress/StressScene.h"

#include <algorithm>
#include <atomic>
#include <cstdio>

namespace pb::stress {

namespace {

using probes::ProbeSet;

std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

ProbeSet bake(const StressScene& s, int rays) {
    probes::BakeRequest r;
    r.volumes.push_back(s.volume);
    r.scenarios = probes::resolveScenarios({"day"}, {}, s.scene);
    r.settings.raysPerProbe = rays;
    r.settings.bounces = 2;
    r.settings.format = probes::StorageFormat::Rgba32f;
    // The sweep tests the renderer's numerics at extremes; its probes are a fixed input: one
    // round of rays, no emitter samples (the converged bake's noise control is not under test
    // here, and its cost would multiply by every case).
    r.settings.noiseTarget = 0.0f;
    r.settings.emitterSamples = 0;
    r.settings.litSamples = 0;
    return probes::bakeProbes(s.scene, r);
}

CaseData caseData(const StressScene& s, ProbeSet probes, const CaseOptions& o) {
    CaseData d;
    d.scene = s.scene;
    d.probes = std::move(probes);
    d.view = s.view;
    d.exposure = s.exposure;
    d.width = o.width;
    d.height = o.height;
    static std::atomic<std::uint64_t> next{1};
    d.id = next++;
    return d;
}

// A case of the plain room with `params`, baked with `rays`, then `edit`ed (visibility,
// states) before storage.
StressCase roomCase(const std::string& group, const std::string& name, const std::string& what,
                    StressSceneParams params, const CaseOptions& o,
                    std::function<void(ProbeSet&)> edit = {}, int rays = 0) {
    const int r = rays > 0 ? rays : o.rays;
    return {group,
            name,
            what,
            [params, o, edit, r] {
                StressScene s = makeStressScene(params);
                ProbeSet set = bake(s, r);
                if (edit) edit(set);
                return caseData(s, std::move(set), o);
            },
            {}};
}

void zeroVariance(ProbeSet& set) {
    for (probes::ProbeTexture& vis : set.visibility)
        for (std::size_t i = 0; i + 1 < vis.texels.size(); i += 2)
            vis.texels[i + 1] = vis.texels[i] * vis.texels[i];
    for (probes::ProbeTexture& vis : set.visibility)
        probes::quantise(vis, probes::StorageFormat::Rgba32f);
}

void invalidateAll(ProbeSet& set) {
    for (auto& states : set.states)
        for (probes::ProbeState& p : states)
            p.valid = false;
}

// Irradiance that jumps at every octahedral fold: a colour per octant of the local direction
// (x, y, z signs), so a lookup that lands on the wrong side of a fold is off by a factor 3.
void octantIrradiance(ProbeSet& set) {
    for (std::size_t v = 0; v < set.volumes.size(); ++v) {
        probes::ProbeTexture& irr = set.irradiance[0][v];
        for (int p = 0; p < set.volumes[v].probeCount(); ++p) {
            const glm::ivec3 c = set.volumes[v].probeCoords(p);
            for (int j = 0; j < probes::kIrradianceInterior; ++j)
                for (int i = 0; i < probes::kIrradianceInterior; ++i) {
                    const glm::vec3 d =
                        probes::octTexelDirection(i, j, probes::kIrradianceInterior);
                    float* t = irr.at(c.x * probes::kIrradianceTile + 1 + i,
                                      c.z * probes::kIrradianceTile + 1 + j, c.y);
                    t[0] = d.x >= 0.0f ? 3.0f : 1.0f;
                    t[1] = d.y >= 0.0f ? 3.0f : 1.0f;
                    t[2] = d.z >= 0.0f ? 3.0f : 1.0f;
                    t[3] = 1.0f;
                }
        }
        probes::fillAllBorders(irr, probes::kIrradianceInterior);
        probes::quantise(irr, probes::StorageFormat::Rgba32f);
    }
}

void addOffsetCases(std::vector<StressCase>& out, const CaseOptions& o) {
    const auto origin = [o] {
        StressScene s = makeStressScene({});
        return caseData(s, bake(s, o.rays), o);
    };
    for (double x : {1e3, 1e5, 1e6}) {
        StressSceneParams p;
        p.offset = glm::dvec3(x);
        StressCase c =
            roomCase("offset", "offset=" + number(x),
                     "the room at (X, X, X), baked there; truth: the room at the origin", p, o);
        c.buildTruth = origin;
        out.push_back(std::move(c));
    }
    const double x = 1e6;
    StressCase moved{"offset_moved", "offset_moved=" + number(x),
                     "the origin's bake moved to (X, X, X): the frame's precision alone",
                     [o, x] {
                         StressSceneParams p;
                         p.offset = glm::dvec3(x);
                         StressScene there = makeStressScene(p);
                         ProbeSet set = bake(makeStressScene({}), o.rays);
                         set.volumes[0].center = there.volume.center;
                         return caseData(there, std::move(set), o);
                     },
                     origin};
    out.push_back(std::move(moved));
}

} // namespace

std::vector<StressCase> stressCases(const CaseOptions& o) {
    std::vector<StressCase> out;
    for (double k : {1e-6, 1e-4, 1e-2, 1.0, 1e2, 1e4, 1e6}) {
        StressSceneParams p;
        p.lightScale = k;
        out.push_back(roomCase("light", "light=" + number(k),
                               "every light x X, exposure / X (fp16 max 65504, min normal 6e-5)", p,
                               o));
    }
    {
        StressSceneParams p;
        p.hotSpot = 1e6;
        out.push_back(roomCase("hot_spot", "hot_spot=1e+06",
                               "an emissive of radiance X at exposure 1: no exposure covers it", p,
                               o));
    }
    for (double spacing : {0.01, 10.0, 1000.0}) {
        StressSceneParams p;
        p.scale = spacing; // the grid is about 1 m at scale 1
        out.push_back(roomCase("spacing", "spacing=" + number(spacing),
                               "the room scaled to a probe spacing of about X metres", p, o));
    }
    addOffsetCases(out, o);
    {
        StressSceneParams p;
        p.partition = 1.0 / 128.0;
        out.push_back(roomCase("thin_wall", "thin_wall=0.0078",
                               "a partition 0.8% of the probe spacing thick", p, o));
    }
    for (glm::ivec3 counts : {glm::ivec3(1), glm::ivec3(2, 1, 1)}) {
        StressSceneParams p;
        p.probeCounts = counts;
        const std::string n = std::to_string(counts.x) + "x" + std::to_string(counts.y) + "x" +
                              std::to_string(counts.z);
        out.push_back(roomCase("grid", "grid=" + n, "a volume of " + n + " probes", p, o));
    }
    out.push_back(roomCase("rays", "rays=1", "one ray per probe", {}, o, {}, 1));
    const int big = std::max(1, o.maxResolution);
    for (glm::ivec2 size : {glm::ivec2(1, 1), glm::ivec2(7, 3), glm::ivec2(big, big)}) {
        StressCase c = roomCase(
            "resolution", "resolution=" + std::to_string(size.x) + "x" + std::to_string(size.y),
            "1x1 up to the largest renderbuffer (at most 4096)", {}, o);
        auto build = c.build;
        c.build = [build, size] {
            CaseData d = build();
            d.width = size.x;
            d.height = size.y;
            return d;
        };
        out.push_back(std::move(c));
    }
    {
        StressSceneParams p;
        p.badNormals = true;
        out.push_back(
            roomCase("bad_normals", "bad_normals", "a mesh with zero and NaN normals", p, o));
    }
    out.push_back(roomCase("variance_zero", "variance_zero",
                           "visibility meanSq = mean^2: Chebyshev variance 0", {}, o,
                           zeroVariance));
    out.push_back(roomCase("fold_edges", "fold_edges",
                           "irradiance jumps at the octahedral folds; normals on the folds", {}, o,
                           octantIrradiance));
    out.push_back(roomCase("all_invalid", "all_invalid", "every probe of the volume invalid", {}, o,
                           invalidateAll));
    return out;
}

std::vector<StressCase> selectCases(const std::vector<StressCase>& all,
                                    const std::vector<std::string>& names) {
    if (names.empty()) return all;
    std::vector<StressCase> out;
    for (const std::string& n : names) {
        bool found = false;
        for (const StressCase& c : all)
            if (c.name == n || c.group == n) {
                found = true;
                if (std::none_of(out.begin(), out.end(),
                                 [&](const StressCase& x) { return x.name == c.name; }))
                    out.push_back(c);
            }
        if (!found) {
            std::vector<std::string> groups;
            for (const StressCase& c : all)
                if (std::find(groups.begin(), groups.end(), c.group) == groups.end())
                    groups.push_back(c.group);
            std::string list;
            for (const std::string& g : groups)
                list += (list.empty() ? "" : ", ") + g;
            throw Error("--cases: no case or group '" + n + "' (groups: " + list + ")");
        }
    }
    return out;
}

ProbeSet inStorageFormat(const ProbeSet& rgba32f, probes::StorageFormat format) {
    ProbeSet out = rgba32f;
    out.settings.format = format;
    if (format == probes::StorageFormat::Rgba32f) return out;
    for (probes::ProbeTexture& t : out.visibility)
        probes::quantise(t, format);
    for (auto& scenario : out.irradiance) {
        probes::assignStorageScale(scenario, format); // as the bake does
        for (probes::ProbeTexture& t : scenario)
            probes::quantise(t, format);
    }
    return out;
}

} // namespace pb::stress
