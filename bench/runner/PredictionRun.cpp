#include "PredictionRun.h"

#include "CacheModelRun.h"
#include "bench/devicemodel/FrameDemand.h"
#include "bench/devicemodel/PassModel.h"
#include "bench/devicemodel/ShaderCost.h"
#include "bench/shaders/ShaderTargets.h"
#include "costmodel/CostModel.h"
#include "frame/FrameRenderer.h"
#include "frame/FrameSkips.h"
#include "gl/TextureFormat.h"
#include "passes/GBufferLayout.h"
#include "passes/ShadowPass.h"

#include <map>
#include <memory>
#include <regex>

namespace pb::bench {
namespace predrun {

namespace dm = devicemodel;

// The plan's ids carry the session size after "@" ("reference@512x288 +gi.loops"); the
// compilers ran the same plan at another size, so ids are compared without it.
std::string sizeFree(const std::string& id) {
    static const std::regex size("@[0-9]+x[0-9]+");
    return std::regex_replace(id, size, "");
}

const shaders::VariantStatistics* statsVariant(const shaders::TargetStatistics& t,
                                               const std::string& id) {
    const std::string want = sizeFree(id);
    for (const shaders::VariantStatistics& v : t.variants)
        if (sizeFree(v.id) == want) return &v;
    return nullptr;
}

const shaders::TargetStatistics* findTarget(const shaders::ShaderStatisticsRun& run,
                                            const std::string& name) {
    for (const shaders::TargetStatistics& t : run.targets)
        if (t.target == name) return &t;
    return nullptr;
}

dm::FrameFacts frameFacts(const scene::Scene& s) {
    dm::FrameFacts f;
    for (const render::GBufferChannel& c : render::kGBufferChannels)
        f.gbufferBytesPerPixel += int(gl::formatInfo(c.format).bytesPerTexel);
    f.gbufferBytesPerPixel += int(gl::formatInfo(render::kGBufferDepthFormat).bytesPerTexel);
    if (render::shadowSkipReason(s).empty()) {
        const int side = render::defaultFrameSettings(s).shadowMapSize;
        f.shadowMapSizes = {side, render::sceneShadowMapSize(side)};
    }
    f.meshes = int(s.instances.size());
    return f;
}

// The switches a GI-pass replay depends on; the rest (precision, order and loops - every
// order/loops variant is in one replay -, target format, upsample, guards) at the defaults.
profile::Profile replaySwitches(const profile::Profile& p) {
    profile::Profile r;
    r.gi.technique = p.gi.technique;
    r.gi.shLeak = p.gi.shLeak;
    r.gi.resolution = p.gi.resolution;
    r.gi.multiVolume = p.gi.multiVolume;
    r.gi.dynamic = p.gi.dynamic;
    r.gi.volumeLod = p.gi.volumeLod;
    return r;
}

class Replays {
public:
    Replays(const scene::Scene& s, const probes::ProbeSet& set, const scene::View& view,
            std::vector<costmodel::CacheConfig> caches, std::function<void(const std::string&)> progress)
        : scene_(s), set_(set), view_(view), caches_(std::move(caches)), progress_(std::move(progress)) {}

    const costmodel::CostReport& get(const profile::Profile& switches, int width, int height) {
        const profile::Profile key = replaySwitches(switches);
        const std::string k = std::to_string(width) + "x" + std::to_string(height) + key.valuesJson().dump();
        auto it = reports_.find(k);
        if (it != reports_.end()) return it->second;
        auto& tester = testers_[key.gi.volumeLod];
        if (!tester) tester = keptVolumesTester(scene_, set_, key.gi.volumeLod);
        if (progress_)
            progress_("device model: replaying the GI pass (" + std::to_string(reports_.size() + 1) +
                      ") " + std::to_string(width) + "x" + std::to_string(height));
        costmodel::CostModelOptions o;
        o.width = width;
        o.height = height;
        o.profile = key;
        o.caches = caches_;
        return reports_.emplace(k, costmodel::runCostModel(*tester, view_, o)).first->second;
    }

private:
    const scene::Scene& scene_;
    const probes::ProbeSet& set_;
    const scene::View& view_;
    std::vector<costmodel::CacheConfig> caches_;
    std::function<void(const std::string&)> progress_;
    std::map<std::string, std::unique_ptr<views::CoverageTester>> testers_;
    std::map<std::string, costmodel::CostReport> reports_;
};

bool fp16Program(const shaders::ProgramStatistics& p) {
    return (";" + p.defines + ";").find(";GI_PRECISION_FP16;") != std::string::npos;
}

struct TargetPair {
    const shaders::TargetStatistics* device = nullptr; // the stand-in compiler
    const shaders::TargetStatistics* ir3 = nullptr;    // texture instruction counts
    std::string driver;
};

PredictedVariant predictVariant(const dm::DeviceSpec& dev, const TargetPair& t,
                                const Variant& variant, int width, int height,
                                const dm::FrameFacts& facts, Replays& replays) {
    PredictedVariant out{variant.id, variant.label, roleName(variant.role), 0, NAN, {}, ""};
    const shaders::VariantStatistics* v = statsVariant(*t.device, variant.id);
    if (!v) {
        out.error = dev.compiler + " did not compile this variant";
        return out;
    }
    if (!v->notRun.empty()) {
        out.error = dev.compiler + " cannot run it: " + v->notRun;
        return out;
    }
    // The fused twin stands in for split loops' arithmetic (FrameDemand.h).
    const shaders::VariantStatistics* alu = v;
    if (variant.switches.gi.loops == profile::GiLoops::Split) {
        alu = statsVariant(*t.device, shaders::fusedTwinId(variant.id));
        if (!alu || !alu->notRun.empty()) {
            out.error = dev.compiler + " has no fused twin of this variant (compile with twins)";
            return out;
        }
    }
    const shaders::VariantStatistics* ir3 = t.ir3 ? statsVariant(*t.ir3, variant.id) : nullptr;
    dm::FrameDemandInputs in;
    in.width = width;
    in.height = height;
    in.switches = variant.switches;
    in.cost = &replays.get(variant.switches, width, height);
    in.l2Cache = dev.l2.name;
    in.facts = facts;
    in.passes = t.device->passes(*v);
    for (const std::string& pass : in.passes) {
        const shaders::ProgramStatistics* p =
            t.device->heaviestFragment(pass == "gi-apply" ? *alu : *v, pass);
        if (!p) continue;
        dm::PassProgram prog;
        // gi.precision makes the apply's probe weights and sums half precision; other passes
        // carry the define but not the arithmetic (FrameDemand.h).
        const bool fp16 = pass == "gi-apply" && fp16Program(*p);
        const dm::AluCost c = dm::aluCost(*p->stage("fragment"), t.driver, dev, fp16);
        prog.aluCyclesPerFragment = c.cyclesPerFragment;
        prog.aluBasis = c.basis;
        if (ir3)
            if (const shaders::ProgramStatistics* q = t.ir3->heaviestFragment(*ir3, pass))
                prog.textureInstructions = dm::textureInstructions(*q->stage("fragment"));
        in.programs[pass] = prog;
    }
    const dm::FramePrediction f = dm::predictFrame(dev, dm::frameDemand(in));
    out.ms = f.totalMs;
    for (const dm::PassPrediction& p : f.passes)
        out.passes.push_back({p.pass, p.bound, p.ms, NAN, p.toJson()});
    return out;
}

} // namespace predrun
using namespace predrun;

std::string predictionTargets(const std::vector<devicemodel::DeviceSpec>& devices) {
    std::vector<std::string> names;
    for (const auto& d : devices)
        if (std::find(names.begin(), names.end(), d.compiler) == names.end()) names.push_back(d.compiler);
    if (std::find(names.begin(), names.end(), "adreno-630") == names.end()) names.push_back("adreno-630");
    std::string out;
    for (const std::string& n : names)
        out += (out.empty() ? "" : ",") + n;
    return out;
}

std::vector<DevicePrediction> predictDevices(const BenchPlan& plan, const scene::Scene& scene,
                                             const probes::ProbeSet& set, const scene::View& view,
                                             const shaders::ShaderStatisticsRun& stats,
                                             const PredictionRequest& request) {
    std::vector<costmodel::CacheConfig> caches;
    for (const dm::DeviceSpec& d : request.devices)
        caches.push_back(d.l2);
    Replays replays(scene, set, view, caches, request.progress);
    const dm::FrameFacts facts = frameFacts(scene);
    std::vector<DevicePrediction> out;
    for (const dm::DeviceSpec& dev : request.devices) {
        DevicePrediction dp{dev.name, dev.label, dev.compiler, stats.mesaVersion, dev.toJson(), "", {}};
        TargetPair t;
        t.device = findTarget(stats, dev.compiler);
        t.ir3 = findTarget(stats, "adreno-630");
        if (t.ir3 && !t.ir3->error.empty()) t.ir3 = nullptr;
        if (!t.device || !t.device->error.empty()) {
            dp.error = "compiler " + dev.compiler + ": " + (t.device ? t.device->error : "not run");
            out.push_back(dp);
            continue;
        }
        t.driver = t.device->driver;
        for (const Session& s : plan.sessions) {
            const bool own = s.profile.modelDevice == dev.name;
            if (request.ownDevicesOnly && !own) continue;
            PredictedSession ps;
            ps.profile = s.profile.name;
            ps.width = s.width;
            ps.height = s.height;
            ps.ownDevice = own;
            ps.budgetMs = s.profile.frameBudgetMs;
            for (const Variant& v : s.variants)
                ps.variants.push_back(predictVariant(dev, t, v, s.width, s.height, facts, replays));
            if (own && request.budgetFrames) { // the budget's frame: the profile at its own output size
                ps.ownWidth = s.profile.width;
                ps.ownHeight = s.profile.height;
                const PredictedVariant& at =
                    s.width == s.profile.width && s.height == s.profile.height
                        ? ps.variants[0]
                        : predictVariant(dev, t, s.variants[0], s.profile.width, s.profile.height,
                                         facts, replays);
                if (at.error.empty()) ps.ownSizeMs = at.ms;
            }
            for (const PlannedDelta& d : s.deltas) {
                const PredictedVariant& off = ps.variants.at(size_t(d.off));
                const PredictedVariant& on = ps.variants.at(size_t(d.on));
                PredictedDelta x{deltaKindName(d.kind), d.switchKey, d.offValue, d.onValue,
                                 off.id, on.id, NAN, NAN};
                if (off.error.empty() && on.error.empty()) x.ms = on.ms - off.ms;
                ps.deltas.push_back(x);
            }
            dp.sessions.push_back(std::move(ps));
        }
        out.push_back(std::move(dp));
    }
    return out;
}

} // namespace pb::bench
