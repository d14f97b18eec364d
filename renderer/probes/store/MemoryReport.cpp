#include "probes/store/MemoryReport.h"

#include "core/Error.h"
#include "probes/store/SparseLayout.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

namespace pb::probes {
namespace {

ProbeBytes bytesOf(const glm::ivec3& c, StorageFormat f) {
    return {storedBytes(irradianceShape(c), f), storedBytes(visibilityShape(c), f)};
}

// A sparse volume's textures: irradiance for the stored and irradiance-only tiles, visibility
// for the stored ones (SparseLayout.h), as GpuProbes allocates them.
ProbeBytes sparseBytesOf(std::size_t stored, std::size_t irradianceOnly, const glm::ivec3& counts,
                         StorageFormat f) {
    const glm::ivec3 irr = packedCounts(stored + irradianceOnly, counts);
    return {storedBytes(irradianceShape(irr), f),
            storedBytes(visibilityShape(visibilityPackedCounts(stored, irr)), f)};
}

void add(ProbeBytes& a, const ProbeBytes& b) {
    a.irradiance += b.irradiance;
    a.visibility += b.visibility;
}

nlohmann::json bytesJson(const ProbeBytes& b, std::size_t probes) {
    return {{"irradiance", b.irradiance},
            {"visibility", b.visibility},
            {"total", b.total()},
            {"per_probe", probes ? b.total() / probes : 0}};
}

nlohmann::json volumeJson(const VolumeMemory& v, bool sparse) {
    nlohmann::json j = {{"name", v.name},
                        {"counts", {v.counts.x, v.counts.y, v.counts.z}},
                        {"probes", v.probes},
                        {"uncompressed", bytesJson(v.uncompressed, v.storedProbes)},
                        {"bc6h", bytesJson(v.bc6h, v.storedProbes)},
                        {"stored", bytesJson(v.stored, v.storedProbes)},
                        {"stored_probes", v.storedProbes},
                        {"irradiance_only_probes", v.irradianceOnlyProbes},
                        {"indirection", v.indirection},
                        {"stored_total", v.storedTotal()}};
    if (sparse)
        j["sparse_candidates"] = {{"far_from_surfaces", v.sparse.far},
                                  {"invalid", v.sparse.invalid},
                                  {"needed", v.probes - v.sparse.total()}};
    return j;
}

// Bytes of `probes` probes at the per-probe cost of `b` over `of` probes.
std::size_t scaled(std::size_t bytes, std::size_t probes, std::size_t of) {
    return of ? std::size_t(double(bytes) * double(probes) / double(of)) : 0;
}

} // namespace

std::string formatBytes(std::size_t bytes) {
    char buf[64];
    if (bytes < 1024)
        std::snprintf(buf, sizeof buf, "%zu B", bytes);
    else if (bytes < 1024 * 1024)
        std::snprintf(buf, sizeof buf, "%.2f KiB", double(bytes) / 1024.0);
    else
        std::snprintf(buf, sizeof buf, "%.2f MiB", double(bytes) / (1024.0 * 1024.0));
    return buf;
}

MemoryReport memoryReport(const std::vector<ProbeVolume>& volumes, StorageFormat format,
                          const std::vector<std::size_t>* storedProbes,
                          const std::vector<std::size_t>* irradianceOnlyProbes) {
    MemoryReport r;
    r.format = format;
    r.total.name = "total";
    for (std::size_t i = 0; i < volumes.size(); ++i) {
        const ProbeVolume& v = volumes[i];
        VolumeMemory m;
        m.name = v.name;
        m.counts = v.counts;
        m.probes = std::size_t(v.probeCount());
        m.storedProbes = storedProbes ? std::min((*storedProbes)[i], m.probes) : m.probes;
        m.irradianceOnlyProbes =
            irradianceOnlyProbes ? std::min((*irradianceOnlyProbes)[i], m.probes - m.storedProbes)
                                 : 0;
        const bool sparse = m.storedProbes < m.probes;
        auto bytes = [&](StorageFormat f) {
            return sparse ? sparseBytesOf(m.storedProbes, m.irradianceOnlyProbes, v.counts, f)
                          : bytesOf(v.counts, f);
        };
        m.uncompressed = bytes(StorageFormat::Rgba16f);
        m.bc6h = bytes(StorageFormat::Bc6h);
        m.stored = bytes(format);
        m.indirection = sparse ? m.probes * kStateBytesPerProbe : 0;
        r.total.probes += m.probes;
        r.total.storedProbes += m.storedProbes;
        r.total.irradianceOnlyProbes += m.irradianceOnlyProbes;
        r.total.indirection += m.indirection;
        add(r.total.uncompressed, m.uncompressed);
        add(r.total.bc6h, m.bc6h);
        add(r.total.stored, m.stored);
        r.volumes.push_back(m);
    }
    return r;
}

MemoryReport memoryReport(const ProbeSet& set) {
    std::vector<std::size_t> stored, irradianceOnly;
    for (const auto& states : set.states) {
        stored.push_back(storedCount(states));
        irradianceOnly.push_back(irradianceOnlyCount(states));
    }
    MemoryReport r = memoryReport(set.volumes, set.format(), &stored, &irradianceOnly);
    std::vector<SparseCounts> sparse = countSparseCandidates(set);
    for (std::size_t v = 0; v < r.volumes.size(); ++v) {
        r.volumes[v].sparse = sparse[v];
        r.total.sparse.far += sparse[v].far;
        r.total.sparse.invalid += sparse[v].invalid;
    }
    r.hasSparse = true;
    return r;
}

glm::ivec3 parseGrid(const std::string& text) {
    std::smatch m;
    static const std::regex re(R"(^\s*(\d{1,5})\s*[xX]\s*(\d{1,5})\s*[xX]\s*(\d{1,5})\s*$)");
    if (!std::regex_match(text, m, re))
        throw Error("--grid: expected NXxNYxNZ such as 32x8x32 (got '" + text + "')");
    glm::ivec3 c(std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3]));
    for (int a = 0; a < 3; ++a)
        if (c[a] < 1 || c[a] > kMaxProbesPerAxis)
            throw Error("--grid: every axis needs 1.." + std::to_string(kMaxProbesPerAxis) +
                        " probes (got '" + text + "')");
    return c;
}

std::string formatMemoryReport(const MemoryReport& r) {
    std::ostringstream s;
    auto line = [&](const VolumeMemory& v) {
        char buf[512];
        // Per stored probe: a sparse volume's tiles (packing padding included) over its stored
        // probes, not over the grid.
        const std::size_t stored = v.storedProbes ? v.storedProbes : v.probes;
        const std::size_t p = std::max<std::size_t>(stored, 1);
        std::snprintf(
            buf, sizeof buf, "%-16s %-12s %11zu %8zu  %10s (%zu+%zu B/probe)  %10s (%zu+%zu B/probe)\n",
            v.name.c_str(),
            v.counts.x ? (std::to_string(v.counts.x) + "x" + std::to_string(v.counts.y) + "x" +
                          std::to_string(v.counts.z))
                             .c_str()
                       : "",
            v.probes, stored, formatBytes(v.uncompressed.total()).c_str(), v.uncompressed.irradiance / p,
            v.uncompressed.visibility / p, formatBytes(v.bc6h.total()).c_str(),
            v.bc6h.irradiance / p, v.bc6h.visibility / p);
        s << buf;
    };
    // "grid probes" and "stored" as `bake` says them (probes/ProbeCounts.h): every probe of
    // the grid, and those that own a tile; bytes and B/probe are of the stored ones.
    s << "probe memory, one scenario resident (irradiance + visibility)\n";
    char head[256];
    std::snprintf(head, sizeof head, "%-16s %-12s %11s %8s  %-36s %s\n", "volume", "grid",
                  "grid probes", "stored", "uncompressed (rgba16f + rg16f)", "bc6h");
    s << head;
    for (const VolumeMemory& v : r.volumes)
        line(v);
    VolumeMemory t = r.total;
    t.counts = glm::ivec3(0);
    line(t);
    s << "  grid probes: every probe of the grids; stored: those with a tile (sparse storage "
         "leaves the rest out); the bytes and B/probe are the stored probes'\n";
    s << "  irradiance " << formatBytes(r.total.uncompressed.irradiance) << " + visibility "
      << formatBytes(r.total.uncompressed.visibility) << " uncompressed; "
      << formatBytes(r.total.bc6h.irradiance) << " + " << formatBytes(r.total.bc6h.visibility)
      << " bc6h\n";
    if (r.format != StorageFormat::Rgba16f && r.format != StorageFormat::Bc6h)
        s << "  stored as " << formatName(r.format) << ": " << formatBytes(r.total.stored.total())
          << "\n";
    if (r.total.storedProbes < r.total.probes)
        s << "sparse storage: " << r.total.storedProbes << " of " << r.total.probes
          << " grid probes stored (packed tiles above)"
          << (r.total.irradianceOnlyProbes
                  ? ", " + std::to_string(r.total.irradianceOnlyProbes) +
                        " more irradiance only (free space: an irradiance tile, no visibility)"
                  : std::string())
          << " + " << formatBytes(r.total.indirection)
          << " indirection (probe state, 16 B per grid probe) = "
          << formatBytes(r.total.storedTotal()) << " as " << formatName(r.format) << "\n";
    if (r.hasSparse && r.total.storedProbes == r.total.probes) {
        const VolumeMemory& t = r.total;
        const std::size_t needed = t.probes - t.sparse.total();
        s << "sparse-storage candidates (all stored now): " << t.sparse.far << " of " << t.probes
          << " grid probes far from every surface, " << t.sparse.invalid
          << " inside geometry; storing only the other " << needed << " would take "
          << formatBytes(scaled(t.stored.total(), needed, t.probes)) << " as "
          << formatName(r.format) << " (an estimate from the visibility; `bake --sparse` keeps "
          << "the probes at surface cells)\n";
    }
    return s.str();
}

nlohmann::json memoryReportJson(const MemoryReport& r) {
    nlohmann::json vols = nlohmann::json::array();
    for (const VolumeMemory& v : r.volumes)
        vols.push_back(volumeJson(v, r.hasSparse));
    nlohmann::json total = volumeJson(r.total, r.hasSparse);
    total.erase("name");
    total.erase("counts");
    return {{"format", formatName(r.format)}, {"volumes", vols}, {"total", total}};
}

} // namespace pb::probes
