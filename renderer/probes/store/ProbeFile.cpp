#include "probes/store/ProbeFile.h"

#include "core/Error.h"
#include "core/FileIO.h"
#include "probes/store/BinaryIO.h"
#include "core/Hash.h"
#include "probes/StorageScale.h"
#include "probes/store/SparseLayout.h"

#include <cmath>
#include <cstring>
#include <filesystem>

namespace pb::probes {
namespace {

constexpr std::size_t kFixedHeader = 8 + 4 + 8; // magic, version, file size

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finiteNonNegative(const glm::vec3& v) {
    return finite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f;
}

// The checksum only proves the bytes are the ones written; a file written by something else
// (or crafted) with a valid checksum must still not hand NaN, negative light or wild offsets
// to the sampler and the GPU. What the bake itself guarantees is checked here.
void checkSettings(const BakeSettings& b, const std::string& path) {
    if (b.raysPerProbe < 1 || b.raysPerProbe > 65536 || b.bounces < 0 || b.bounces > 64 ||
        !(b.backfaceThreshold >= 0.0f && b.backfaceThreshold <= 1.0f) ||
        b.emitterSamples < 0 || b.emitterSamples > 65536 || b.litSamples < 0 ||
        b.litSamples > 65536 ||
        !(b.noiseTarget >= 0.0f && b.noiseTarget < 1.0f))
        throw fileError(path, "corrupt bake settings (rays " + std::to_string(b.raysPerProbe) +
                                  ", bounces " + std::to_string(b.bounces) + ")");
}

void checkScenario(const Scenario& s, const std::string& path) {
    const std::string what = "scenario '" + s.name + "'";
    if (s.name.empty()) throw fileError(path, "corrupt: a scenario without a name");
    const scene::Sun& sun = s.sun;
    if (!finite(sun.toSun) || (sun.enabled && !(glm::length(sun.toSun) > 0.0f)) ||
        !finiteNonNegative(sun.color) || !std::isfinite(sun.intensity) || sun.intensity < 0.0f ||
        !finiteNonNegative(s.sky.radiance))
        throw fileError(path, "corrupt " + what +
                                  ": sun or sky not finite and non-negative, or no sun direction");
}

void checkStates(const ProbeVolume& v, const std::vector<ProbeState>& states,
                 const std::string& path) {
    // Relocation stays within kMaxRelocation of a cell; a whole cell is the corrupt limit.
    const glm::vec3 cell = v.cellSize();
    for (const ProbeState& p : states)
        if (!finite(p.offset) || std::abs(p.offset.x) > cell.x || std::abs(p.offset.y) > cell.y ||
            std::abs(p.offset.z) > cell.z || !(p.backfaceRatio >= 0.0f && p.backfaceRatio <= 1.0f))
            throw fileError(path, "corrupt probe state in volume '" + v.name +
                                      "' (offset beyond a cell, or not finite)");
}

// The stored bytes, not the decoded texels: decodeStored turns inf/NaN into 0 for the CPU
// sampler, but the GPU uploads the stored bytes as they are. BC6H (unsigned) has no sign,
// infinity or NaN to check.
void checkStoredValues(const ProbeTexture& t, StorageFormat f, const std::string& path,
                       const char* what) {
    bool bad = false;
    const std::uint8_t* p = t.stored.data();
    if (f == StorageFormat::Rgba32f) {
        for (std::size_t i = 0; i + 4 <= t.stored.size() && !bad; i += 4) {
            float v;
            std::memcpy(&v, p + i, 4);
            bad = !(v >= 0.0f && v <= 3.4028235e38f); // NaN fails both
        }
    } else if (f == StorageFormat::Rgba16f) {
        for (std::size_t i = 0; i + 2 <= t.stored.size() && !bad; i += 2) {
            std::uint16_t h;
            std::memcpy(&h, p + i, 2);
            const bool negative = (h & 0x8000) != 0 && (h & 0x7FFF) != 0; // -0 is fine
            bad = negative || (h & 0x7C00) == 0x7C00;                     // inf or NaN
        }
    }
    if (bad)
        throw fileError(path, std::string("corrupt ") + what +
                                  " data (a negative, infinite or NaN texel)");
}

// The storage-scale record (version 2, StorageScale.h): one f32 per scenario, shared by the
// scenario's volumes. Kept as its own record after the scenarios.
// A volume's fields (ProbeVolume::forEachField) as the file stores them: strings with their
// length, the rotation as x, y, z, w whatever glm's own order, everything else as its bytes.
void writeField(ByteWriter& w, const std::string& s) { w.str(s); }
void writeField(ByteWriter& w, const glm::quat& q) { w.pod(glm::vec4(q.x, q.y, q.z, q.w)); }
template <class T> void writeField(ByteWriter& w, const T& v) { w.pod(v); }

void readField(ByteReader& r, const std::string& what, std::string& s) { s = r.str(what.c_str()); }
void readField(ByteReader& r, const std::string& what, glm::quat& q) {
    const auto v = r.pod<glm::vec4>(what.c_str());
    q = glm::quat(v.w, v.x, v.y, v.z);
}
template <class T> void readField(ByteReader& r, const std::string& what, T& v) {
    v = r.pod<T>(what.c_str());
}

void writeStorageScales(ByteWriter& w, const ProbeSet& set) {
    for (const auto& textures : set.irradiance) {
        const float s = textures.empty() ? 1.0f : textures.front().storageScale;
        for (const ProbeTexture& t : textures)
            if (std::memcmp(&t.storageScale, &s, sizeof s) != 0) // bits: a NaN is written too
                throw Error("probe set: the volumes of one scenario have different storage "
                            "scales (the file holds one per scenario)");
        w.pod(s);
    }
}

std::vector<float> readStorageScales(ByteReader& r, std::uint32_t scenarios,
                                     const std::vector<Scenario>& named, const std::string& path) {
    std::vector<float> scales;
    for (std::uint32_t i = 0; i < scenarios; ++i) {
        scales.push_back(r.pod<float>("storage scale"));
        if (!isValidStorageScale(scales.back()))
            throw fileError(path, "corrupt storage scale of scenario '" + named[i].name +
                                      "' (not a power of two in 2^-64..2^64)");
    }
    return scales;
}

void writeTexture(ByteWriter& w, const ProbeTexture& t) {
    w.pod(std::uint64_t(t.stored.size()));
    w.raw(t.stored.data(), t.stored.size());
}

void readTexture(ByteReader& r, ProbeTexture& t, const TextureShape& shape, StorageFormat f,
                 const std::string& path, const char* what, float storageScale = 1.0f) {
    auto size = r.pod<std::uint64_t>(what);
    if (size != storedBytes(shape, f))
        throw fileError(path, std::string("corrupt ") + what + " size (" + std::to_string(size) +
                                  " bytes, expected " + std::to_string(storedBytes(shape, f)) +
                                  ")");
    const std::uint8_t* p = r.take(std::size_t(size), what);
    t.shape = shape;
    t.storageScale = storageScale;
    t.stored.assign(p, p + size);
    checkStoredValues(t, f, path, what);
    decodeStored(t, f);
}

// --- Sparse storage record (version 2), kept apart from the rest of the format: per volume
// u8 layout (0 dense, 1 sparse); sparse: u32 stored count + a presence bitmap, bit i (byte
// i / 8, least significant bit first) = probe i owns a tile. A sparse volume's textures are
// then its stored tiles packed in probe order (SparseLayout.h); absent probes are invalid.
// Version 7 adds, after the presence bitmap, u32 + a bitmap of the same kind for the
// irradiance-only probes (ProbeState::irradianceOnly): valid, with an irradiance tile packed
// after the stored ones (irradianceSlots) and no visibility tile.

void writeBitmap(ByteWriter& w, const std::vector<ProbeState>& states, bool (*has)(const ProbeState&)) {
    std::vector<std::uint8_t> bits((states.size() + 7) / 8, 0);
    std::uint32_t count = 0;
    for (std::size_t i = 0; i < states.size(); ++i)
        if (has(states[i])) {
            bits[i / 8] |= std::uint8_t(1u << (i % 8));
            ++count;
        }
    w.pod(count);
    w.raw(bits.data(), bits.size());
}

void writeStorageRecord(ByteWriter& w, const ProbeSet& set) {
    for (const auto& states : set.states) {
        const bool sparse = isSparse(states);
        w.pod(std::uint8_t(sparse ? 1 : 0));
        if (!sparse) continue;
        writeBitmap(w, states, [](const ProbeState& p) { return p.stored; });
        writeBitmap(w, states, [](const ProbeState& p) { return p.irradianceOnly && !p.stored; });
    }
}

// Reads a count + bitmap; calls set(i, bit) per probe; throws on bits past the end or a count
// that does not match.
template <typename Set>
void readBitmap(ByteReader& r, std::size_t n, const std::string& what, const char* name,
                const std::string& path, Set set) {
    const auto count = r.pod<std::uint32_t>(name);
    const std::size_t bytes = (n + 7) / 8;
    const std::uint8_t* bits = r.take(bytes, name);
    std::size_t present = 0;
    for (std::size_t i = 0; i < bytes * 8; ++i) {
        const bool bit = (bits[i / 8] >> (i % 8)) & 1u;
        if (i >= n) {
            if (bit) throw fileError(path, "corrupt " + what + " (bits past the last probe)");
            continue;
        }
        set(i, bit);
        present += bit ? 1 : 0;
    }
    if (present != count)
        throw fileError(path, "corrupt " + what + " (" + std::to_string(count) + " " + name +
                                  " declared, " + std::to_string(present) + " present)");
}

// Marks the absent probes of every sparse volume (stored = valid = false); returns which
// volumes are sparse.
std::vector<bool> readStorageRecord(ByteReader& r, ProbeSet& set, const std::string& path,
                                    std::uint32_t version) {
    std::vector<bool> sparse;
    for (std::size_t v = 0; v < set.volumes.size(); ++v) {
        const std::string what = "storage of volume '" + set.volumes[v].name + "'";
        const auto layout = r.pod<std::uint8_t>("storage layout");
        if (layout > 1)
            throw fileError(path, "corrupt " + what + " (layout " + std::to_string(layout) + ")");
        sparse.push_back(layout == 1);
        if (layout == 0) continue;
        std::vector<ProbeState>& states = set.states[v];
        readBitmap(r, states.size(), what, "stored probes", path, [&](std::size_t i, bool bit) {
            states[i].stored = bit;
        });
        if (version >= 7)
            readBitmap(r, states.size(), what, "irradiance-only probes", path,
                       [&](std::size_t i, bool bit) {
                           if (bit && states[i].stored)
                               throw fileError(path, "corrupt " + what +
                                                         " (a probe both stored and irradiance-only)");
                           states[i].irradianceOnly = bit;
                       });
        for (ProbeState& s : states)
            if (!s.stored && !s.irradianceOnly) s.valid = false;
    }
    return sparse;
}

// The dense in-memory texture of volume v from the file: read as stored (packed when the
// volume is sparse), then unpacked with absent tiles zero.
void readVolumeTexture(ByteReader& r, ProbeTexture& t, const ProbeVolume& v,
                       const std::vector<ProbeState>& states, bool sparse, bool irradiance,
                       StorageFormat f, const std::string& path, float storageScale = 1.0f) {
    const char* what = irradiance ? "irradiance" : "visibility";
    const int tile = irradiance ? kIrradianceTile : kVisibilityTile;
    const auto shapeOf = [&](const glm::ivec3& c) {
        return irradiance ? irradianceShape(c) : visibilityShape(c);
    };
    if (!sparse) return readTexture(r, t, shapeOf(v.counts), f, path, what, storageScale);
    // Irradiance: the stored tiles, then the irradiance-only ones (irradianceSlots).
    const std::vector<int> slots = irradiance ? irradianceSlots(states) : packedSlots(states);
    const glm::ivec3 packed = packedCounts(
        storedCount(states) + (irradiance ? irradianceOnlyCount(states) : 0), v.counts);
    ProbeTexture p;
    readTexture(r, p, shapeOf(packed), f, path, what, storageScale);
    t = unpackTiles(p, slots, v.counts, packed, tile, f);
}

void writeVolumeTexture(ByteWriter& w, const ProbeTexture& t, const ProbeVolume& v,
                        const std::vector<ProbeState>& states, bool irradiance, StorageFormat f) {
    if (!isSparse(states)) return writeTexture(w, t);
    const std::vector<int> slots = irradiance ? irradianceSlots(states) : packedSlots(states);
    const glm::ivec3 packed = packedCounts(
        storedCount(states) + (irradiance ? irradianceOnlyCount(states) : 0), v.counts);
    writeTexture(w, packTiles(t, slots, v.counts, packed,
                              irradiance ? kIrradianceTile : kVisibilityTile, f));
}

// --- SH record (version 6): u8 present; then per volume and probe u8 insideAtLattice; then
// per scenario, per volume and probe with irradiance (ownsIrradiance) 9 RGB f32 (the others
// read as zeros).
void writeShRecord(ByteWriter& w, const ProbeSet& set) {
    w.pod(std::uint8_t(set.hasSh()));
    if (!set.hasSh()) return;
    for (const auto& states : set.states)
        for (const ProbeState& p : states) w.pod(std::uint8_t(p.insideAtLattice));
    if (set.sh.size() != set.irradiance.size())
        throw Error("probe set: SH for " + std::to_string(set.sh.size()) + " scenarios, " +
                    std::to_string(set.irradiance.size()) + " baked");
    for (const auto& sc : set.sh)
        for (std::size_t v = 0; v < set.volumes.size(); ++v) {
            if (sc.at(v).size() != std::size_t(set.volumes[v].probeCount()) * 9)
                throw Error("probe set: SH of volume '" + set.volumes[v].name + "' has " +
                            std::to_string(sc[v].size()) + " coefficients");
            // Sparse storage's absent probes hold zeros: only probes with irradiance are written.
            for (std::size_t p = 0; p < set.states[v].size(); ++p)
                if (ownsIrradiance(set.states[v][p]))
                    for (int k = 0; k < 9; ++k) w.pod(sc[v][p * 9 + std::size_t(k)]);
        }
}

void readShRecord(ByteReader& body, ProbeSet& set, const std::string& path) {
    if (body.pod<std::uint8_t>("SH present") == 0) return;
    for (auto& states : set.states) {
        if (states.size() > body.remaining())
            throw fileError(path, "file is truncated or corrupt (SH lattice validity)");
        for (ProbeState& p : states) p.insideAtLattice = body.pod<std::uint8_t>("SH lattice") != 0;
    }
    set.sh.resize(set.irradiance.size());
    for (auto& sc : set.sh)
        for (const ProbeVolume& v : set.volumes) {
            const std::size_t n = std::size_t(v.probeCount()) * 9;
            std::size_t stored = 0;
            for (const ProbeState& p : set.states[std::size_t(&v - set.volumes.data())])
                stored += ownsIrradiance(p) ? 1 : 0;
            if (stored * 9 > body.remaining() / sizeof(glm::vec3))
                throw fileError(path, "file is truncated or corrupt (SH of volume '" + v.name +
                                          "')");
            std::vector<glm::vec3> c(n, glm::vec3(0.0f));
            const auto& states = set.states[std::size_t(&v - set.volumes.data())];
            for (std::size_t i = 0; i < n; ++i) {
                if (!ownsIrradiance(states[i / 9])) continue;
                glm::vec3& x = c[i];
                x = body.pod<glm::vec3>("SH coefficient");
                if (!finite(x))
                    throw fileError(path, "corrupt SH coefficient in volume '" + v.name +
                                              "' (not finite)");
            }
            sc.push_back(std::move(c));
        }
}

// --- Free-space record (version 8): u8 FreeSpace, f64 Ranked's budget (ProbeSet.h).
void writeFreeSpaceRecord(ByteWriter& w, const ProbeSet& set) {
    w.pod(std::uint8_t(set.freeSpace));
    w.pod(set.freeSpaceBudgetBytes);
}

void readFreeSpaceRecord(ByteReader& body, ProbeSet& set, const std::string& path) {
    const auto mode = body.pod<std::uint8_t>("free-space choice");
    const auto budget = body.pod<double>("free-space budget");
    if (mode > std::uint8_t(FreeSpace::Irradiance))
        throw fileError(path, "corrupt free-space record (choice " + std::to_string(mode) + ")");
    if (!std::isfinite(budget) || budget < 0.0)
        throw fileError(path, "corrupt free-space record (budget not a finite size)");
    set.freeSpace = FreeSpace(mode);
    set.freeSpaceBudgetBytes = budget;
}

// Before version 8: what the states imply (the bake hashed nothing else then).
void impliedFreeSpace(ProbeSet& set) {
    set.freeSpace = FreeSpace::StandIns;
    for (const auto& states : set.states)
        for (const ProbeState& p : states)
            if (p.irradianceOnly) set.freeSpace = FreeSpace::Irradiance;
    set.freeSpaceBudgetBytes = 0.0;
}

} // namespace

std::vector<std::uint8_t> serializeProbeSet(const ProbeSet& set) {
    ByteWriter w;
    w.raw(kProbeFileMagic, sizeof(kProbeFileMagic));
    w.pod(kProbeFileVersion);
    w.pod(std::uint64_t(0)); // file size, patched below
    w.pod(set.inputHash);
    const BakeSettings& b = set.settings;
    w.pod(std::uint32_t(b.format));
    w.pod(std::int32_t(b.raysPerProbe));
    w.pod(std::int32_t(b.bounces));
    w.pod(b.seed);
    w.pod(std::uint8_t(b.relocate));
    w.pod(b.backfaceThreshold);
    w.pod(std::int32_t(b.emitterSamples));
    w.pod(b.noiseTarget);
    w.pod(std::int32_t(b.litSamples));
    w.pod(std::uint32_t(kIrradianceTile));
    w.pod(std::uint32_t(kVisibilityTile));

    w.pod(std::uint32_t(set.volumes.size()));
    for (const ProbeVolume& v : set.volumes)
        ProbeVolume::forEachField(v, [&w](const char*, const auto& field) { writeField(w, field); });
    w.pod(std::uint32_t(set.scenarios.size()));
    for (const Scenario& s : set.scenarios) {
        w.str(s.name);
        w.pod(std::uint8_t(s.sun.enabled));
        w.pod(s.sun.toSun);
        w.pod(s.sun.color);
        w.pod(s.sun.intensity);
        w.pod(s.sky.radiance);
    }
    if (set.irradiance.size() != set.scenarios.size())
        throw Error("probe set: irradiance for " + std::to_string(set.irradiance.size()) +
                    " scenarios, " + std::to_string(set.scenarios.size()) + " named");
    writeStorageScales(w, set);
    for (const auto& states : set.states)
        for (const ProbeState& p : states) {
            w.pod(p.offset);
            w.pod(p.backfaceRatio);
            w.pod(std::uint8_t(p.valid));
        }
    writeStorageRecord(w, set);
    for (std::size_t v = 0; v < set.visibility.size(); ++v)
        writeVolumeTexture(w, set.visibility[v], set.volumes[v], set.states[v], false,
                           set.format());
    for (const auto& sc : set.irradiance)
        for (std::size_t v = 0; v < sc.size(); ++v)
            writeVolumeTexture(w, sc[v], set.volumes[v], set.states[v], true, set.format());

    writeShRecord(w, set);
    writeFreeSpaceRecord(w, set);

    std::uint64_t total = w.data().size() + sizeof(std::uint64_t);
    std::memcpy(w.data().data() + 12, &total, sizeof(total));
    w.pod(fnv1a64(w.data().data(), w.data().size()));
    return std::move(w.data());
}

ProbeSet parseProbeSet(const std::vector<std::uint8_t>& bytes, const std::string& path) {
    if (bytes.size() < kFixedHeader ||
        std::memcmp(bytes.data(), kProbeFileMagic, sizeof(kProbeFileMagic)) != 0)
        throw fileError(path, "not a probebench probe file (bad magic)");
    ByteReader r(bytes.data(), bytes.size(), path);
    r.take(sizeof(kProbeFileMagic), "magic");
    auto version = r.pod<std::uint32_t>("version");
    // Version 2 was a development format (scales or sparse storage, never both) never shipped.
    if (version < kProbeFileFirstVersion || version > kProbeFileVersion || version == 2)
        throw fileError(path, "probe file version " + std::to_string(version) +
                                  ", this build reads versions " +
                                  std::to_string(kProbeFileFirstVersion) + " to " +
                                  std::to_string(kProbeFileVersion) + " (not 2; re-bake it)");
    auto declared = r.pod<std::uint64_t>("file size");
    if (declared != bytes.size())
        throw fileError(path, "file is truncated or padded (" + std::to_string(bytes.size()) +
                                  " bytes, header says " + std::to_string(declared) + ")");
    if (bytes.size() < kFixedHeader + 8) throw fileError(path, "file is truncated (no checksum)");
    std::uint64_t stored;
    std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
    if (fnv1a64(bytes.data(), bytes.size() - 8) != stored)
        throw fileError(path, "checksum mismatch: the file is corrupted (re-bake it)");
    ByteReader body(bytes.data(), bytes.size() - 8, path);
    body.take(kFixedHeader, "header");

    ProbeSet set;
    set.inputHash = body.pod<std::uint64_t>("input hash");
    auto format = body.pod<std::uint32_t>("format");
    if (!isKnownFormat(format))
        throw fileError(path, "unknown storage format " + std::to_string(format));
    BakeSettings& b = set.settings;
    b.format = StorageFormat(format);
    b.raysPerProbe = body.pod<std::int32_t>("rays");
    b.bounces = body.pod<std::int32_t>("bounces");
    b.seed = body.pod<std::uint64_t>("seed");
    b.relocate = body.pod<std::uint8_t>("relocate") != 0;
    b.backfaceThreshold = body.pod<float>("backface threshold");
    // Before version 4 the bake had neither emitter samples nor a noise target.
    b.emitterSamples = version >= 4 ? body.pod<std::int32_t>("emitter samples") : 0;
    b.noiseTarget = version >= 4 ? body.pod<float>("noise target") : 0.0f;
    // Before version 5 the bake did not sample lit surfaces.
    b.litSamples = version >= 5 ? body.pod<std::int32_t>("lit samples") : 0;
    checkSettings(b, path);
    if (body.pod<std::uint32_t>("tile") != std::uint32_t(kIrradianceTile) ||
        body.pod<std::uint32_t>("tile") != std::uint32_t(kVisibilityTile))
        throw fileError(path, "unsupported probe tile sizes");

    auto volumeCount = body.pod<std::uint32_t>("volume count");
    if (volumeCount == 0 || volumeCount > 4096)
        throw fileError(path, "corrupt volume count " + std::to_string(volumeCount));
    for (std::uint32_t i = 0; i < volumeCount; ++i) {
        ProbeVolume v;
        ProbeVolume::forEachField(v, [&body](const char* label, auto& field) {
            readField(body, "volume " + std::string(label), field);
        });
        set.volumes.push_back(v);
    }
    validateVolumes(set.volumes, path);
    auto scenarioCount = body.pod<std::uint32_t>("scenario count");
    if (scenarioCount == 0 || scenarioCount > 256)
        throw fileError(path, "corrupt scenario count " + std::to_string(scenarioCount));
    for (std::uint32_t i = 0; i < scenarioCount; ++i) {
        Scenario s;
        s.name = body.str("scenario name");
        s.sun.enabled = body.pod<std::uint8_t>("sun") != 0;
        s.sun.toSun = body.pod<glm::vec3>("sun direction");
        s.sun.color = body.pod<glm::vec3>("sun colour");
        s.sun.intensity = body.pod<float>("sun intensity");
        s.sky.radiance = body.pod<glm::vec3>("sky");
        checkScenario(s, path);
        if (set.findScenario(s.name) >= 0)
            throw fileError(path, "corrupt: scenario '" + s.name + "' appears twice");
        set.scenarios.push_back(s);
    }
    // Version 1 has no storage scales (every scenario stored as is) and no storage record.
    const std::vector<float> scales =
        version >= 3 ? readStorageScales(body, scenarioCount, set.scenarios, path)
                     : std::vector<float>(scenarioCount, 1.0f);
    for (const ProbeVolume& v : set.volumes) {
        // 17 bytes per probe must still be there before anything is allocated for them.
        if (std::size_t(v.probeCount()) > body.remaining() / 17)
            throw fileError(path, "file is truncated or corrupt (probe states of volume '" +
                                      v.name + "')");
        std::vector<ProbeState> states(static_cast<size_t>(v.probeCount()));
        for (ProbeState& p : states) {
            p.offset = body.pod<glm::vec3>("probe offset");
            p.backfaceRatio = body.pod<float>("probe ratio");
            p.valid = body.pod<std::uint8_t>("probe validity") != 0;
        }
        checkStates(v, states, path);
        set.states.push_back(std::move(states));
    }
    const std::vector<bool> sparse = version >= 3 ? readStorageRecord(body, set, path, version)
                                                  : std::vector<bool>(set.volumes.size(), false);
    for (std::size_t v = 0; v < set.volumes.size(); ++v) {
        set.visibility.emplace_back();
        readVolumeTexture(body, set.visibility.back(), set.volumes[v], set.states[v], sparse[v],
                          false, b.format, path);
    }
    for (std::uint32_t s = 0; s < scenarioCount; ++s) {
        set.irradiance.emplace_back();
        for (std::size_t v = 0; v < set.volumes.size(); ++v) {
            set.irradiance.back().emplace_back();
            readVolumeTexture(body, set.irradiance.back().back(), set.volumes[v], set.states[v],
                              sparse[v], true, b.format, path, scales[s]);
        }
    }
    if (version >= 6) readShRecord(body, set, path);
    if (version >= 8)
        readFreeSpaceRecord(body, set, path);
    else
        impliedFreeSpace(set);
    if (body.remaining() != 0)
        throw fileError(path, "corrupt: " + std::to_string(body.remaining()) +
                                  " unexpected bytes before the checksum");
    return set;
}

void writeProbeFile(const std::string& path, const ProbeSet& set) {
    std::vector<std::uint8_t> bytes = serializeProbeSet(set);
    writeFileAtomic(path, bytes.data(), bytes.size());
}

ProbeSet readProbeFile(const std::string& path) {
    return parseProbeSet(readFileBytes(path), path);
}

std::optional<ProbeSet> readCachedProbeFile(const std::string& path, std::uint64_t inputHash,
                                            std::string* why) {
    auto say = [&](const std::string& s) {
        if (why) *why = s;
    };
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        say("no file yet");
        return std::nullopt;
    }
    try {
        ProbeSet set = readProbeFile(path);
        // A file from before version 6 has no SH probes: re-bake it so every technique runs.
        if (set.inputHash == inputHash && set.hasSh()) return set;
        if (set.inputHash == inputHash) {
            say("no SH probes (an older probe file version)");
            return std::nullopt;
        }
        say("inputs changed");
    } catch (const Error& e) {
        say(std::string("unusable: ") + e.what());
    }
    return std::nullopt;
}

} // namespace pb::probes
