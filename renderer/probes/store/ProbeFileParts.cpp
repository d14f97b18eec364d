#include "probes/store/ProbeFileParts.h"

#include "core/Error.h"
#include "core/FileIO.h"
#include "probes/store/BinaryIO.h"
#include "probes/store/FreeSpaceTiles.h"
#include "core/Hash.h"
#include "probes/store/ProbeFile.h"
#include "probes/store/SparseStorage.h"

#include <algorithm>
#include <cstring>

namespace pb::probes {
namespace {

// A part's geometry as bytes: the probe file without its scenarios. Equal bytes = the same
// volumes, settings, input hash, probe states, storage record and visibility.
std::vector<std::uint8_t> geometryBytes(const ProbeSet& set) {
    ProbeSet g;
    g.inputHash = set.inputHash;
    g.settings = set.settings;
    g.freeSpace = set.freeSpace;
    g.freeSpaceBudgetBytes = set.freeSpaceBudgetBytes;
    g.volumes = set.volumes;
    g.states = set.states;
    g.visibility = set.visibility;
    return serializeProbeSet(g);
}

} // namespace

std::vector<std::size_t> scenarioSplit(std::size_t total, int part, int parts) {
    if (parts < 1 || part < 0 || part >= parts)
        throw Error("--part: must be I/N with 0 <= I < N (got " + std::to_string(part) + "/" +
                    std::to_string(parts) + ")");
    if (std::size_t(parts) > total)
        throw Error("--part: " + std::to_string(parts) + " parts for " + std::to_string(total) +
                    " scenario(s); a scenario split has at most one part per scenario");
    const std::size_t n = std::size_t(parts), p = std::size_t(part);
    const std::size_t base = total / n, extra = total % n;
    const std::size_t first = p * base + std::min(p, extra);
    const std::size_t count = base + (p < extra ? 1 : 0);
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < count; ++i)
        out.push_back(first + i);
    return out;
}

std::vector<std::uint8_t> serializeProbeFilePart(const ProbeFilePart& p) {
    ByteWriter w;
    w.raw(kProbePartMagic, sizeof(kProbePartMagic));
    w.pod(kProbePartVersion);
    w.pod(p.part);
    w.pod(p.parts);
    w.pod(p.totalScenarios);
    w.pod(std::uint32_t(p.scenarios.size()));
    for (std::uint32_t s : p.scenarios)
        w.pod(s);
    const std::vector<std::uint8_t> inner = serializeProbeSet(p.set);
    w.pod(std::uint64_t(inner.size()));
    w.raw(inner.data(), inner.size());
    w.pod(fnv1a64(w.data().data(), w.data().size()));
    return std::move(w.data());
}

ProbeFilePart parseProbeFilePart(const std::vector<std::uint8_t>& bytes, const std::string& path) {
    if (bytes.size() < sizeof(kProbePartMagic) + sizeof(std::uint64_t) ||
        std::memcmp(bytes.data(), kProbePartMagic, sizeof(kProbePartMagic)) != 0)
        throw fileError(path, "not a probe part file (bake --split writes them)");
    const std::size_t body = bytes.size() - sizeof(std::uint64_t);
    std::uint64_t sum = 0;
    std::memcpy(&sum, bytes.data() + body, sizeof(sum));
    if (sum != fnv1a64(bytes.data(), body))
        throw fileError(path, "checksum mismatch (the part file is corrupt)");
    ByteReader r(bytes.data(), body, path);
    r.take(sizeof(kProbePartMagic), "magic");
    if (auto v = r.pod<std::uint32_t>("version"); v != kProbePartVersion)
        throw fileError(path, "part file version " + std::to_string(v) + ", this build reads " +
                                  std::to_string(kProbePartVersion));
    ProbeFilePart p;
    p.part = r.pod<std::uint32_t>("part");
    p.parts = r.pod<std::uint32_t>("parts");
    p.totalScenarios = r.pod<std::uint32_t>("scenario count");
    if (p.parts == 0 || p.part >= p.parts || p.totalScenarios == 0 || p.parts > p.totalScenarios)
        throw fileError(path, "corrupt part header (part " + std::to_string(p.part) + " of " +
                                  std::to_string(p.parts) + ", " +
                                  std::to_string(p.totalScenarios) + " scenarios)");
    const auto held = r.pod<std::uint32_t>("held scenarios");
    if (held == 0 || held > p.totalScenarios)
        throw fileError(path, "corrupt held scenario count " + std::to_string(held));
    for (std::uint32_t i = 0; i < held; ++i) {
        p.scenarios.push_back(r.pod<std::uint32_t>("scenario index"));
        if (p.scenarios.back() >= p.totalScenarios || (i > 0 && p.scenarios[i] <= p.scenarios[i - 1]))
            throw fileError(path, "corrupt scenario index " + std::to_string(p.scenarios.back()));
    }
    const auto size = r.pod<std::uint64_t>("probe file size");
    if (size != r.remaining())
        throw fileError(path, "corrupt probe file size " + std::to_string(size));
    const std::uint8_t* inner = r.take(std::size_t(size), "probe file");
    p.set = parseProbeSet(std::vector<std::uint8_t>(inner, inner + size), path);
    if (p.set.scenarios.size() != held)
        throw fileError(path, "holds " + std::to_string(p.set.scenarios.size()) +
                                  " scenario(s), its header says " + std::to_string(held));
    return p;
}

void writeProbeFilePart(const std::string& path, const ProbeFilePart& p) {
    std::vector<std::uint8_t> bytes = serializeProbeFilePart(p);
    writeFileAtomic(path, bytes.data(), bytes.size());
}

ProbeFilePart readProbeFilePart(const std::string& path) {
    return parseProbeFilePart(readFileBytes(path), path);
}

ProbeSet mergeProbeFileParts(const std::vector<ProbeFilePart>& parts,
                             const std::vector<std::string>& paths) {
    if (parts.empty()) throw Error("bake-merge: no part files");
    auto name = [&](std::size_t i) { return i < paths.size() ? paths[i] : "part " + std::to_string(i); };
    const ProbeFilePart& first = parts.front();
    const std::vector<std::uint8_t> geometry = geometryBytes(first.set);
    std::vector<int> owner(first.totalScenarios, -1); // which given part holds each scenario
    std::vector<int> partSeen(first.parts, -1);
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const ProbeFilePart& p = parts[i];
        if (p.parts != first.parts || p.totalScenarios != first.totalScenarios ||
            p.set.inputHash != first.set.inputHash)
            throw fileError(name(i), "is a part of another bake than " + name(0) +
                                         " (input hash, part count or scenarios differ)");
        if (partSeen[p.part] >= 0)
            throw fileError(name(i), "part " + std::to_string(p.part) + " given twice (also " +
                                         name(std::size_t(partSeen[p.part])) + ")");
        partSeen[p.part] = int(i);
        if (geometryBytes(p.set) != geometry)
            throw fileError(name(i), "its probe states or visibility differ from " + name(0) +
                                         "'s: not one bake's parts (another build or machine "
                                         "that bakes differently?)");
        for (std::uint32_t s : p.scenarios) {
            if (owner[s] >= 0)
                throw fileError(name(i), "scenario " + std::to_string(s) + " is also in " +
                                             name(std::size_t(owner[s])));
            owner[s] = int(i);
        }
    }
    for (std::uint32_t k = 0; k < first.parts; ++k)
        if (partSeen[k] < 0)
            throw Error("bake-merge: part " + std::to_string(k) + " of " +
                        std::to_string(first.parts) + " is missing");
    ProbeSet out = first.set;
    out.scenarios.clear();
    out.irradiance.clear();
    out.sh.clear();
    for (std::uint32_t s = 0; s < first.totalScenarios; ++s) {
        if (owner[s] < 0)
            throw Error("bake-merge: scenario " + std::to_string(s) + " is in no part");
        const ProbeFilePart& p = parts[std::size_t(owner[s])];
        const auto at = std::size_t(std::find(p.scenarios.begin(), p.scenarios.end(), s) -
                                    p.scenarios.begin());
        out.scenarios.push_back(p.set.scenarios[at]);
        out.irradiance.push_back(p.set.irradiance[at]);
        if (p.set.hasSh()) out.sh.push_back(p.set.sh[at]);
    }
    if (out.sh.size() != out.irradiance.size()) out.sh.clear(); // a part without SH: none
    // Ranked free space ranks over every scenario's light, which no part has alone: the parts
    // keep every left-out probe's tile and the choice is made here, as the whole bake makes it.
    if (out.freeSpace == FreeSpace::Ranked) {
        std::vector<std::vector<std::uint8_t>> keep;
        for (const auto& states : out.states) {
            keep.emplace_back(states.size(), 0);
            for (std::size_t i = 0; i < states.size(); ++i)
                keep.back()[i] = states[i].stored ? 1 : 0;
        }
        storeOnly(out, keep, chooseFreeSpaceTiles(out, keep, out.freeSpaceBudgetBytes).tiles);
    }
    return out;
}

} // namespace pb::probes
