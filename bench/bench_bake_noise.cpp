// bench_bake_noise: how much a bake depends on its random seed (probes/bake/SeedDifference.h).
// Two probe files of one scene, baked alike but for --seed, compared at random surface points:
// the relative difference of the irradiance as mean, median and p90, and split into the
// dimmest quarter of the points and the rest. bench/bake_noise.sh bakes the pairs and runs
// this on them (bench/README.md "Bake noise").
//
// Usage: bench_bake_noise SCENE A.probes B.probes [POINTS]   (SCENE: built-in name or glTF)
#include "core/Error.h"
#include "probes/bake/SeedDifference.h"
#include "probes/store/ProbeFile.h"
#include "scene/SceneLoader.h"

#include <cstdio>
#include <cstdlib>

using namespace pb;

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: bench_bake_noise SCENE A.probes B.probes [POINTS]\n");
        return 2;
    }
    try {
        const scene::Scene s = scene::loadScene(argv[1]);
        const probes::SeedDifference d =
            probes::seedDifference(s, probes::readProbeFile(argv[2]),
                                   probes::readProbeFile(argv[3]), argc > 4 ? std::atoi(argv[4]) : 2000);
        std::printf("%s: %zu points compared, relative difference of the irradiance between the "
                    "seeds: mean %.2f%%, median %.2f%%, p90 %.2f%%\n",
                    argv[1], d.points, 100 * d.mean, 100 * d.median, 100 * d.p90);
        std::printf("  dimmest quarter (irradiance < %.4g): mean %.2f%%; the rest: mean %.2f%%\n",
                    d.dimQuarterBelow, 100 * d.dimMean, 100 * d.brightMean);
    } catch (const Error& e) {
        std::fprintf(stderr, "bench_bake_noise: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
