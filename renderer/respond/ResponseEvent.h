#pragma once
// Scene changes that probes must follow (issue 20), given on the command line
// (`--event SPEC`) or in a TOML timeline (`[[event]] spec = "SPEC"`). SPEC forms:
//   sun:off@F  sun:on@F  sun:dir:X,Y,Z@F (direction towards the sun)  sun:scale:K@F
//   light:NAME:off@F  light:NAME:on@F  light:NAME:scale:K@F  light:NAME:move:X,Y,Z@F
//   node:NAME:remove@F  node:NAME:insert:X,Y,Z@F (a static copy of node NAME, its bounds
//   centred at X,Y,Z)
// F is the frame the change happens at (0-based, before that frame renders).
// Sun and sky changes are global (every probe sees the sky); the others are local: they
// happen at points (the light's or the object's old and new place).
#include "probes/Scenario.h"
#include "scene/Scene.h"

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace pb::respond {

enum class EventKind {
    SunOff,
    SunOn,
    SunDir,
    SunScale,
    LightOff,
    LightOn,
    LightScale,
    LightMove,
    NodeRemove,
    NodeInsert
};

struct ResponseEvent {
    std::string spec; // as given, for messages
    EventKind kind = EventKind::SunOff;
    std::string name; // light or node
    glm::vec3 value{0.0f};
    float scale = 1.0f;
    int frame = 0;
};

// Throws pb::Error "`option` 'SPEC': problem" for a spec that does not parse.
ResponseEvent parseEvent(const std::string& spec, const std::string& option = "--event");
// A TOML file of [[event]] tables with a `spec` string each. Throws pb::Error naming the file.
std::vector<ResponseEvent> readTimeline(const std::string& path);

// The lighting the probes see: the scene (lights, geometry) and the scenario (sun, sky).
struct World {
    scene::Scene scene;
    probes::Scenario scenario;
};

// Throws pb::Error naming the event for a light or node the scene lacks, or a frame outside
// [0, frames). Call for every event before anything renders.
void checkEvent(const ResponseEvent& e, const World& world, int frames);

// Where a change happened: everywhere (global) or at points.
struct Change {
    bool global = false;
    std::vector<glm::vec3> points;
};

// Applies `e` to `world` (the initial world supplies what `on` restores) and says where.
Change applyEvent(const ResponseEvent& e, World& world, const World& initial);

} // namespace pb::respond
