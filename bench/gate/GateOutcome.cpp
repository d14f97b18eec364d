#include "GateOutcome.h"

#include "GateEnvironment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace pb::gate {

namespace {

std::string num(double v, const char* fmt) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

// Display groups: "gl.shadow.draws" -> "gl.shadow" with the field "draws"; names with two
// parts ("model.gi_pixels") stand alone.
std::string groupOf(const std::string& key) {
    if (std::count(key.begin(), key.end(), '.') < 2) return key;
    return key.substr(0, key.rfind('.'));
}

struct Group {
    std::string name;
    std::vector<std::string> fields;
    std::map<std::string, std::int64_t> base, now;
    bool inBase = false, inNow = false;
};

std::vector<Group> groups(const Counters& base, const Counters& now) {
    std::vector<Group> out;
    auto find = [&](const std::string& g) -> Group& {
        for (Group& x : out)
            if (x.name == g) return x;
        out.push_back({g, {}, {}, {}, false, false});
        return out.back();
    };
    auto field = [](const std::string& key, const std::string& g) {
        return key == g ? std::string() : key.substr(g.size() + 1);
    };
    for (const auto& [k, v] : now) {
        Group& g = find(groupOf(k));
        const std::string f = field(k, g.name);
        g.fields.push_back(f);
        g.now[f] = v;
        g.inNow = true;
    }
    for (const auto& [k, v] : base) {
        Group& g = find(groupOf(k));
        const std::string f = field(k, g.name);
        if (std::find(g.fields.begin(), g.fields.end(), f) == g.fields.end()) g.fields.push_back(f);
        g.base[f] = v;
        g.inBase = true;
    }
    return out;
}

std::int64_t valueOr(const Counters& c, const std::string& key, std::int64_t fallback) {
    for (const auto& [k, v] : c)
        if (k == key) return v;
    return fallback;
}

// "cache.xyz/fused" {lines, hits}: hit rate and bytes missed per GI pixel.
std::string cacheText(const std::map<std::string, std::int64_t>& f, const Counters& all) {
    auto it = f.find("lines"), hit = f.find("hits");
    if (it == f.end() || hit == f.end()) return "?";
    const double lines = double(it->second), hits = double(hit->second);
    const double lineBytes = double(valueOr(all, "cache.preset.line_bytes", 0));
    const double pixels = double(valueOr(all, "model.gi_pixels", 0));
    return num(lines > 0 ? 100.0 * hits / lines : 0.0, "%.3f%% hit, ") +
           num(pixels > 0 ? (lines - hits) * lineBytes / pixels : 0.0, "%.2f B/px missed");
}

std::string groupText(const Group& g, const std::map<std::string, std::int64_t>& values,
                      const Counters& all) {
    if (g.name.rfind("cache.", 0) == 0 && g.name != "cache.preset") return cacheText(values, all);
    std::string s;
    for (const std::string& f : g.fields) {
        auto it = values.find(f);
        if (!s.empty()) s += '/';
        s += it == values.end() ? std::string("-") : std::to_string(it->second);
    }
    return s;
}

std::string groupName(const Group& g) {
    if (g.fields.size() == 1 && g.fields[0].empty()) return g.name;
    if (g.name.rfind("gl.", 0) == 0) return g.name; // the table's legend names the fields
    if (g.name.rfind("cache.", 0) == 0 && g.name != "cache.preset") return g.name;
    std::string s = g.name + " (";
    for (size_t i = 0; i < g.fields.size(); ++i)
        s += (i ? "/" : "") + g.fields[i];
    return s + ")";
}

bool isCacheReplay(const Group& g) {
    return g.name.rfind("cache.", 0) == 0 && g.name != "cache.preset";
}

// Every field of a cache-replay group within kOtherMachineCacheTolerance of the baseline's.
bool withinOtherMachineTolerance(const Group& g) {
    for (const std::string& f : g.fields) {
        if (!g.base.count(f) || !g.now.count(f)) return false;
        const double b = double(g.base.at(f)), n = double(g.now.at(f));
        if (std::abs(n - b) > kOtherMachineCacheTolerance * std::max(std::abs(b), 1.0))
            return false;
    }
    return true;
}

// Every counter is exact: they are measured with the committed probe file, whatever CPU runs
// the gate (GateEnvironment.h) - except, on another machine (`otherMachine`), the cache
// replay's lines and hits, which pass within kOtherMachineCacheTolerance with a note.
void compareCounters(const ProfileRecord* base, const ProfileRecord& now, bool otherMachine,
                     GateOutcome& out) {
    static const Counters none;
    const Counters& b = base ? base->counters : none;
    for (const Group& g : groups(b, now.counters)) {
        GateRow row{now.name,
                    "counters",
                    groupName(g),
                    g.inBase ? groupText(g, g.base, b) : "-",
                    g.inNow ? groupText(g, g.now, now.counters) : "-",
                    RowStatus::Ok,
                    ""};
        if (!g.inBase)
            row.status = RowStatus::New;
        else if (!g.inNow)
            row.status = RowStatus::Missing;
        else if (g.base != g.now) {
            for (const std::string& f : g.fields) {
                const bool both = g.base.count(f) && g.now.count(f);
                if (both && g.base.at(f) == g.now.at(f)) continue;
                if (both)
                    row.note += (row.note.empty() ? "" : ", ") + (f.empty() ? g.name : f) + " " +
                                (g.now.at(f) > g.base.at(f) ? "+" : "") +
                                std::to_string(g.now.at(f) - g.base.at(f));
            }
            row.status = RowStatus::Changed;
            if (otherMachine && isCacheReplay(g) && withinOtherMachineTolerance(g)) {
                row.status = RowStatus::Ok;
                row.note +=
                    num(100.0 * kOtherMachineCacheTolerance, " (within %.2g%% on another machine)");
                const std::string note =
                    "environment: another CPU or Embree ISA than the baseline's: cache.* lines "
                    "and hits pass within " +
                    num(100.0 * kOtherMachineCacheTolerance, "%.2g%%") +
                    " (texel footprints on 64-byte line edges follow the last bits of CPU "
                    "arithmetic); every other counter stays exact";
                if (std::find(out.notes.begin(), out.notes.end(), note) == out.notes.end())
                    out.notes.push_back(note);
            }
        }
        if (row.note.empty() && g.name == "model.fetches" && g.inNow) {
            // The "texture fetches per pixel": all fetches over the GI pixels.
            std::int64_t sum = 0;
            for (const auto& [f, v] : g.now)
                sum += v;
            const std::int64_t pixels = valueOr(now.counters, "model.gi_pixels", 0);
            if (pixels > 0) row.note = num(double(sum) / double(pixels), "%.2f per GI pixel");
        }
        out.rows.push_back(row);
    }
}

std::string psnrText(double db) {
    return std::isfinite(db) ? num(db, "%.2f dB") : "inf";
}

void compareAccuracy(const ProfileRecord* base, const ProfileRecord& now,
                     const AccuracyTolerance& tol, GateOutcome& out) {
    if (!now.accuracy.measured) return; // the reference itself
    const AccuracyValues* b = base && base->accuracy.measured ? &base->accuracy : nullptr;
    const AccuracyValues& n = now.accuracy;
    auto row = [&](const std::string& name, const std::string& bt, const std::string& nt,
                   RowStatus s, const std::string& note) {
        out.rows.push_back(
            {now.name, "accuracy", name, b ? bt : "-", nt, b ? s : RowStatus::New, note});
    };
    // FLIP mean: lower is better.
    {
        const double allowed = b ? std::max(tol.flipAbs, tol.flipRel * b->flipMean) : 0;
        RowStatus s = RowStatus::Ok;
        if (b && n.flipMean > b->flipMean + allowed) s = RowStatus::Worse;
        if (b && n.flipMean < b->flipMean - allowed) s = RowStatus::Better;
        row("FLIP mean vs reference", b ? num(b->flipMean, "%.5f") : "", num(n.flipMean, "%.5f"), s,
            b ? "tolerance +" + num(allowed, "%.2g") : "");
    }
    // PSNR: higher is better; inf = identical to the reference.
    {
        RowStatus s = RowStatus::Ok;
        if (b) {
            if (std::isinf(b->psnr) && !std::isinf(n.psnr))
                s = RowStatus::Worse;
            else if (!std::isinf(b->psnr) && std::isinf(n.psnr))
                s = RowStatus::Better;
            else if (!std::isinf(b->psnr) && n.psnr < b->psnr - tol.psnrDb)
                s = RowStatus::Worse;
            else if (!std::isinf(b->psnr) && n.psnr > b->psnr + tol.psnrDb)
                s = RowStatus::Better;
        }
        row("PSNR vs reference", b ? psnrText(b->psnr) : "", psnrText(n.psnr), s,
            b ? "tolerance -" + num(tol.psnrDb, "%.2g") + " dB" : "");
    }
    // Relative MSE of the GI irradiance: lower is better.
    {
        const double allowed = b ? tol.relMseAbs + tol.relMseRel * b->relMseGi : 0;
        RowStatus s = RowStatus::Ok;
        if (b && n.relMseGi > b->relMseGi + allowed) s = RowStatus::Worse;
        if (b && n.relMseGi < b->relMseGi - allowed) s = RowStatus::Better;
        row("rel. MSE of the GI", b ? num(b->relMseGi, "%.4g") : "", num(n.relMseGi, "%.4g"), s,
            b ? "tolerance +" + num(allowed, "%.2g") : "");
    }
}

// The GL pass's evaluated pixels per volume against the model's (model.gi.evaluated.<name>):
// they count the same lookups from two sides (GPU raster + depth reconstruction vs CPU rays),
// so a surface pixel right on a volume's boundary may fall either way; more than that means
// the model no longer describes the pass.
void compareModelWithGl(const ProfileRecord& now, GateOutcome& out) {
    for (const auto& [volume, gl] : now.glPixels) {
        const std::int64_t* model = now.counter("model.gi.evaluated." + volume);
        if (!model) continue;
        const std::int64_t diff = gl - *model;
        const std::int64_t allowed = std::max<std::int64_t>(4, *model / 1000); // 0.1%
        out.rows.push_back(
            {now.name, "model-vs-gl", "evaluated px, " + volume, "model " + std::to_string(*model),
             "GL " + std::to_string(gl),
             std::llabs(diff) <= allowed ? RowStatus::Ok : RowStatus::Disagree,
             "difference " + std::to_string(diff) + ", allowed +-" + std::to_string(allowed)});
    }
}

// What the device shaded against what it evaluated, per volume (informational: naive shades
// every volume full-screen by design). A row says whether they agree and, if not, by how much,
// so a change that makes the device shade more than the counters say shows up here.
void compareInvocationsWithPixels(const ProfileRecord& now, GateOutcome& out) {
    for (const auto& [volume, invocations] : now.glInvocations) {
        std::int64_t pixels = 0;
        for (const auto& [name, n] : now.glPixels)
            if (name == volume) pixels = n;
        const std::int64_t wasted = invocations - pixels;
        out.rows.push_back({now.name, "gl-invocations", "apply invocations, " + volume,
                            "evaluated " + std::to_string(pixels),
                            "invoked " + std::to_string(invocations), RowStatus::Ok,
                            wasted == 0 ? "agree"
                                        : "DISAGREE (informational): " + std::to_string(wasted) +
                                              " invocations evaluated nothing"});
    }
}

} // namespace

const char* rowStatusName(RowStatus s) {
    switch (s) {
    case RowStatus::Ok:
        return "ok";
    case RowStatus::Changed:
        return "CHANGED";
    case RowStatus::New:
        return "NEW";
    case RowStatus::Missing:
        return "MISSING";
    case RowStatus::Worse:
        return "WORSE";
    case RowStatus::Disagree:
        return "DISAGREE";
    case RowStatus::Better:
        return "better";
    case RowStatus::Slower:
        return "SLOWER";
    case RowStatus::Faster:
        return "faster";
    case RowStatus::Same:
        return "same";
    case RowStatus::Unknown:
        return "unknown";
    case RowStatus::Failed:
        return "FAILED";
    case RowStatus::Skipped:
        break;
    }
    return "skipped";
}

bool failsDeterministic(RowStatus s) {
    return s == RowStatus::Changed || s == RowStatus::New || s == RowStatus::Missing ||
           s == RowStatus::Worse || s == RowStatus::Disagree || s == RowStatus::Failed;
}

int GateOutcome::deterministicFailures() const {
    return int(std::count_if(rows.begin(), rows.end(),
                             [](const GateRow& r) { return failsDeterministic(r.status); }));
}

int GateOutcome::timingFailures() const {
    return int(std::count_if(rows.begin(), rows.end(),
                             [](const GateRow& r) { return r.status == RowStatus::Slower; }));
}

std::vector<std::string> GateOutcome::undecidedRows() const {
    std::vector<std::string> out;
    for (const GateRow& r : rows)
        if (r.group == "timing" && r.status == RowStatus::Unknown)
            out.push_back(r.profile + ": " + r.name);
    return out;
}

int GateOutcome::exitCode() const {
    if (deterministicFailures() > 0) return kExitRegression;
    if (timingFailures() > 0) return kExitTimingRegression;
    if (undecidedFails && !undecidedRows().empty()) return kExitUndecided;
    return 0;
}

void compareRecords(const GateRecord& baseline, const GateRecord& now, GateOutcome& out) {
    compareEnvironment(baseline, now, out);
    for (const ProfileRecord& p : now.profiles) {
        const ProfileRecord* b = baseline.profile(p.name);
        compareCounters(b, p, otherMachine(baseline, now), out);
        compareModelWithGl(p, out);
        compareInvocationsWithPixels(p, out);
        compareAccuracy(b, p, now.suite.tolerance, out);
    }
    for (const ProfileRecord& b : baseline.profiles)
        if (!now.profile(b.name))
            out.rows.push_back({b.name, "counters", "(profile)", "measured", "-",
                                RowStatus::Missing, "in the baseline, not in this run's suite"});
}

void compareCallgrind(const GateRecord& baseline, const CallgrindRecord& now, GateOutcome& out) {
    const CallgrindRecord* base = baseline.callgrindFor(now.key);
    if (!base) {
        std::string have;
        for (const CallgrindRecord& c : baseline.callgrind)
            have += (have.empty() ? "" : "; ") + c.key.text();
        out.notes.push_back("callgrind: skipped - the baseline has no instruction counts for " +
                            now.key.text() + " (it has: " + (have.empty() ? "none" : have) +
                            "); `--update --callgrind` on this toolchain records them");
        out.rows.push_back({"", "callgrind", "instructions per frame", "-", "measured",
                            RowStatus::Skipped, "no baseline for this toolchain"});
        return;
    }
    const double tol = baseline.suite.callgrindTolerance;
    for (const auto& [profile, sections] : now.profiles) {
        const Counters* b = base->profile(profile);
        GateRow row{profile, "callgrind", "instructions per frame", "-", "-", RowStatus::Ok, ""};
        const std::int64_t nowFrame = valueOr(sections, "frame", -1);
        row.now = num(double(nowFrame), "%.0f");
        if (!b) {
            row.status = RowStatus::New;
            out.rows.push_back(row);
            continue;
        }
        const std::int64_t baseFrame = valueOr(*b, "frame", -1);
        row.baseline = num(double(baseFrame), "%.0f");
        // The frame total is gated; sections are named when they moved by more than the
        // tolerance of the frame (a pass's own count also moves with heap layout: a few
        // hundred thousand instructions between runs, seen in the shadow pass).
        const double rel = baseFrame > 0 ? double(nowFrame - baseFrame) / double(baseFrame) : 1.0;
        row.status = rel > tol ? RowStatus::Worse : rel < -tol ? RowStatus::Better : RowStatus::Ok;
        row.note =
            "frame " + num(100 * rel, "%+.4f%%") + " (tolerance " + num(100 * tol, "%.2g%%") + ")";
        for (const auto& [section, n] : sections) {
            if (section == "frame") continue;
            const std::int64_t bv = valueOr(*b, section, 0);
            if (std::llabs(n - bv) > tol * double(baseFrame))
                row.note += ", " + section + " " + num(double(n - bv), "%+.0f");
        }
        out.rows.push_back(row);
    }
}

GateRow timingRow(const std::string& profile, const std::string& what, const TimingComparison& c,
                  const std::string& unit, int rounds, bool budgetReached) {
    GateRow row{profile, "timing", what, "", "", RowStatus::Unknown, ""};
    const char* fmt = unit == "ms" ? "%.2f ms" : "%.4f";
    row.baseline = num(c.baselineMedian, fmt);
    row.now = num(c.candidateMedian, fmt);
    switch (c.verdict) {
    case TimingVerdict::Same:
        row.status = RowStatus::Same;
        break;
    case TimingVerdict::Different:
        row.status = c.shift > 0 ? RowStatus::Slower : RowStatus::Faster;
        break;
    case TimingVerdict::Unknown:
        row.status = RowStatus::Unknown;
        break;
    }
    row.note = timingSummary(c) + ", " + std::to_string(rounds) + " rounds" +
               (c.verdict == TimingVerdict::Unknown && budgetReached ? " (budget reached)" : "");
    return row;
}

} // namespace pb::gate
