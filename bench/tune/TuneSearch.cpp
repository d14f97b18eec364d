#include "TuneSearch.h"

#include "core/Error.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <tuple>

namespace pb::bench {

namespace {

class Search {
public:
    Search(const TuneSpace& space, const MemoryFn& memory, const MeasureFn& measure,
           const TuneOptions& o)
        : space_(space), memory_(memory), measure_(measure), o_(o) {}

    TuneResult& result() { return r_; }

    // The candidate's index, adding it (with its memory) when new.
    int add(const profile::Profile& p) {
        const std::string key = candidateKey(p);
        if (auto it = index_.find(key); it != index_.end()) return it->second;
        TuneCandidate c;
        c.switches = p;
        c.label = candidateLabel(p, space_.base);
        c.memoryMiB = memory_(p);
        r_.candidates.push_back(c);
        return index_[key] = int(r_.candidates.size()) - 1;
    }

    void measure(const std::vector<int>& ids, const std::string& what) {
        if (ids.empty()) return;
        say("session " + std::to_string(r_.sessions + 1) + ": " + what + ", " +
            std::to_string(ids.size()) + " candidate(s)");
        std::vector<profile::Profile> batch;
        for (int i : ids)
            batch.push_back(r_.candidates[size_t(i)].switches);
        const std::vector<TuneMeasurement> got = measure_(batch);
        if (got.size() != ids.size()) throw Error("tune: the measurement lost candidates");
        for (size_t k = 0; k < ids.size(); ++k) {
            TuneCandidate& c = r_.candidates[size_t(ids[k])];
            c.measured = true;
            c.m = got[k];
            ++c.measurements;
            char line[300];
            if (c.m.ok)
                std::snprintf(line, sizeof line, "  %-48s %8.2f ms %8.3f MiB  FLIP %.4f%s",
                              c.label.c_str(), c.m.frameMs, c.memoryMiB, c.m.flip,
                              c.fits(o_) ? "" : "  (over budget)");
            else
                std::snprintf(line, sizeof line, "  %-48s not run: %s", c.label.c_str(),
                              c.m.error.c_str());
            say(line);
        }
        ++r_.sessions;
        r_.variantsMeasured += int(ids.size());
    }

    // Lower is better.
    std::tuple<int, double, double, double> objective(int i) const {
        const TuneCandidate& c = r_.candidates[size_t(i)];
        if (!c.measured || !c.m.ok) return {2, 0, 0, 0};
        if (c.fits(o_)) return {0, c.m.flip, c.m.relativeMseGi, c.m.frameMs};
        return {1, std::max(c.m.frameMs / o_.budgetMs, c.memoryMiB / o_.budgetMiB), c.m.flip, 0};
    }

    void say(const std::string& line) const {
        if (o_.progress) o_.progress(line);
    }

    const TuneSpace& space_;
    const MemoryFn& memory_;
    const MeasureFn& measure_;
    const TuneOptions& o_;
    TuneResult r_;
    std::map<std::string, int> index_;
};

void exhaustive(Search& s, const std::vector<int>& fitting) {
    // Sessions of at most sessionSize, as even as possible.
    const size_t max = size_t(std::max(1, s.o_.sessionSize));
    const size_t sessions = (fitting.size() + max - 1) / max;
    const size_t n = (fitting.size() + sessions - 1) / sessions;
    for (size_t b = 0; b < fitting.size(); b += n) {
        std::vector<int> batch(fitting.begin() + long(b),
                               fitting.begin() + long(std::min(fitting.size(), b + n)));
        s.measure(batch, "exhaustive " + std::to_string(b / n + 1) + "/" +
                             std::to_string((fitting.size() + n - 1) / n));
    }
}

// The base, or when it is over the memory budget the fitting candidate that changes the
// fewest switches (ties: the least memory).
int startingPoint(Search& s, const std::vector<int>& fitting) {
    const int base = s.add(canonical(s.space_.base, s.space_));
    if (s.r_.candidates[size_t(base)].fitsMemory(s.o_)) return base;
    auto changes = [&](int i) {
        const std::string label = s.r_.candidates[size_t(i)].label;
        return label == "base" ? 0L : long(std::count(label.begin(), label.end(), ' ')) + 1;
    };
    int best = fitting.front();
    for (int i : fitting)
        if (std::make_pair(changes(i), s.r_.candidates[size_t(i)].memoryMiB) <
            std::make_pair(changes(best), s.r_.candidates[size_t(best)].memoryMiB))
            best = i;
    s.say("the base is over the memory budget: descent starts at " +
          s.r_.candidates[size_t(best)].label);
    return best;
}

void coordinateDescent(Search& s, const std::vector<int>& fitting) {
    const TuneSpace& space = s.space_;
    int current = startingPoint(s, fitting);
    for (int pass = 1; pass <= s.o_.maxPasses; ++pass) {
        bool changed = false;
        for (const SwitchAxis& axis : space.axes) {
            std::vector<int> ids{current};
            for (const std::string& v : axis.values) {
                profile::Profile p = s.r_.candidates[size_t(current)].switches;
                p.set(axis.key, v);
                const int id = s.add(canonical(p, space));
                if (std::find(ids.begin(), ids.end(), id) != ids.end()) continue;
                if (!s.r_.candidates[size_t(id)].fitsMemory(s.o_)) continue; // never rendered
                ids.push_back(id);
            }
            if (ids.size() < 2) continue;
            s.measure(ids, "pass " + std::to_string(pass) + ", " + axis.key);
            int best = current;
            for (int id : ids)
                if (s.objective(id) < s.objective(best)) best = id;
            if (best != current) {
                current = best;
                changed = true;
            }
        }
        if (!changed) break;
    }
}

} // namespace

std::vector<int> paretoFront3(const std::vector<TuneCandidate>& c) {
    auto usable = [&](size_t i) { return c[i].measured && c[i].m.ok; };
    auto dominates = [&](size_t a, size_t b) {
        const bool le = c[a].m.frameMs <= c[b].m.frameMs && c[a].memoryMiB <= c[b].memoryMiB &&
                        c[a].m.flip <= c[b].m.flip;
        const bool lt = c[a].m.frameMs < c[b].m.frameMs || c[a].memoryMiB < c[b].memoryMiB ||
                        c[a].m.flip < c[b].m.flip;
        return le && lt;
    };
    std::vector<int> front;
    for (size_t i = 0; i < c.size(); ++i) {
        if (!usable(i)) continue;
        bool beaten = false;
        for (size_t j = 0; j < c.size() && !beaten; ++j)
            beaten = j != i && usable(j) && dominates(j, i);
        if (!beaten) front.push_back(int(i));
    }
    std::sort(front.begin(), front.end(),
              [&](int a, int b) { return c[size_t(a)].m.frameMs < c[size_t(b)].m.frameMs; });
    return front;
}

TuneResult runTune(const TuneSpace& space, const MemoryFn& memory, const MeasureFn& measure,
                   const TuneOptions& o) {
    Search s(space, memory, measure, o);
    TuneResult& r = s.result();
    r.combinations = space.combinations();
    const std::vector<profile::Profile> all = enumerateSpace(space);
    r.distinct = all.size();
    std::vector<int> fitting;
    for (const profile::Profile& p : all) {
        const int id = s.add(p);
        if (r.candidates[size_t(id)].fitsMemory(o))
            fitting.push_back(id);
        else
            ++r.overMemory;
    }
    if (fitting.empty()) {
        std::vector<int> order(r.candidates.size());
        for (size_t i = 0; i < order.size(); ++i)
            order[i] = int(i);
        // Least memory first; among equals, the fewest switches changed from the base.
        auto changes = [&](int i) {
            const std::string& l = r.candidates[size_t(i)].label;
            return l == "base" ? 0L : long(std::count(l.begin(), l.end(), ' ')) + 1;
        };
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
            return std::make_pair(r.candidates[size_t(a)].memoryMiB, changes(a)) <
                   std::make_pair(r.candidates[size_t(b)].memoryMiB, changes(b));
        });
        order.resize(std::min<size_t>(3, order.size()));
        r.closest = order;
        r.method = "none (nothing fits the memory budget)";
        return r;
    }
    s.say(std::to_string(space.axes.size()) + " switch(es) searched, " +
          std::to_string(r.combinations) + " combination(s), " + std::to_string(r.distinct) +
          " distinct, " + std::to_string(r.overMemory) + " over the memory budget (not rendered)");
    if (int(fitting.size()) <= o.maxExhaustive) {
        r.method = "exhaustive";
        exhaustive(s, fitting);
    } else {
        r.method = "coordinate descent";
        coordinateDescent(s, fitting);
    }
    std::vector<int> measured;
    for (size_t i = 0; i < r.candidates.size(); ++i)
        if (r.candidates[i].measured) measured.push_back(int(i));
    std::stable_sort(measured.begin(), measured.end(),
                     [&](int a, int b) { return s.objective(a) < s.objective(b); });
    if (!measured.empty() && r.candidates[size_t(measured.front())].fits(o))
        r.chosen = measured.front();
    else
        for (size_t k = 0; k < measured.size() && k < 3; ++k)
            if (r.candidates[size_t(measured[k])].m.ok) r.closest.push_back(measured[k]);
    r.pareto = paretoFront3(r.candidates);
    return r;
}

} // namespace pb::bench
