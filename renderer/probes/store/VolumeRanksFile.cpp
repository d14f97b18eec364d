#include "probes/store/VolumeRanksFile.h"

#include "core/Error.h"
#include "core/FileIO.h"
#include "probes/store/ProbeFile.h"

#include <filesystem>

namespace pb::probes {

namespace {
constexpr const char* kFormat = "probebench volume ranks";
constexpr int kVersion = 1;
} // namespace

std::string volumeRanksPath(const std::string& probeFile) {
    return probeFile + ".ranks.json";
}

nlohmann::json volumeRanksJson(const VolumeRanks& r) {
    nlohmann::json vols = nlohmann::json::array();
    for (const VolumeRank& v : r.volumes)
        vols.push_back({{"name", v.name},
                        {"loss", v.loss},
                        {"bytes", v.bytes},
                        {"value_per_mib", v.valuePerMiB()},
                        {"pixels", v.pixels},
                        {"views", v.views},
                        {"lookups_naive", v.lookups},
                        {"lookups_saved_stencil", v.lookupsSaved}});
    return {{"format", kFormat},
            {"version", kVersion},
            {"probe_input_hash", r.inputHash},
            {"scenario", r.scenario},
            {"views", r.views},
            {"width", r.width},
            {"height", r.height},
            {"loss", "relative MSE of the indirect irradiance over the views' pixels with the "
                     "volume and its children omitted"},
            {"volumes", vols}};
}

VolumeRanks parseVolumeRanks(const nlohmann::json& j, const std::string& path) {
    try {
        if (!j.is_object() || j.value("format", "") != kFormat)
            throw Error(path + ": not a volume ranks file (probebench volumes --write-ranks)");
        if (j.at("version").get<int>() != kVersion)
            throw Error(path + ": ranks file version " +
                        std::to_string(j.at("version").get<int>()) + ", expected " +
                        std::to_string(kVersion));
        VolumeRanks r;
        r.inputHash = j.at("probe_input_hash").get<std::uint64_t>();
        r.scenario = j.at("scenario").get<std::string>();
        r.views = j.at("views").get<std::string>();
        r.width = j.at("width").get<int>();
        r.height = j.at("height").get<int>();
        for (const auto& v : j.at("volumes")) {
            VolumeRank k;
            k.name = v.at("name").get<std::string>();
            k.loss = v.at("loss").get<double>();
            k.bytes = v.at("bytes").get<std::uint64_t>();
            k.pixels = v.at("pixels").get<std::int64_t>();
            k.views = v.at("views").get<int>();
            k.lookups = v.at("lookups_naive").get<std::int64_t>();
            k.lookupsSaved = v.at("lookups_saved_stencil").get<std::int64_t>();
            if (!(k.loss >= 0)) throw Error(path + ": volume '" + k.name + "': loss below 0");
            r.volumes.push_back(std::move(k));
        }
        return r;
    } catch (const nlohmann::json::exception& e) {
        throw Error(path + ": malformed ranks file: " + e.what());
    }
}

void writeVolumeRanks(const std::string& path, const VolumeRanks& r) {
    const std::string text = volumeRanksJson(r).dump(2) + "\n";
    writeFileAtomic(path, text.data(), text.size());
}

VolumeRanks readVolumeRanks(const std::string& path) {
    const std::vector<unsigned char> bytes = readFileBytes(path);
    nlohmann::json j = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
    if (j.is_discarded()) throw Error(path + ": not valid JSON");
    return parseVolumeRanks(j, path);
}

std::string volumeRanksProblem(const VolumeRanks& r, const ProbeSet& set) {
    if (r.inputHash != set.inputHash) return "ranked another bake (input hash differs)";
    if (r.volumes.size() != set.volumes.size())
        return "ranks " + std::to_string(r.volumes.size()) + " volume(s), the probe set has " +
               std::to_string(set.volumes.size());
    for (size_t i = 0; i < r.volumes.size(); ++i)
        if (r.volumes[i].name != set.volumes[i].name)
            return "volume " + std::to_string(i) + " is '" + r.volumes[i].name + "' there and '" +
                   set.volumes[i].name + "' in the probe set";
    return "";
}

void attachVolumeRanks(ProbeSet& set, const std::string& probeFile) {
    set.ranks.reset();
    const std::string path = volumeRanksPath(probeFile);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        set.ranksNote = "no ranks file " + path;
        return;
    }
    try {
        VolumeRanks r = readVolumeRanks(path);
        if (std::string why = volumeRanksProblem(r, set); !why.empty()) {
            set.ranksNote = path + " is stale: " + why;
            return;
        }
        set.ranks = std::move(r);
        set.ranksNote.clear();
    } catch (const Error& e) {
        set.ranksNote = e.what();
    }
}

ProbeSet readProbeFileWithRanks(const std::string& path) {
    ProbeSet set = readProbeFile(path);
    attachVolumeRanks(set, path);
    return set;
}

} // namespace pb::probes
