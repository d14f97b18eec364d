#pragma once
// The procedural scenes behind makeBuiltinScene(). Each fills in geometry, lights, sky,
// exposure and its named views; makeBuiltinScene() adds the "default" view in front.
#include "scene/Scene.h"

namespace pb::scene {

Scene makeCornellScene();
Scene makeRoomsScene();
// `rooms` with three dynamic boxes in free space (issue 18).
Scene makeRoomsDynamicScene();
Scene makeCourtyardScene();
// Two rooms sharing a 10 cm wall, one lit: the GI leak figure (issue 19).
Scene makeThinWallScene();

} // namespace pb::scene
