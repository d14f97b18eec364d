// reportJson / reportText of CostModel.h: the machine and the people form of one report.
#include "costmodel/CostModel.h"

#include <algorithm>
#include <cstdio>

namespace pb::costmodel {

namespace {

nlohmann::json cacheJson(const CacheConfig& c) {
    return {{"name", c.name}, {"size_bytes", c.sizeBytes}, {"line_bytes", c.lineBytes},
            {"ways", c.ways}, {"sets", c.sets()},          {"source", c.source}};
}

nlohmann::json volumeJson(const VolumeCounters& v) {
    return {{"name", v.name},
            {"file_index", v.fileIndex},
            {"fragments", v.fragments},
            {"sky_skipped", v.skySkipped},
            {"outside_skipped", v.outsideSkipped},
            {"evaluated", v.evaluated},
            {"faded_out", v.fadedOut},
            {"won", v.won},
            {"culled", v.culled},
            {"fetches",
             {{"gbuffer_depth", v.depthFetches},
              {"gbuffer_normal", v.normalFetches},
              {"gbuffer_flags", v.flagsFetches},
              {"probe_state", v.stateFetches},
              {"visibility", v.visibilityFetches},
              {"irradiance", v.irradianceFetches},
              {"sh_mask", v.shMaskFetches},
              {"sh_coefficients", v.shCoefficientFetches}}},
            {"probe_texels", v.probeTexels},
            {"probe_footprint_bytes", v.probeFootprintBytes}};
}

std::string bytesText(double b) {
    char buf[32];
    if (b >= 1024.0 * 1024.0)
        std::snprintf(buf, sizeof buf, "%.2f MiB", b / (1024.0 * 1024.0));
    else if (b >= 1024.0)
        std::snprintf(buf, sizeof buf, "%.1f KiB", b / 1024.0);
    else
        std::snprintf(buf, sizeof buf, "%.0f B", b);
    return buf;
}

// The naive pass structure's counts; stencil's are not modelled (-1): null / "n/a".
nlohmann::json structureJson(int n) {
    return n < 0 ? nlohmann::json(nullptr) : nlohmann::json(n);
}
std::string structureText(int n) {
    return n < 0 ? "n/a" : std::to_string(n);
}

} // namespace

nlohmann::json reportJson(const CostReport& r) {
    const GiPassCounters& c = r.counters;
    nlohmann::json volumes = nlohmann::json::array();
    for (const VolumeCounters& v : c.volumes)
        volumes.push_back(volumeJson(v));
    nlohmann::json pass{{"multi_volume", c.multiVolume},
                        {"gbuffer_width", c.gbufferWidth},
                        {"gbuffer_height", c.gbufferHeight},
                        {"target_width", c.targetWidth},
                        {"target_height", c.targetHeight},
                        {"divisor", c.divisor},
                        {"target_format", c.targetFormat},
                        {"target_bytes_per_pixel", c.targetBytesPerPixel},
                        {"target_pixels", c.targetPixels},
                        {"gi_pixels", c.giPixels},
                        {"draw_calls", structureJson(c.drawCalls)},
                        {"clears", c.clears},
                        {"program_binds", structureJson(c.programBinds)},
                        {"texture_binds", structureJson(c.textureBinds)},
                        {"texture_unbinds", structureJson(c.textureUnbinds)},
                        {"gbuffer_fetches", c.gbufferFetches},
                        {"depth_copy_fetches", c.depthCopyFetches},
                        {"probe_fetches", c.probeFetches},
                        {"fetches_per_gi_pixel", c.fetchesPerGiPixel},
                        {"max_fetches_per_lookup", c.maxFetchesPerLookup},
                        {"probe_texels", c.probeTexels},
                        {"probe_footprint_bytes", c.probeFootprintBytes},
                        {"render_target_bytes_written", c.renderTargetBytesWritten},
                        {"clear_bytes", c.clearBytes},
                        {"gpu_probe_bytes", c.gpuProbeBytes},
                        {"volumes", volumes}};
    nlohmann::json results = nlohmann::json::array();
    for (const CacheResult& res : r.results)
        results.push_back(
            {{"variant", res.variant},
             {"cache", res.cache.name},
             {"probe_line_accesses", res.probeLines},
             {"probe_line_hits", res.probeHits},
             {"gbuffer_line_accesses", res.gbufferLines},
             {"gbuffer_line_hits", res.gbufferHits},
             {"probe_hit_rate", res.probeHitRate()},
             {"probe_bytes_missed_per_pixel", res.probeBytesMissedPerPixel(c.giPixels)},
             {"all_bytes_missed_per_pixel", res.allBytesMissedPerPixel(c.giPixels)}});
    nlohmann::json caches = nlohmann::json::array();
    std::vector<std::string> seen;
    for (const CacheResult& res : r.results)
        if (std::find(seen.begin(), seen.end(), res.cache.name) == seen.end()) {
            seen.push_back(res.cache.name);
            caches.push_back(cacheJson(res.cache));
        }
    return {
        {"scene", r.scene},
        {"view", r.view},
        {"camera", r.camera},
        {"probe_format", r.probeFormat},
        {"memory_layout", r.layout},
        {"shading_order",
         {{"tile", r.tile}, {"warp_pixels", r.warpPixels}, {"warps_in_flight", r.warpsInFlight}}},
        {"profile", r.profile.valuesJson()},
        {"profile_variant", r.profileVariant},
        {"gi_apply", pass},
        {"caches", caches},
        {"cache_model", results}};
}

std::string reportText(const CostReport& r) {
    const GiPassCounters& c = r.counters;
    std::string out;
    char line[512];
    std::snprintf(line, sizeof line,
                  "cost model: scene %s, view %s, probes %s, memory layout %s, %dx%d tiles, "
                  "warps of %d pixels, %d in flight\n"
                  "gi-apply (gi.multi_volume=%s): GBuffer %dx%d, target %dx%d (%s, %d B/pixel), "
                  "%llu of %llu target pixels need GI\n",
                  r.scene.c_str(), r.view.c_str(), r.probeFormat.c_str(), r.layout.c_str(), r.tile,
                  r.tile, r.warpPixels, r.warpsInFlight, c.multiVolume.c_str(), c.gbufferWidth,
                  c.gbufferHeight, c.targetWidth, c.targetHeight, c.targetFormat.c_str(),
                  c.targetBytesPerPixel, (unsigned long long)c.giPixels,
                  (unsigned long long)c.targetPixels);
    out += line;
    std::snprintf(
        line, sizeof line,
        "  draws %s, clears %d, program binds %s, texture binds %s (+%s unbinds)\n"
        "  fetches: %llu GBuffer + %llu probe = %.2f per GI pixel (shader maximum "
        "%d per lookup), %llu probe texels\n"
        "  probe footprint read %s, render target written %s (+ clear %s), probe data "
        "on the GPU %s\n",
        structureText(c.drawCalls).c_str(), c.clears, structureText(c.programBinds).c_str(),
        structureText(c.textureBinds).c_str(), structureText(c.textureUnbinds).c_str(),
        (unsigned long long)c.gbufferFetches, (unsigned long long)c.probeFetches,
        c.fetchesPerGiPixel, c.maxFetchesPerLookup, (unsigned long long)c.probeTexels,
        bytesText(double(c.probeFootprintBytes)).c_str(),
        bytesText(double(c.renderTargetBytesWritten)).c_str(),
        bytesText(double(c.clearBytes)).c_str(), bytesText(double(c.gpuProbeBytes)).c_str());
    out += line;
    std::snprintf(line, sizeof line, "  %-16s %10s %8s %8s %9s %8s %6s\n", "volume (draw order)",
                  "evaluated", "won", "sky", "outside", "faded", "fetch");
    out += line;
    for (const VolumeCounters& v : c.volumes) {
        if (v.culled) {
            std::snprintf(line, sizeof line, "  %-16s culled (outside the view: not drawn)\n",
                          v.name.c_str());
            out += line;
            continue;
        }
        const std::uint64_t probe = v.stateFetches + v.visibilityFetches + v.irradianceFetches +
                                    v.shMaskFetches + v.shCoefficientFetches;
        std::snprintf(line, sizeof line, "  %-16s %10llu %8llu %8llu %9llu %8llu %6.2f\n",
                      v.name.c_str(), (unsigned long long)v.evaluated, (unsigned long long)v.won,
                      (unsigned long long)v.skySkipped, (unsigned long long)v.outsideSkipped,
                      (unsigned long long)v.fadedOut,
                      v.evaluated ? double(probe) / double(v.evaluated) : 0.0);
        out += line;
    }
    out += "texture cache (probe textures; misses x line size per GI pixel):\n";
    std::snprintf(line, sizeof line, "  %-20s %-14s %-28s %9s %14s\n", "variant", "cache", "size",
                  "hit rate", "B missed/px");
    out += line;
    for (const CacheResult& res : r.results) {
        const bool mine = res.variant == r.profileVariant;
        std::snprintf(line, sizeof line, "  %-20s %-14s %-28s %8.2f%% %14.1f\n",
                      (res.variant + (mine ? " *" : "")).c_str(), res.cache.name.c_str(),
                      res.cache.describe().c_str(), 100.0 * res.probeHitRate(),
                      res.probeBytesMissedPerPixel(c.giPixels));
        out += line;
    }
    out += "  * the profile's variant (gi.probe_order, gi.loops; SH: gi.technique/gi.sh_leak)\n";
    return out;
}

} // namespace pb::costmodel
