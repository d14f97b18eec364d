#include "probes/sh/ShSampler.h"

#include "core/Error.h"

#include <cmath>
#include <limits>

namespace pb::probes {

std::string noShMessage(const std::string& source) {
    return source + ": the probe file has no SH probes (baked before probe file version 6); " +
           "re-bake it for gi.technique=sh_l1|sh_l2";
}

bool nudgeToValid(glm::vec3& f, std::uint8_t validMask) {
    if (validMask == 0) return false;
    if (validMask == 0xFF) return true;
    glm::vec3 best = f;
    float bestMove = std::numeric_limits<float>::infinity();
    for (int option = 0; option < 27; ++option) {
        glm::vec3 g;
        int o = option;
        for (int a = 0; a < 3; ++a, o /= 3)
            g[a] = o % 3 == 0 ? f[a] : float(o % 3 - 1);
        bool clean = true;
        for (int c = 0; c < 8 && clean; ++c) {
            if (validMask & (1u << c)) continue;
            float w = 1.0f;
            for (int a = 0; a < 3; ++a)
                w *= (c >> a) & 1 ? g[a] : 1.0f - g[a];
            clean = w == 0.0f;
        }
        const float move = std::abs(g.x - f.x) + std::abs(g.y - f.y) + std::abs(g.z - f.z);
        if (clean && move < bestMove) {
            bestMove = move;
            best = g;
        }
    }
    f = best;
    return true;
}

ShSampler::ShSampler(const ProbeSet& set, int scenario, const std::string& source) {
    if (!set.hasSh()) throw Error(noShMessage(source));
    if (scenario < 0 || scenario >= int(set.sh.size()))
        throw Error(source + ": no scenario #" + std::to_string(scenario));
    std::vector<int> parents = validateVolumes(set.volumes, source);
    for (std::size_t v = 0; v < set.volumes.size(); ++v) {
        const ProbeVolume& vol = set.volumes[v];
        Frame f;
        f.volume = &vol;
        f.lookup = shLookupVolume(vol, set.states[v], set.sh[size_t(scenario)][v],
                                  set.settings.backfaceThreshold);
        for (int p = 0; p < vol.probeCount(); ++p)
            f.apv.push_back(encodeApv(&f.lookup.sh[size_t(p) * kShL2Coefficients]));
        f.toLocal = glm::transpose(vol.localToWorldRotation());
        const glm::vec3 cell = vol.cellSize();
        for (int a = 0; a < 3; ++a)
            f.invCell[a] = vol.counts[a] > 1 ? 1.0f / cell[a] : 0.0f;
        f.fadeWidth = parents[v] < 0 ? kEdgeFadeCells * cell : glm::vec3(0.0f);
        f.minCell = vol.minCellSize();
        f.boxVolume = vol.boxVolume();
        frames_.push_back(f);
    }
}

int ShSampler::selectVolume(const glm::vec3& pos) const {
    int best = -1;
    float bestVolume = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < frames_.size(); ++i) {
        const Frame& f = frames_[i];
        const glm::vec3 p = f.toLocal * (pos - f.volume->center);
        bool in = true;
        for (int a = 0; a < 3; ++a)
            in = in && std::abs(p[a]) <= f.volume->halfExtents[a] + f.fadeWidth[a];
        if (in && f.boxVolume < bestVolume) {
            best = int(i);
            bestVolume = f.boxVolume;
        }
    }
    return best;
}

namespace {
glm::vec3 unitOr(const glm::vec3& v, const glm::vec3& fallback) {
    const float l = glm::length(v);
    return l > 1e-12f && std::isfinite(l) ? v / l : fallback;
}
} // namespace

IrradianceSample ShSampler::sample(const glm::vec3& pos, const glm::vec3& normal,
                                   const glm::vec3& view, const ShSampleOptions& opt) const {
    const int vi = selectVolume(pos);
    return vi < 0 ? IrradianceSample{} : sampleVolume(vi, pos, normal, view, opt);
}

IrradianceSample ShSampler::sampleVolume(int vi, const glm::vec3& pos, const glm::vec3& normal,
                                         const glm::vec3& view, const ShSampleOptions& opt,
                                         ShTrace* trace) const {
    IrradianceSample out;
    if (trace) *trace = ShTrace{};
    const Frame& f = frames_.at(size_t(vi));
    const ProbeVolume& vol = *f.volume;
    out.volume = vi;
    // 1. Local frame and edge fade.
    const glm::vec3 p = f.toLocal * (pos - vol.center);
    const glm::vec3 n = unitOr(f.toLocal * normal, glm::vec3(0, 1, 0));
    const glm::vec3 vdir = unitOr(f.toLocal * view, n);
    float fade = 1.0f;
    for (int a = 0; a < 3; ++a) {
        const float outside = std::abs(p[a]) - vol.halfExtents[a];
        if (outside > 0.0f)
            fade *= f.fadeWidth[a] > 0.0f
                        ? std::min(std::max(1.0f - outside / f.fadeWidth[a], 0.0f), 1.0f)
                        : 0.0f;
    }
    if (!opt.edgeFade) fade = fade > 0.0f ? 1.0f : 0.0f;
    if (fade <= 0.0f) return out;
    // 2-3. Biased point, lattice base and fractions.
    const glm::vec3 b =
        p + (kBiasNormalWeight * n + kBiasViewWeight * vdir) * (kBiasScale * f.minCell);
    glm::ivec3 base(0);
    glm::vec3 frac(0.0f);
    for (int a = 0; a < 3; ++a) {
        if (vol.counts[a] <= 1) continue;
        const float g = std::min(std::max((b[a] + vol.halfExtents[a]) * f.invCell[a], 0.0f),
                                 float(vol.counts[a] - 1));
        base[a] = std::min(int(std::floor(g)), vol.counts[a] - 2);
        frac[a] = g - float(base[a]);
    }
    auto corner = [&](int c) {
        return glm::min(base + glm::ivec3(c & 1, (c >> 1) & 1, (c >> 2) & 1), vol.counts - 1);
    };
    auto valid = [&](int c) {
        return shProbeValid(f.lookup.states[size_t(vol.probeIndex(corner(c)))]);
    };
    // 4. Leak mode.
    if (opt.leak != ShLeak::None) {
        std::uint8_t mask = 0;
        for (int c = 0; c < 8; ++c)
            if (valid(c)) mask = std::uint8_t(mask | (1u << c));
        if (trace) {
            trace->maskRead = true;
            trace->cell = base;
        }
        if (mask == 0) return opt.leak == ShLeak::Weight ? IrradianceSample{} : out;
        if (opt.leak == ShLeak::ValidityMask) nudgeToValid(frac, mask);
    }
    if (trace) {
        trace->coefficientsRead = true;
        trace->lattice = glm::vec3(base) + frac;
    }
    glm::vec3 sum[kShL2Coefficients] = {};
    ShApvTexels apv;
    float sumW = 0.0f;
    for (int c = 0; c < 8; ++c) {
        float w = 1.0f;
        for (int a = 0; a < 3; ++a)
            w *= (c >> a) & 1 ? frac[a] : 1.0f - frac[a];
        if (opt.leak == ShLeak::Weight && !valid(c)) w = 0.0f;
        if (w == 0.0f) continue;
        const glm::vec3* src =
            f.lookup.sh.data() + std::size_t(vol.probeIndex(corner(c))) * kShL2Coefficients;
        for (int k = opt.apv ? kShL1Coefficients : 0; k < opt.coefficients; ++k)
            sum[k] += src[k] * w;
        if (opt.apv) {
            const ShApvTexels& t = f.apv[size_t(vol.probeIndex(corner(c)))];
            apv.t0 += t.t0 * w;
            apv.t1 += t.t1 * w;
            apv.t2 += t.t2 * w;
        }
        sumW += w;
        ++out.probes;
    }
    if (opt.leak == ShLeak::Weight) {
        if (!(sumW > 0.0f)) return {};
        for (int k = 0; k < opt.coefficients; ++k)
            sum[k] /= sumW;
        apv.t0 /= sumW;
        apv.t1 /= sumW;
        apv.t2 /= sumW;
    }
    if (opt.apv) decodeApv(apv, sum);
    // 5. Irradiance, faded.
    out.irradiance = shIrradiance(sum, n, opt.coefficients) * fade;
    out.weight = fade;
    return out;
}

} // namespace pb::probes
