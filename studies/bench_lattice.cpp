// bench_lattice: does the DDGI lookup print the probe lattice on floors? (issue 24) A benchmark,
// not a test (studies/findings/lattice-on-floors.md "Lattice on floors"): it prints a table (and JSON with --json),
// asserts nothing.
//
// Per scene, lines on flat upward surfaces (studies/common/LatticeScore.h: --lines lines of
// 64 points, an eighth of the default uniform spacing apart, along X and Z) are looked up in
// each placement and compared with a direct gather at the same points:
//   uniform   `--volumes auto-uniform`, stored dense (probe planes where the bounds put them);
//   auto      the default `bake` (`--volumes auto`: adaptive, sparse, lattice search);
//   FILE      hand-drawn volumes (--volumes FILE.toml, repeatable), stored dense.
// Each is baked with the bake's defaults but for --rays (default 128) and --noise-target 0
// (one round: the pattern is the lookup's, not the bake's noise). The truth at a point is the
// last bounce gathered there (SurfaceGather.h, --gather-rays, default 512) with the first
// read from a 1-bounce bake of the uniform grid at the hits: the same truth for every
// placement; the hemisphere average of those lookups leaves little of that grid's pattern.
// Per placement: the relative RMS error over all line points (luminance, over the mean truth)
// and the lattice score of each line at the spacing of the volume that holds its midpoint
// (median, p90, and the share of lines above 2).
//
// --elevation DEG: the viewer's angle above the floor (default 15: a standing eye looking a few
// metres ahead; 90 looks straight down, where the surface bias points straight up).
// --below Y keeps the lines under height Y (world units): a value a little over a storey's floor
// measures that floor alone (Sponza's ground floor: --below 1; without it most lines fall on
// the roof).
// Usage: bench_lattice [--lines N] [--rays R] [--gather-rays G] [--below Y] [--elevation DEG]
//                      [--volumes FILE]...
//                      [--json FILE] [SCENE...]   (default: the five shared scenes)
#include "core/Error.h"
#include "core/Luminance.h"
#include "core/ReuseFreedMemory.h"
#include "probes/ProbeSampler.h"
#include "raytrace/RayScene.h"
#include "probes/bake/SurfaceGather.h"
#include "probes/placement/AutoPlacement.h"
#include "probes/store/VolumeFile.h"
#include "scene/SceneLoader.h"
#include "studies/common/LatticeScore.h"
#include "studies/common/SharedScenes.h"
#include "studies/common/StudyBake.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

using namespace pb;
using namespace pb::probes;
using studies::FloorLine;

namespace {

constexpr int kSamplesPerLine = 64, kSamplesPerCell = 8;

// The command line (usage above).
struct Options {
    int lines = 40, rays = 128, gatherRays = 512;
    float below = std::numeric_limits<float>::infinity(); // --below: lines start under it
    float elevation = 15.0f; // --elevation: the viewer's angle above the floor, degrees
    std::vector<std::string> volumeFiles, scenes;
    std::string json;
};

// One scene's floor lines and the truth at their points: what every placement is scored on.
struct FloorTruth {
    std::vector<FloorLine> lines;
    float step = 0.0f;            // between the points of a line
    std::vector<glm::vec3> truth; // per point, line after line (kSamplesPerLine each)
};

double percentile(std::vector<double> v, double q) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v[std::min(v.size() - 1, std::size_t(q * double(v.size())))];
}

// A bake of one round (--noise-target 0): the pattern measured is the lookup's, not the bake's
// noise.
ProbeSet bakeOneRound(const scene::Scene& s, const std::vector<ProbeVolume>& volumes, bool sparse,
                      int rays, int bounces) {
    studies::BakeOptions b;
    b.volumes = volumes;
    b.rays = rays;
    b.bounces = bounces;
    b.noiseTarget = 0.0f;
    b.sparse = sparse;
    return studies::bake(s, b);
}

// One placement's row: the relative RMS error over every line point and the lattice score of
// each line at the spacing of the volume that holds its midpoint.
nlohmann::json scorePlacement(const std::string& name, const ProbeSet& set,
                              const std::vector<FloorLine>& lines,
                              const std::vector<glm::vec3>& truth, float elevationDeg) {
    const ProbeSampler sampler(set, 0);
    std::vector<double> scores;
    double squared = 0.0, truthSum = 0.0;
    std::size_t points = 0, unlit = 0;
    for (std::size_t l = 0; l < lines.size(); ++l) {
        const FloorLine& line = lines[l];
        std::vector<double> residual(std::size_t(line.samples));
        // Towards a viewer looking along the line from behind its start, elevationDeg above
        // the floor: the surface bias leans along the view, so a grazing view reads the probes
        // from much closer to the floor than a view from straight above.
        const float el = glm::radians(elevationDeg);
        const glm::vec3 view = -line.axis * std::cos(el) + glm::vec3(0, 1, 0) * std::sin(el);
        double lineTruth = 0.0;
        for (int i = 0; i < line.samples; ++i)
            lineTruth += pb::luminance(truth[l * kSamplesPerLine + std::size_t(i)]) / line.samples;
        if (!(lineTruth > 0.0)) continue;
        for (int i = 0; i < line.samples; ++i) {
            const glm::vec3 p = line.point(i);
            const IrradianceSample e = sampler.sample(p, {0, 1, 0}, view);
            unlit += e.weight <= 0.0f;
            const double t = pb::luminance(truth[l * kSamplesPerLine + std::size_t(i)]);
            const double d = pb::luminance(e.irradiance) - t;
            residual[std::size_t(i)] = d / lineTruth;
            squared += d * d;
            truthSum += t;
            ++points;
        }
        const glm::vec3 mid = line.point(line.samples / 2);
        const int v = sampler.selectVolume(mid);
        if (v < 0) continue;
        const glm::vec3 cell = set.volumes[std::size_t(v)].cellSize();
        const float spacing = line.axis.x != 0.0f ? cell.x : cell.z;
        scores.push_back(studies::latticeScore(residual, line.step, 1.0f / spacing));
    }
    const double meanTruth = points ? truthSum / double(points) : 0.0;
    const double above2 = scores.empty() ? 0.0
                                         : double(std::count_if(scores.begin(), scores.end(),
                                                                [](double s) { return s > 2.0; })) /
                                               double(scores.size());
    return {{"placement", name},
            {"probes", set.probeCount()},
            {"stored_probes", set.storedCount()},
            {"lines_scored", scores.size()},
            {"relative_rms_error",
             meanTruth > 0 ? std::sqrt(squared / double(points)) / meanTruth : 0.0},
            {"lattice_score_median", percentile(scores, 0.5)},
            {"lattice_score_p90", percentile(scores, 0.9)},
            {"lines_above_2", above2},
            {"unlit_points", unlit}};
}

// `--volumes auto-uniform`: the uniform grid whose spacing sets the lines' step.
std::vector<ProbeVolume> uniformVolumes(const scene::Scene& s) {
    AutoPlacementRequest uniformReq;
    uniformReq.mode = AutoMode::Uniform;
    return placeAutoVolumes(s, uniformReq).volumes;
}

// The lines (an eighth of the uniform spacing between points), and at their points the last
// bounce gathered there with the first read from a 1-bounce bake of the uniform grid.
FloorTruth gatherFloorTruth(const scene::Scene& s, const pb::raytrace::RayScene& rs,
                            const std::vector<ProbeVolume>& uniform, const Options& o) {
    FloorTruth f;
    const float spacing = uniform[0].cellSize().x;
    f.step = spacing / float(kSamplesPerCell);
    f.lines = studies::findFloorLines(rs, o.lines, kSamplesPerLine, f.step, 0x11A77ECEu, o.below);
    if (f.lines.empty()) return f;
    std::vector<GatherPoint> points;
    for (const FloorLine& l : f.lines)
        for (int i = 0; i < l.samples; ++i)
            points.push_back({l.point(i), {0, 1, 0}});
    const ProbeSet firstBounce = bakeOneRound(s, uniform, false, o.rays, 1);
    const ProbeSampler indirect(firstBounce, 0);
    GatherSettings gs;
    gs.rays = o.gatherRays;
    f.truth = gatherIrradiance(rs, resolveScenarios({}, {}, s)[0], s.lights, points, &indirect, gs);
    return f;
}

// The rows of every placement: uniform, auto (sparse) and each --volumes file, 2 bounces.
nlohmann::json scorePlacements(const scene::Scene& s, const std::vector<ProbeVolume>& uniform,
                               const FloorTruth& f, const Options& o) {
    nlohmann::json rows = nlohmann::json::array();
    rows.push_back(scorePlacement("uniform", bakeOneRound(s, uniform, false, o.rays, 2), f.lines,
                                  f.truth, o.elevation));
    AutoPlacementRequest autoReq;
    autoReq.sparse = true;
    rows.push_back(scorePlacement(
        "auto", bakeOneRound(s, placeAutoVolumes(s, autoReq).volumes, true, o.rays, 2), f.lines,
        f.truth, o.elevation));
    for (const std::string& file : o.volumeFiles)
        rows.push_back(
            scorePlacement(std::filesystem::path(file).filename().string(),
                           bakeOneRound(s, loadVolumeFile(file).volumes, false, o.rays, 2), f.lines,
                           f.truth, o.elevation));
    return rows;
}

// One scene: its floor lines, the truth there, and every placement's row.
nlohmann::json runScene(const std::string& path, const Options& o) {
    const scene::Scene s = scene::loadScene(path);
    const pb::raytrace::RayScene rs(s);
    const std::vector<ProbeVolume> uniform = uniformVolumes(s);
    const FloorTruth f = gatherFloorTruth(s, rs, uniform, o);
    nlohmann::json out = {{"scene", path},
                          {"lines", f.lines.size()},
                          {"step", f.step},
                          {"view_elevation_deg", o.elevation}};
    out["placements"] =
        f.lines.empty() ? nlohmann::json::array() : scorePlacements(s, uniform, f, o);
    return out;
}

// The command line; exits with 2 on a bad one.
Options parseOptions(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool hasValue = i + 1 < argc;
        if (a == "--lines" && hasValue)
            o.lines = std::atoi(argv[++i]);
        else if (a == "--rays" && hasValue)
            o.rays = std::atoi(argv[++i]);
        else if (a == "--gather-rays" && hasValue)
            o.gatherRays = std::atoi(argv[++i]);
        else if (a == "--below" && hasValue)
            o.below = float(std::atof(argv[++i]));
        else if (a == "--elevation" && hasValue)
            o.elevation = float(std::atof(argv[++i]));
        else if (a == "--volumes" && hasValue)
            o.volumeFiles.push_back(argv[++i]);
        else if (a == "--json" && hasValue)
            o.json = argv[++i];
        else if (a.rfind("--", 0) == 0) {
            std::fprintf(stderr, "bench_lattice: error: %s: unknown option or missing value\n",
                         a.c_str());
            std::exit(2);
        } else
            o.scenes.push_back(a);
    }
    if (o.lines < 1 || o.rays < 1 || o.gatherRays < 1) {
        std::fprintf(stderr,
                     "bench_lattice: error: --lines, --rays and --gather-rays must be >= 1\n");
        std::exit(2);
    }
    if (o.scenes.empty()) o.scenes = studies::sharedScenes();
    return o;
}

void printHeader() {
    std::printf("%-28s %-22s %7s %8s %9s %10s %9s %9s\n", "scene", "placement", "lines", "stored",
                "rel RMS", "score med", "p90", ">2");
}

// One scene's rows of the table (runScene's result).
void printScene(const std::string& path, const nlohmann::json& r) {
    const std::string name = std::filesystem::path(path).stem().string();
    for (const auto& p : r["placements"])
        std::printf("%-28s %-22s %7zu %8zu %9.4f %10.2f %9.2f %8.0f%%\n", name.c_str(),
                    p["placement"].get<std::string>().c_str(), p["lines_scored"].get<std::size_t>(),
                    p["stored_probes"].get<std::size_t>(), p["relative_rms_error"].get<double>(),
                    p["lattice_score_median"].get<double>(), p["lattice_score_p90"].get<double>(),
                    100.0 * p["lines_above_2"].get<double>());
    if (r["placements"].empty())
        std::printf("%-28s (no flat upward surface found)\n", name.c_str());
    std::fflush(stdout);
}

} // namespace

int main(int argc, char** argv) {
    pb::reuseFreedMemory(); // as probebench does (ReuseFreedMemory.h)
    const Options o = parseOptions(argc, argv);
    nlohmann::json all = nlohmann::json::array();
    printHeader();
    try {
        for (const std::string& path : o.scenes) {
            const nlohmann::json r = runScene(path, o);
            printScene(path, r);
            all.push_back(r);
        }
    } catch (const Error& e) {
        std::fprintf(stderr, "bench_lattice: error: %s\n", e.what());
        return 1;
    }
    if (!o.json.empty()) std::ofstream(o.json) << all.dump(2) << "\n";
    return 0;
}
