#include "fuzz/FuzzInputs.h"

#include "core/FileIO.h"
#include "core/Hash.h"
#include "probes/store/ProbeFile.h"
#include "probes/ProbeSampler.h"
#include "profile/ProfileLoader.h"
#include "scene/SceneLoader.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <unistd.h>
#include <vector>

namespace pb::fuzz {

namespace {

void writeBytes(const std::filesystem::path& path, const std::uint8_t* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    if (!out) throw ContractViolation("fuzz harness: cannot write " + path.string());
}

Outcome loadScene(const std::filesystem::path& path) {
    return expectCleanResult(path.string(), [&] { scene::loadGltf(path.string()); });
}

// Every scenario, at each volume's centre and corners, a few normals: a probe set the reader
// accepted must give finite irradiance wherever it is looked up.
void sampleEverywhere(const probes::ProbeSet& set) {
    const glm::vec3 normals[] = {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}, {0.6f, -0.8f, 0}};
    for (int s = 0; s < int(set.scenarios.size()); ++s) {
        const probes::ProbeSampler sampler(set, s);
        for (const probes::ProbeVolume& v : set.volumes) {
            std::vector<glm::vec3> points = v.worldCorners();
            points.push_back(v.center);
            for (const glm::vec3& p : points)
                for (const glm::vec3& n : normals) {
                    const probes::IrradianceSample e = sampler.sample(p, n, n);
                    if (!std::isfinite(e.irradiance.x + e.irradiance.y + e.irradiance.z) ||
                        !std::isfinite(e.weight))
                        throw ContractViolation("probe file loaded but its irradiance at a "
                                                "volume corner is not finite");
                }
        }
    }
}

} // namespace

std::filesystem::path scratchDir() {
    static const std::filesystem::path dir = [] {
        std::error_code ec;
        std::filesystem::path base = std::filesystem::is_directory("/dev/shm", ec)
                                         ? std::filesystem::path("/dev/shm")
                                         : std::filesystem::temp_directory_path();
        std::filesystem::path d = base / ("pb-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    // Removed when the fuzzer exits normally (the end of -max_total_time); a crash leaves it.
    static const bool cleanup = std::atexit([] {
                                    std::error_code ec;
                                    std::filesystem::remove_all(scratchDir(), ec);
                                }) == 0;
    (void)cleanup;
    return dir;
}

Outcome runGltfWithBin(const std::uint8_t* data, std::size_t size,
                       const std::filesystem::path& dir) {
    const auto* nul = static_cast<const std::uint8_t*>(std::memchr(data, 0, size));
    const std::size_t jsonSize = nul ? std::size_t(nul - data) : size;
    const std::size_t binOffset = nul ? jsonSize + 1 : size;
    writeBytes(dir / "fuzz.bin", data + binOffset, size - binOffset);
    writeBytes(dir / "fuzz.gltf", data, jsonSize);
    return loadScene(dir / "fuzz.gltf");
}

Outcome runGlb(const std::uint8_t* data, std::size_t size, const std::filesystem::path& dir) {
    writeBytes(dir / "fuzz.glb", data, size);
    return loadScene(dir / "fuzz.glb");
}

void parseProfileText(std::string_view text, const std::string& name) {
    profile::parseProfileToml(std::string(text), name, profile::ProfileSearch{});
}

Outcome runProbeFile(const std::uint8_t* data, std::size_t size) {
    std::vector<std::uint8_t> bytes(data, data + size);
    auto parseAndSample = [&] {
        const probes::ProbeSet set = probes::parseProbeSet(bytes, "fuzz.pbp");
        sampleEverywhere(set);
    };
    Outcome outcome = expectCleanResult("fuzz.pbp", parseAndSample);
    // The header's file size is bytes 12..19, the FNV-1a checksum the last 8 bytes.
    if (bytes.size() >= 28) {
        const std::uint64_t total = bytes.size();
        std::memcpy(bytes.data() + 12, &total, 8);
        const std::uint64_t sum = pb::fnv1a64(bytes.data(), bytes.size() - 8);
        std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
        if (expectCleanResult("fuzz.pbp", parseAndSample) == Outcome::Loaded)
            outcome = Outcome::Loaded;
    }
    return outcome;
}

} // namespace pb::fuzz
