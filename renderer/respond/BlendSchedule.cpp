#include "respond/BlendSchedule.h"

#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace pb::respond {

const char* scheduleName(Schedule s) {
    switch (s) {
    case Schedule::Hysteresis:
        return "hysteresis";
    case Schedule::Rtxgi:
        return "rtxgi";
    case Schedule::Hastened:
        return "hastened";
    }
    return "?";
}

std::vector<Schedule> parseSchedules(const std::string& list, const std::string& option) {
    std::vector<Schedule> out;
    std::stringstream in(list);
    std::string name;
    while (std::getline(in, name, ',')) {
        Schedule s;
        if (name == "hysteresis")
            s = Schedule::Hysteresis;
        else if (name == "rtxgi")
            s = Schedule::Rtxgi;
        else if (name == "hastened")
            s = Schedule::Hastened;
        else
            throw Error(option + ": unknown schedule '" + name + "' (hysteresis, rtxgi, hastened)");
        if (std::find(out.begin(), out.end(), s) != out.end())
            throw Error(option + ": schedule '" + name + "' given twice");
        out.push_back(s);
    }
    if (out.empty()) throw Error(option + ": no schedule given (hysteresis, rtxgi, hastened)");
    return out;
}

float hastenedWeight(int index, const ScheduleParams& p) {
    const float w = 1.0f / float(std::max(index, 1));
    return std::clamp(w, p.hastenedMin, p.hastenedMax);
}

int hastenedStart(float dist, float radius, const ScheduleParams& p) {
    if (!(radius > 0.0f)) return 1;
    const float t = std::clamp(dist / radius, 0.0f, 1.0f);
    return 1 + int(std::floor(t * float(p.hastenedMaxStart - 1) + 0.5f));
}

namespace {

// RTXGI's irradiance encoding (gamma 5), where its thresholds are defined.
float encode(float e) {
    return std::pow(std::max(e, 0.0f), 0.2f);
}

void blendRtxgi(const ScheduleParams& p, const float* freshLinear, float* storedLinear) {
    // RTXGI stores and blends the gamma-5 encoding; so does this, then decodes.
    float fresh[3], stored[3];
    for (int c = 0; c < 3; ++c) {
        fresh[c] = encode(freshLinear[c]);
        stored[c] = encode(storedLinear[c]);
    }
    float h = p.hysteresis;
    float maxComponent = 0.0f, lengthSq = 0.0f;
    for (int c = 0; c < 3; ++c) {
        const float d = stored[c] - fresh[c];
        maxComponent = std::max(maxComponent, std::fabs(d));
        lengthSq += d * d;
    }
    if (maxComponent > p.irradianceThreshold) h = std::max(0.0f, h - 0.75f);
    const bool limit = std::sqrt(lengthSq) > p.brightnessThreshold;
    for (int c = 0; c < 3; ++c) {
        float delta = fresh[c] - stored[c];
        if (limit) delta *= 0.25f;
        float step = (1.0f - h) * delta;
        // Darkening: at least 1/1024 of the encoding per update (never past the new value),
        // so a probe does not hang just above a dark target.
        if (delta < 0.0f) step = -std::min(std::max(p.darkeningStep, -step), -delta);
        const float e = stored[c] + step;
        storedLinear[c] = e * e * e * e * e;
    }
}

} // namespace

void blendTexels(Schedule s, const ScheduleParams& p, int sampleIndex, const float* fresh,
                 float* stored, int texels) {
    for (int t = 0; t < texels; ++t) {
        const float* f = fresh + 3 * t;
        float* o = stored + 3 * t;
        switch (s) {
        case Schedule::Hysteresis:
            for (int c = 0; c < 3; ++c)
                o[c] = p.hysteresis * o[c] + (1.0f - p.hysteresis) * f[c];
            break;
        case Schedule::Rtxgi:
            blendRtxgi(p, f, o);
            break;
        case Schedule::Hastened: {
            const float w = hastenedWeight(sampleIndex, p);
            for (int c = 0; c < 3; ++c)
                o[c] = (1.0f - w) * o[c] + w * f[c];
            break;
        }
        }
    }
}

double hysteresisResidual(const ScheduleParams& p, int n) {
    return std::pow(double(p.hysteresis), double(n));
}

} // namespace pb::respond
