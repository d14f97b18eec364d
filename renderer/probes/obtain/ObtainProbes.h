#pragma once
// The one way to get probes: "the probes for this scene and these options", as `bake`, `bench`,
// `tune`, `respond` and the gate ask for them (issue 44, item 6). Same options, same file, in
// every command:
//
//   1. placement cache (PlacementCache.h): with automatic placement, when FILE.placement.json
//      holds this request's placement key and FILE's volumes hash to FILE's own input hash, FILE
//      is up to date - no placement, no lattice search;
//   2. place (or read the volumes file) and build the bake request;
//   3. bake cache: FILE with this request's input hash is up to date;
//   4. bake, write FILE atomically, record the placement cache.
//
// Nothing is trusted blindly: a damaged FILE or sidecar means placing and baking again.
// `bake --split` parts are not probes for a scene and do not come through here.
#include "BakeOptions.h"
#include "PlacementSummary.h"

#include "probes/ProbeSet.h"
#include "probes/bake/Baker.h"
#include "scene/Scene.h"

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace pb::probes {

// A placed request: the volumes and everything else the bake needs.
struct PlacedRequest {
    BakeRequest request;
    PlacementInfo placement;
    nlohmann::json placementJson; // placementJson(placement, format)
    double seconds = 0.0;         // the placement's wall time (lattice search included)
};

// What callers see of the work (all optional). Every callback runs on the calling thread.
struct ObtainHooks {
    std::function<void(const std::string& stage, int done, int total)> placementProgress;
    std::function<void()> placementDone;              // e.g. to clear a progress line
    std::function<void(const std::string&)> note;     // one line, without "note: "
    std::function<void(const PlacedRequest&)> placed; // placed this run, before the bake cache
    std::function<void(const PlacedRequest&)> bakeStarts;
    std::function<void(const BakeProgress&)> bakeProgress;
};

struct ObtainedProbes {
    ProbeSet set;
    nlohmann::json placement;    // this run's placement, or the placement cache's
    bool placedThisRun = false;  // false: the placement cache proved the file up to date
    bool baked = false;          // false: the file was up to date
    BakeStats stats;             // only when baked
    double placementSeconds = 0.0, writeSeconds = 0.0;
};

// Places automatically (hooks.placementProgress, notes) or reads the volumes file (refused when
// over the budget) and builds the bake request. Throws pb::Error (one line) on bad options.
PlacedRequest placeRequest(const scene::Scene& s, const BakeOptions& o, const ObtainHooks& hooks);

// What an up-to-date file may save: the placement and the bake (steps 1 and 3), only the bake
// (step 3: `bake --write-volumes` needs this run's placement), or nothing (`bake --force`).
enum class Reuse { PlacementAndBake, BakeOnly, Nothing };

// The probes of `o` for `s` in `file` (steps above).
ObtainedProbes obtainProbes(const scene::Scene& s, const BakeOptions& o, const std::string& file,
                            Reuse reuse = Reuse::PlacementAndBake, const ObtainHooks& hooks = {});

// The file of these options in a cache folder, named without placing: the scene's name, a key
// of the options (the placement key with automatic placement, else the bake's input hash) and
// the Embree ISA (bakes on two ISAs differ in the last bits). Creates the folder.
std::string probeCachePath(const scene::Scene& s, const BakeOptions& o, const std::string& cacheDir);

} // namespace pb::probes
