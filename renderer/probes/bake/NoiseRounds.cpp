#include "probes/bake/NoiseRounds.h"

#include "core/Luminance.h"
#include "probes/ProbeLayout.h"
#include "probes/ProbeSet.h"

#include <algorithm>
#include <cmath>

namespace pb::probes {

void NoiseRounds::startScenario(std::size_t probes) {
    carriedVar_.assign(probes, 0.0);
    carriedMean_.assign(probes, 0.0);
    traced_.assign(probes, 0);
    floor_ = 0.0f;
}

void NoiseRounds::startSlab(std::size_t first, std::size_t count) {
    first_ = first;
    firstVariance_.assign(count * kIrradianceInteriorTexels, 0.0f);
    sumY_.assign(count * kIrradianceInteriorTexels, 0.0);
    sumY2_.assign(count * kIrradianceInteriorTexels, 0.0);
    meanY_.assign(count, 0.0f);
    rounds_.assign(count, 0);
}

void NoiseRounds::firstRound(std::size_t i, const RadianceSlab& slab, const ProbeConvolution& conv,
                             const float* rgb) {
    slab.texelVariance(i, conv, &firstVariance_[i * kIrradianceInteriorTexels]);
    float y = 0.0f;
    for (int t = 0; t < kIrradianceInteriorTexels; ++t) {
        const float yt = luminance(glm::vec3(rgb[3 * t], rgb[3 * t + 1], rgb[3 * t + 2]));
        sumY_[i * kIrradianceInteriorTexels + size_t(t)] = yt;
        sumY2_[i * kIrradianceInteriorTexels + size_t(t)] = double(yt) * yt;
        y += yt / kIrradianceInteriorTexels;
    }
    meanY_[i] = y;
    rounds_[i] = 1;
}

float NoiseRounds::passVariance(std::size_t i) const {
    if (rounds_[i] == 0) return 0.0f;
    const double k = rounds_[i];
    double v = 0.0;
    for (int t = 0; t < kIrradianceInteriorTexels; ++t) {
        const std::size_t at = i * kIrradianceInteriorTexels + size_t(t);
        if (rounds_[i] == 1) {
            v += double(firstVariance_[at]) / kIrradianceInteriorTexels;
        } else {
            const double s2 = std::max(0.0, (sumY2_[at] - sumY_[at] * sumY_[at] / k) / (k - 1.0));
            v += s2 / k / kIrradianceInteriorTexels;
        }
    }
    return float(v);
}

float NoiseRounds::finalNoise(std::size_t flat, float passVar, float passMean) const {
    const double mean = std::max(carriedMean_[flat] + double(passMean), double(floor_));
    if (!(mean > 0.0)) return 0.0f;
    return float(std::sqrt(carriedVar_[flat] + double(passVar)) / mean);
}

std::vector<std::size_t> NoiseRounds::aboveTarget(std::size_t count) const {
    std::vector<std::size_t> out;
    if (!active()) return out;
    for (std::size_t i = 0; i < count; ++i)
        if (rounds_[i] > 0 && rounds_[i] < kMaxNoiseRounds &&
            finalNoise(first_ + i, passVariance(i), meanY_[i]) > target_)
            out.push_back(i);
    return out;
}

int NoiseRounds::addRound(std::size_t i, const float* rgb) {
    for (int t = 0; t < kIrradianceInteriorTexels; ++t) {
        const double yt = luminance(glm::vec3(rgb[3 * t], rgb[3 * t + 1], rgb[3 * t + 2]));
        sumY_[i * kIrradianceInteriorTexels + size_t(t)] += yt;
        sumY2_[i * kIrradianceInteriorTexels + size_t(t)] += yt * yt;
    }
    return ++rounds_[i];
}
void NoiseRounds::setMean(std::size_t i, const float* tile, int pitch) {
    float y = 0.0f;
    for (int ty = 0; ty < kIrradianceInterior; ++ty)
        for (int tx = 0; tx < kIrradianceInterior; ++tx) {
            const float* p = tile + (size_t(ty + 1) * size_t(pitch) + size_t(tx + 1)) * 4;
            y += luminance(glm::vec3(p[0], p[1], p[2])) / kIrradianceInteriorTexels;
        }
    meanY_[i] = y;
}

void NoiseRounds::finishSlab(std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        if (rounds_[i] == 0) continue;
        const std::size_t flat = first_ + i;
        carriedVar_[flat] += double(passVariance(i));
        carriedMean_[flat] += double(meanY_[i]);
        traced_[flat] = 1;
        ++probePasses_;
        if (rounds_[i] > 1) ++multiRound_;
    }
}

void NoiseRounds::setFloorFromCarried() {
    double sum = 0.0;
    std::size_t n = 0;
    for (std::size_t p = 0; p < traced_.size(); ++p)
        if (traced_[p]) {
            sum += carriedMean_[p];
            ++n;
        }
    floor_ = n > 0 ? float(double(kNoiseFloorShare) * sum / double(n)) : 0.0f;
}

void NoiseRounds::finishScenario() {
    for (std::size_t p = 0; p < traced_.size(); ++p) {
        if (!traced_[p]) continue;
        const float n = finalNoise(p, 0.0f, 0.0f);
        finals_.push_back(n);
        if (active() && n > target_) {
            ++aboveAfterAll_;
            aboveFlat_.push_back(p);
        }
    }
}

void NoiseRounds::summarise(BakeStats& st) const {
    st.tracedProbes = finals_.size();
    st.tracedProbePasses = probePasses_;
    st.noisyProbePasses = multiRound_;
    st.probesAboveTarget = aboveAfterAll_;
    st.extraRoundRays = extraRays;
    if (finals_.empty()) return;
    double sum = 0.0;
    for (float n : finals_)
        sum += n;
    st.noiseMean = sum / double(finals_.size());
    std::vector<float> sorted = finals_;
    const std::size_t k = std::min(sorted.size() - 1, std::size_t(0.95 * double(sorted.size())));
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(k), sorted.end());
    st.noiseP95 = sorted[k];
}

} // namespace pb::probes
