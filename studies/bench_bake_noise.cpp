// bench_bake_noise: how much a bake depends on its random seed (studies/common/SeedDifference.h).
// Two probe files of one scene, baked alike but for --seed, compared at random surface points:
// the relative difference of the irradiance as mean, median and p90, and split into the
// dimmest quarter of the points and the rest. studies/bake_noise.sh bakes the pairs and runs
// this on them (studies/findings/bake-noise.md "Bake noise").
//
// Usage: bench_bake_noise SCENE A.probes B.probes [POINTS] [--region X0,Y0,Z0,X1,Y1,Z1]
// (SCENE: built-in name or glTF; --region: only the points inside that box, e.g. one room)
#include "core/Error.h"
#include "core/ReuseFreedMemory.h"
#include "probes/store/ProbeFile.h"
#include "scene/SceneLoader.h"
#include "studies/common/SeedDifference.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>

using namespace pb;

namespace {

const char* const kUsage =
    "usage: bench_bake_noise SCENE A.probes B.probes [POINTS] [--region X0,Y0,Z0,X1,Y1,Z1]\n";

// The command line (usage above).
struct Options {
    std::string scene, a, b; // the scene and the two probe files
    int points = 2000;
    std::optional<scene::Bounds> region;
};

// The command line, or exit 2 with the usage or the bad --region.
Options parseOptions(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "%s", kUsage);
        std::exit(2);
    }
    Options o{argv[1], argv[2], argv[3], 2000, std::nullopt};
    for (int i = 4; i < argc; ++i) {
        if (std::strcmp(argv[i], "--region") == 0 && i + 1 < argc) {
            scene::Bounds b;
            if (std::sscanf(argv[++i], "%f,%f,%f,%f,%f,%f", &b.min.x, &b.min.y, &b.min.z, &b.max.x,
                            &b.max.y, &b.max.z) != 6 ||
                b.empty()) {
                std::fprintf(stderr,
                             "bench_bake_noise: error: --region: expected X0,Y0,Z0,X1,Y1,Z1 "
                             "with X0 <= X1 (got '%s')\n",
                             argv[i]);
                std::exit(2);
            }
            o.region = b;
        } else if ((o.points = std::atoi(argv[i])) <= 0) {
            std::fprintf(stderr, "%s", kUsage);
            std::exit(2);
        }
    }
    return o;
}

void printSeedDifference(const std::string& scene, const studies::SeedDifference& d) {
    std::printf("%s: %zu points compared, relative difference of the irradiance between the "
                "seeds: mean %.2f%%, median %.2f%%, p90 %.2f%%\n",
                scene.c_str(), d.points, 100 * d.mean, 100 * d.median, 100 * d.p90);
    std::printf("  dimmest quarter (irradiance < %.4g): mean %.2f%%; the rest: mean %.2f%%\n",
                d.dimQuarterBelow, 100 * d.dimMean, 100 * d.brightMean);
}

} // namespace

int main(int argc, char** argv) {
    pb::reuseFreedMemory(); // as probebench does (ReuseFreedMemory.h)
    const Options o = parseOptions(argc, argv);
    try {
        const scene::Scene s = scene::loadScene(o.scene);
        const studies::SeedDifference d =
            studies::seedDifference(s, probes::readProbeFile(o.a), probes::readProbeFile(o.b),
                                    o.points, o.region ? &*o.region : nullptr);
        printSeedDifference(o.scene, d);
    } catch (const Error& e) {
        std::fprintf(stderr, "bench_bake_noise: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
