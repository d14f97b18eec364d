#pragma once
// How one probe update blends freshly traced irradiance into the stored texels (issue 20).
// Three schedules, as published (../shared/reference/gi-techniques-anchors.md, "Responsive
// updates"):
//   hysteresis  stored = h * stored + (1 - h) * new, h = 0.97 (RTXGI-DDGI's default). After n
//               updates of a constant input a step has decayed to h^n: ~98 updates to 5%.
//   rtxgi       the same hysteresis plus RTXGI's two rules, per texel: when the largest
//               component of (previous - new) exceeds the irradiance threshold 0.25, h drops by
//               0.75 (h = max(0, h - 0.75)); when the change is longer than the brightness
//               threshold 0.10 it is limited to 0.25 x the change; a darkening step is at least
//               1/1024. RTXGI stores and blends its gamma-5 irradiance encoding, so this
//               schedule does too: thresholds, blend and darkening step act on E^(1/5) (E in
//               scene units), and the result is decoded (a blend of encodings is not the
//               encoding of the blend: the published rule's own bias towards dark).
//   hastened    EdenSpark: sample i is blended with weight 1/i floored at wMin = 1/32 (the
//               running mean, then ~hysteresis 0.969). A change puts a probe in the hastened
//               state: its sample index restarts at a value set by its distance to the change
//               (1 at the change: weight wMax = 1, the next sample replaces the old value; up
//               to kHastenedMaxStart at the edge of the radius), so the weights descend from
//               the maximum to the minimum over the next samples.
#include <string>
#include <vector>

namespace pb::respond {

enum class Schedule { Hysteresis, Rtxgi, Hastened };

struct ScheduleParams {
    float hysteresis = 0.97f;
    float irradianceThreshold = 0.25f;
    float brightnessThreshold = 0.10f;
    float darkeningStep = 1.0f / 1024.0f;
    float hastenedMax = 1.0f;         // weight of the first hastened sample at the change
    float hastenedMin = 1.0f / 32.0f; // EdenSpark's floor
    int hastenedMaxStart = 8;         // start index at the edge of the change's radius
};

const char* scheduleName(Schedule s);
// "hysteresis,rtxgi,hastened" -> schedules; throws pb::Error naming `option` otherwise.
std::vector<Schedule> parseSchedules(const std::string& list, const std::string& option);

// EdenSpark's weight of the probe's sample number `index` (1-based): 1/index clamped to
// [hastenedMin, hastenedMax].
float hastenedWeight(int index, const ScheduleParams& p);
// The sample index a probe at distance `dist` from the change restarts at: 1 at the change,
// growing linearly to hastenedMaxStart at `radius` (a global change: 1 everywhere).
int hastenedStart(float dist, float radius, const ScheduleParams& p);

// Blends `texels` RGB triples of `fresh` into `stored` (in place). `sampleIndex` is the
// hastened schedule's index of this sample (ignored by the others).
void blendTexels(Schedule s, const ScheduleParams& p, int sampleIndex, const float* freshRgb,
                 float* storedRgb, int texels);

// The hysteresis schedule's remaining fraction of a step after n updates of a constant input.
double hysteresisResidual(const ScheduleParams& p, int n);

} // namespace pb::respond
