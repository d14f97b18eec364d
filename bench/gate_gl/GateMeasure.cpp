#include "GateMeasure.h"

#include "GlCallCounter.h"
#include "bench/runner/AccuracyCapture.h"
#include "core/Error.h"
#include "costmodel/CachePresets.h"
#include "costmodel/CostModel.h"
#include "passes/GiApplyPass.h"
#include "profile/GiVolumeLod.h"
#include <glad/gl.h>

namespace pb::gate {

GateRenderer::GateRenderer(const GateInputs& in, const profile::PlatformProfile& p) : profile_(p) {
    render::GiOptions gi{in.probes, 0, p.switches};
    renderer_ = std::make_unique<render::FrameRenderer>(*in.scene, in.settings, gi);
    view_ = render::makeRenderView(in.view, in.scene->worldBounds(), in.width, in.height);
    for (int i = 0; i < in.warmup; ++i)
        frame();
    glFinish();
}

void GateRenderer::frame(render::FrameTimer* timer) {
    renderer_->render(view_, timer);
}

const views::CoverageTester& ModelScenes::forVolumeLod(const std::string& volumeLod) {
    auto& t = testers_[volumeLod];
    if (!t) {
        std::vector<bool> kept(in_.probes->volumes.size(), false);
        for (int v : profile::selectVolumes(*in_.probes, profile::parseVolumeLod(volumeLod)))
            kept[size_t(v)] = true;
        t = std::make_unique<views::CoverageTester>(*in_.scene, *in_.probes, kept);
    }
    return *t;
}

namespace {

void add(Counters& c, const std::string& key, std::int64_t v) {
    c.emplace_back(key, v);
}

void glCounters(const GlCallCounter& counter, Counters& c) {
    for (const auto& [section, n] : counter.sections()) {
        const std::string p = "gl." + section + ".";
        add(c, p + "draws", n.draws);
        add(c, p + "programs", n.programs);
        add(c, p + "tex_binds", n.texBinds);
        add(c, p + "tex_unbinds", n.texUnbinds);
        add(c, p + "clears", n.clears);
        add(c, p + "fbo_binds", n.fboBinds);
    }
}

void modelCounters(const costmodel::CostReport& r, Counters& c) {
    const costmodel::GiPassCounters& m = r.counters;
    std::uint64_t lookups = 0;
    for (const costmodel::VolumeCounters& v : m.volumes) {
        add(c, "model.gi.evaluated." + v.name, std::int64_t(v.evaluated));
        lookups += v.evaluated;
    }
    std::uint64_t state = 0, vis = 0, irr = 0;
    for (const costmodel::VolumeCounters& v : m.volumes) {
        state += v.stateFetches;
        vis += v.visibilityFetches;
        irr += v.irradianceFetches;
    }
    add(c, "model.gi_pixels", std::int64_t(m.giPixels));
    add(c, "model.lookups", std::int64_t(lookups));
    add(c, "model.fetches.gbuffer", std::int64_t(m.gbufferFetches));
    add(c, "model.fetches.state", std::int64_t(state));
    add(c, "model.fetches.visibility", std::int64_t(vis));
    add(c, "model.fetches.irradiance", std::int64_t(irr));
    add(c, "model.fetches_per_lookup_max", m.maxFetchesPerLookup);
    add(c, "model.probe_bytes_read", std::int64_t(m.probeFootprintBytes));
    add(c, "model.rt_bytes_written", std::int64_t(m.renderTargetBytesWritten));
    add(c, "model.rt_bytes_cleared", std::int64_t(m.clearBytes));
    add(c, "model.gpu_probe_bytes", std::int64_t(m.gpuProbeBytes));
    if (!r.results.empty()) {
        const costmodel::CacheConfig& cache = r.results.front().cache;
        add(c, "cache.preset.size_bytes", std::int64_t(cache.sizeBytes));
        add(c, "cache.preset.line_bytes", cache.lineBytes);
        add(c, "cache.preset.ways", cache.ways);
    }
    for (const costmodel::CacheResult& res : r.results) {
        add(c, "cache." + res.variant + ".lines", std::int64_t(res.probeLines));
        add(c, "cache." + res.variant + ".hits", std::int64_t(res.probeHits));
    }
}

} // namespace

void measureCounters(GateRenderer& r, const GateInputs& in, ModelScenes& scenes,
                     ProfileRecord& out) {
    out.name = r.profile().name;
    {
        GlCallCounter counter;
        r.frame(&counter);
        glCounters(counter, out.counters);
    }
    render::GiApplyPass* gi = r.renderer().giApplyPass();
    if (!gi) throw Error("gate: profile '" + out.name + "' rendered no GI pass");
    add(out.counters, "memory.gpu_probe_bytes", std::int64_t(r.renderer().gpuProbes()->bytes()));
    add(out.counters, "memory.gi_target_bytes", std::int64_t(gi->targetBytes()));

    // The counted frame and the last one come right after a camera cut: gi.upsample=temporal
    // then samples each footprint's centre pixel - the pixel the cost model evaluates - and the
    // accuracy is read on the frame the bench reads (bench/runner/SessionRunner.cpp).
    r.renderer().resetGiHistory();
    gi->setCountPixels(true);
    r.frame();
    gi->setCountPixels(false);
    const render::GiPassStats stats = gi->stats();
    r.renderer().resetGiHistory();
    r.frame(); // a plain last frame: what the accuracy reads
    std::vector<int> culled;
    for (const render::GiVolumeStats& v : stats.volumes) {
        add(out.glPixels, v.name, v.culled ? 0 : v.evaluatedPixels);
        if (stats.invocationsCounted)
            add(out.glInvocations, v.name, v.culled ? 0 : v.applyInvocations);
        if (v.culled) culled.push_back(v.fileIndex);
    }

    costmodel::CostModelOptions o;
    o.width = in.width;
    o.height = in.height;
    o.profile = r.profile().switches;
    o.caches = {costmodel::cachePresetFor(r.profile().cachePreset)};
    o.culledVolumes = culled;
    const costmodel::CostReport report =
        costmodel::runCostModel(scenes.forVolumeLod(r.profile().switches.gi.volumeLod), in.view, o);
    modelCounters(report, out.counters);
}

AccuracyValues measureAccuracy(GateRenderer& profile, GateRenderer& reference,
                               const GateInputs& in) {
    bench::SessionResult s;
    bench::Variant pv, rv;
    pv.id = profile.profile().name;
    pv.role = bench::VariantRole::Profile;
    pv.switches = profile.profile().switches;
    rv.id = reference.profile().name;
    rv.role = bench::VariantRole::Reference;
    rv.switches = reference.profile().switches;
    s.session.variants = {pv, rv};
    s.session.referenceVariant = 1;
    s.session.width = in.width;
    s.session.height = in.height;
    s.variants.resize(2);
    s.variants[0].variant = pv;
    s.variants[1].variant = rv;
    bench::AccuracyInputs ai{in.scene, in.probes, in.view, in.settings,
                             in.width, in.height, 1,       67.0};
    bench::captureAccuracy(s, {&profile.renderer(), &reference.renderer()}, ai, nullptr);
    const bench::AccuracyResult& a = s.variants[0].accuracy;
    if (!a.measured) throw Error("gate: the accuracy of '" + pv.id + "' could not be measured");
    return {true, a.flipMean, a.psnr, a.relativeMseGi};
}

} // namespace pb::gate
