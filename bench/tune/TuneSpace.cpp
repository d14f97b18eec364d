#include "TuneSpace.h"

#include "core/Error.h"
#include "profile/SwitchTable.h"

#include <algorithm>
#include <set>

namespace pb::bench {

std::size_t TuneSpace::combinations() const {
    std::size_t n = 1;
    for (const SwitchAxis& a : axes)
        n *= a.values.size();
    return n;
}

TuneSpace makeTuneSpace(const profile::Profile& base, const TuneContext& context,
                        const std::vector<std::string>& only) {
    for (const std::string& key : only)
        if (!profile::findSwitch(key)) throw Error("--search: unknown switch '" + key + "'");
    TuneSpace space;
    space.base = base;
    space.context = context;
    for (const profile::SwitchInfo& s : profile::switchTable()) {
        const std::string current = s.get(base);
        if (!only.empty() && std::find(only.begin(), only.end(), s.key) == only.end()) {
            space.fixed.push_back(s.key + ": not in --search");
            continue;
        }
        // A guard protects against inputs the tuned scene need not contain (fp16 overflow at
        // extreme light, README "What breaks where"); on an ordinary scene turning it off only
        // looks free, so it is searched only when --search names it.
        if (only.empty() && isGuard(s.key)) {
            space.fixed.push_back(s.key + ": a guard (searched only when --search names it)");
            continue;
        }
        std::vector<std::string> values{current};
        if (s.kind == profile::SwitchKind::Choice)
            values.insert(values.end(), s.choices.begin(), s.choices.end());
        else if (s.key == "gi.volume_lod")
            values.insert(values.end(), context.volumeLodValues.begin(),
                          context.volumeLodValues.end());
        else {
            space.fixed.push_back(s.key + ": no finite list of values to try");
            continue;
        }
        std::vector<std::string> unique;
        for (const std::string& v : values)
            if (std::find(unique.begin(), unique.end(), v) == unique.end()) unique.push_back(v);
        if (s.key == "gi.dynamic" && context.dynamicObjects == 0) {
            space.fixed.push_back(s.key + ": the scene has no dynamic objects");
            continue;
        }
        if (unique.size() < 2) {
            space.fixed.push_back(s.key + ": one value");
            continue;
        }
        space.axes.push_back({s.key, unique});
    }
    return space;
}

bool isGuard(const std::string& key) {
    return key.rfind("gi.guard_", 0) == 0;
}

profile::Profile canonical(const profile::Profile& p, const TuneSpace& space) {
    profile::Profile c = p;
    if (c.gi.resolution == profile::GiResolution::Full) c.gi.upsample = space.base.gi.upsample;
    if (space.context.dynamicObjects == 0) c.gi.dynamic = space.base.gi.dynamic;
    return c;
}

std::string candidateKey(const profile::Profile& p) {
    return p.valuesJson().dump();
}

std::string candidateLabel(const profile::Profile& p, const profile::Profile& base) {
    std::string out;
    for (const profile::SwitchInfo& s : profile::switchTable())
        if (s.get(p) != s.get(base)) out += (out.empty() ? "" : " ") + s.key + "=" + s.get(p);
    return out.empty() ? "base" : out;
}

std::vector<profile::Profile> enumerateSpace(const TuneSpace& space) {
    std::vector<profile::Profile> out;
    std::set<std::string> seen;
    std::vector<size_t> index(space.axes.size(), 0);
    for (;;) {
        profile::Profile p = space.base;
        for (size_t a = 0; a < space.axes.size(); ++a)
            p.set(space.axes[a].key, space.axes[a].values[index[a]]);
        p = canonical(p, space);
        if (seen.insert(candidateKey(p)).second) out.push_back(p);
        size_t a = 0;
        for (; a < index.size(); ++a) {
            if (++index[a] < space.axes[a].values.size()) break;
            index[a] = 0;
        }
        if (a == index.size()) break;
    }
    return out;
}

} // namespace pb::bench
