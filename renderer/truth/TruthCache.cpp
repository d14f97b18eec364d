#include "truth/TruthCache.h"

#include "core/Error.h"
#include "core/FileIO.h"
#include "raytrace/SceneHash.h"

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace pb::truth {
namespace {

void hashScene(Hasher& h, const scene::Scene& s) {
    h.pod(std::uint64_t(s.materials.size()));
    for (const scene::Material& m : s.materials) {
        h.pod(m.baseColor);
        h.pod(std::int32_t(m.baseColorTexture));
        h.pod(m.emissive);
        h.pod(std::int32_t(m.emissiveTexture));
        h.pod(std::uint8_t(m.doubleSided));
        h.pod(std::uint32_t(m.alphaMode));
        h.pod(m.alphaCutoff);
    }
    h.pod(std::uint64_t(s.textures.size()));
    for (const scene::Texture& t : s.textures) {
        h.pod(std::int32_t(t.width));
        h.pod(std::int32_t(t.height));
        h.pod(std::uint64_t(t.rgba8.size()));
        h.bytes(t.rgba8.data(), t.rgba8.size());
    }
    h.pod(std::uint64_t(s.instances.size()));
    for (const scene::Instance& inst : s.instances) {
        h.pod(inst.transform);
        h.pod(std::int32_t(inst.primitive));
        if (inst.primitive < 0 || inst.primitive >= int(s.primitives.size())) continue;
        const scene::Primitive& p = s.primitives[size_t(inst.primitive)];
        raytrace::hashPrimitiveGeometry(h, p);
        h.pod(std::uint64_t(p.normals.size()));
        h.bytes(p.normals.data(), p.normals.size() * sizeof(glm::vec3));
        h.pod(std::uint64_t(p.uvs.size()));
        h.bytes(p.uvs.data(), p.uvs.size() * sizeof(glm::vec2));
    }
    raytrace::hashLights(h, s.lights);
    raytrace::hashSun(h, s.sun);
    h.pod(s.sky.radiance);
}

std::string sidecarPath(const std::string& pfm) {
    return pfm.substr(0, pfm.size() - 4) + ".json";
}

} // namespace

std::uint64_t truthInputHash(const scene::Scene& scene, const scene::View& view,
                             const TruthSettings& settings) {
    Hasher h;
    h.pod(kTruthAlgorithmVersion);
    hashScene(h, scene);
    h.pod(view.position);
    h.pod(view.target);
    h.pod(view.fovYDegrees);
    h.pod(std::int32_t(settings.width));
    h.pod(std::int32_t(settings.height));
    h.pod(std::int32_t(settings.spp));
    h.pod(std::int32_t(settings.maxDepth));
    h.pod(settings.seed); // threads are not hashed: they never change the image
    return h.value();
}

std::string truthCachePath(const std::string& dir, std::uint64_t hash) {
    char name[40];
    std::snprintf(name, sizeof name, "truth-%016llx.pfm", static_cast<unsigned long long>(hash));
    return (std::filesystem::path(dir) / name).string();
}

std::optional<TruthResult> loadCachedTruth(const std::string& dir, std::uint64_t hash,
                                           const TruthSettings& settings) {
    const std::string pfm = truthCachePath(dir, hash);
    std::error_code ec;
    if (!std::filesystem::exists(pfm, ec) || !std::filesystem::exists(sidecarPath(pfm), ec))
        return std::nullopt;
    try {
        TruthResult r;
        const image::ImageF rgb = image::readPfm(pfm);
        if (rgb.width != settings.width || rgb.height != settings.height || rgb.channels < 3)
            return std::nullopt;
        // PFM holds RGB; the tracer's image is RGBA (a = 1), as the renderer's read-back.
        r.hdr.width = rgb.width;
        r.hdr.height = rgb.height;
        r.hdr.channels = 4;
        r.hdr.pixels.assign(size_t(rgb.width) * size_t(rgb.height) * 4, 1.0f);
        for (int y = 0; y < rgb.height; ++y)
            for (int x = 0; x < rgb.width; ++x)
                for (int c = 0; c < 3; ++c)
                    r.hdr.at(x, y, c) = rgb.at(x, y, c);
        auto bytes = readFileBytes(sidecarPath(pfm));
        auto j = nlohmann::json::parse(bytes.begin(), bytes.end());
        if (j.at("hash").get<std::string>() != std::to_string(hash)) return std::nullopt;
        r.noise.meanLuminance = j.at("mean_luminance").get<double>();
        r.noise.standardError = j.at("standard_error").get<double>();
        r.noise.relativeStandardError = j.at("relative_standard_error").get<double>();
        r.noise.pixelRelativeStandardError = j.at("pixel_relative_standard_error").get<double>();
        r.noise.relativeMseNoiseFloor = j.at("relative_mse_noise_floor").get<double>();
        r.noise.varianceKnown = j.at("variance_known").get<bool>();
        r.cameraRays = j.at("camera_rays").get<std::uint64_t>();
        r.seconds = j.at("seconds").get<double>();
        r.note = j.at("note").get<std::string>();
        return r;
    } catch (const std::exception&) {
        return std::nullopt; // damaged: recompute
    }
}

void storeCachedTruth(const std::string& dir, std::uint64_t hash, const TruthResult& r) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) throw fileError(dir, "cannot create the cache folder: " + ec.message());
    const std::string pfm = truthCachePath(dir, hash);
    nlohmann::json j;
    j["hash"] = std::to_string(hash);
    j["mean_luminance"] = r.noise.meanLuminance;
    j["standard_error"] = r.noise.standardError;
    j["relative_standard_error"] = r.noise.relativeStandardError;
    j["pixel_relative_standard_error"] = r.noise.pixelRelativeStandardError;
    j["relative_mse_noise_floor"] = r.noise.relativeMseNoiseFloor;
    j["variance_known"] = r.noise.varianceKnown;
    j["camera_rays"] = r.cameraRays;
    j["seconds"] = r.seconds;
    j["note"] = r.note;
    const std::string text = j.dump(2) + "\n";
    image::writePfm(pfm, r.hdr);
    writeFileAtomic(sidecarPath(pfm), text.data(), text.size());
}

} // namespace pb::truth
