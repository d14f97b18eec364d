#include "ShaderTargets.h"

#include "core/Error.h"
#include "core/Suggest.h"

namespace pb::shaders {
namespace {

// Model ids are the ones each 22.3.6 shim accepts (../shared/reference/mesa-drm-shim-notes.md,
// checked by running each). freedreno's FD_MESA_DEBUG=shaderdb makes it compile the first
// variant at link time, synchronously, and print its statistics; panfrost compiles its default
// variant at link time anyway and prints to the debug callback; v3d compiles at link time only
// with V3D_DEBUG=precompile; nouveau translates at link time and always reports.
ShaderTarget adreno(const std::string& model, const std::string& note = {}) {
    return {"adreno-" + model,
            "Adreno " + model,
            "freedreno",
            "libfreedreno_noop_drm_shim.so",
            {"FD_GPU_ID=" + model, "FD_MESA_DEBUG=shaderdb"},
            note};
}

ShaderTarget bifrost(const std::string& model, const std::string& id) {
    return {"mali-g" + model,
            "Mali-G" + model + " (Bifrost)",
            "panfrost",
            "libpanfrost_noop_drm_shim.so",
            {"PAN_GPU_ID=" + id, "BIFROST_MESA_DEBUG=shaderdb"},
            "cycles: the compiler's per-unit bound (arith 24 tuples, texture 2, varying 16, "
            "load/store 1 per cycle)"};
}

std::vector<ShaderTarget> buildTargets() {
    std::vector<ShaderTarget> t;
    t.push_back(adreno("330", "Adreno 3xx: no half registers, GLES 3.0"));
    t.push_back(adreno("530"));
    t.push_back(adreno("540"));
    t.push_back(adreno("618"));
    t.push_back(adreno("630"));
    t.push_back(adreno("660"));
    t.push_back(bifrost("31", "7093"));
    t.push_back(bifrost("52", "7212"));
    t.push_back(bifrost("72", "6221"));
    t.push_back(bifrost("76", "7211"));
    t.push_back({"mali-g57",
                 "Mali-G57 (Valhall)",
                 "panfrost",
                 "libpanfrost_noop_drm_shim.so",
                 {"PAN_GPU_ID=9093", "BIFROST_MESA_DEBUG=shaderdb"},
                 "cycles: the compiler's per-unit bound (fma and cvt 64, sfu 16, varying 16, "
                 "texture 4, load/store 1 per cycle)"});
    t.push_back({"mali-t860",
                 "Mali-T860 (Midgard)",
                 "panfrost",
                 "libpanfrost_noop_drm_shim.so",
                 {"PAN_GPU_ID=860", "MIDGARD_MESA_DEBUG=shaderdb"},
                 "Midgard: mediump often costs instructions here"});
    t.push_back({"videocore-vi",
                 "VideoCore VI, V3D 4.2 (Raspberry Pi 4)",
                 "v3d",
                 "libv3d_noop_drm_shim.so",
                 {"V3D_DEBUG=precompile"},
                 ""});
    t.push_back({"tegra-x1",
                 "Tegra X1, GM20B (Nintendo Switch class)",
                 "nouveau",
                 "libnouveau_noop_drm_shim.so",
                 {"NOUVEAU_CHIPSET=12b"},
                 "nouveau ignores mediump on Maxwell (the hardware has double-rate fp16; this "
                 "compiler does not use it): fp16 changes nothing here"});
    return t;
}

} // namespace

const std::vector<ShaderTarget>& shaderTargets() {
    static const std::vector<ShaderTarget> targets = buildTargets();
    return targets;
}

const ShaderTarget& findShaderTarget(const std::string& name) {
    std::vector<std::string> names;
    for (const ShaderTarget& t : shaderTargets()) {
        if (t.name == name) return t;
        names.push_back(t.name);
    }
    throw Error("unknown shader target '" + printable(name) + "'" + didYouMean(name, names) +
                " (probebench shaders --list-targets)");
}

std::vector<ShaderTarget> parseShaderTargets(const std::string& list) {
    if (list == "all") return shaderTargets();
    std::vector<ShaderTarget> out;
    size_t start = 0;
    while (start <= list.size()) {
        const size_t comma = list.find(',', start);
        const std::string name =
            list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (name.empty()) throw Error("--targets: an empty name in '" + printable(list) + "'");
        const ShaderTarget& t = findShaderTarget(name);
        bool seen = false;
        for (const ShaderTarget& o : out)
            seen = seen || o.name == t.name;
        if (!seen) out.push_back(t);
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

} // namespace pb::shaders
