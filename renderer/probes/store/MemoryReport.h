#pragma once
// GPU memory of baked probes, per volume and in total, for ONE scenario resident (the GPU
// loads only the active scenario's irradiance; visibility is shared): uncompressed =
// rgba16f + rg16f, BC6H = both textures BC6H, plus the stored format of a probe file.
// A sparse volume (SparseLayout.h) counts only its packed tiles, plus its indirection: the
// per-probe state texture (16 B per grid probe) through which the shader finds the tiles.
#include "probes/ProbeSet.h"
#include "probes/store/SparseCandidates.h"

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace pb::probes {

struct VolumeMemory {
    std::string name;
    glm::ivec3 counts{0};
    std::size_t probes = 0;
    ProbeBytes uncompressed; // rgba16f irradiance + rg16f visibility
    ProbeBytes bc6h;
    ProbeBytes stored;            // in `format`
    SparseCounts sparse;          // probes a sparse layout would not store (from a baked set only)
    std::size_t storedProbes = 0; // probes that own a tile (= probes unless sparse)
    // Sparse: probes left out that keep an irradiance tile (ProbeState::irradianceOnly),
    // counted in the irradiance bytes.
    std::size_t irradianceOnlyProbes = 0;
    std::size_t indirection = 0;  // sparse volumes: bytes of the probe -> tile state texture
    // What the budget counts: the stored textures plus the indirection.
    std::size_t storedTotal() const { return stored.total() + indirection; }
};

struct MemoryReport {
    StorageFormat format = StorageFormat::Rgba16f;
    std::vector<VolumeMemory> volumes;
    VolumeMemory total;
    bool hasSparse = false; // sparse counts filled (the report came from a baked set)
};

// `storedProbes` (optional, one entry per volume): how many probes each volume stores; a
// volume storing fewer than all is sparse (packed tiles + indirection). `irradianceOnlyProbes`
// (optional): how many of the others keep an irradiance tile (SparseLayout.h).
MemoryReport memoryReport(const std::vector<ProbeVolume>& volumes,
                          StorageFormat format = StorageFormat::Rgba16f,
                          const std::vector<std::size_t>* storedProbes = nullptr,
                          const std::vector<std::size_t>* irradianceOnlyProbes = nullptr);
// The same for a baked set, plus the sparse-storage candidates (SparseCandidates.h).
MemoryReport memoryReport(const ProbeSet& set);
// "32x8x32" -> counts; throws pb::Error naming --grid otherwise.
glm::ivec3 parseGrid(const std::string& text);

std::string formatMemoryReport(const MemoryReport& r);
nlohmann::json memoryReportJson(const MemoryReport& r);
// "12.00 MiB", "320 B", ...
std::string formatBytes(std::size_t bytes);

} // namespace pb::probes
