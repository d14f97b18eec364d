#pragma once
// The five shared scenes the placement and lattice benchmarks run by default: under
// $PB_SCENES_DIR, else ../shared/scenes (run them from the repository root).
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace pb::studies {

inline std::vector<std::string> sharedScenes() {
    std::filesystem::path dir = "../shared/scenes";
    if (const char* d = std::getenv("PB_SCENES_DIR")) dir = d;
    return {(dir / "sponza_decimated/sponza_s_lod4.glb").string(),
            (dir / "cornell_box/CornellBox-Original.gltf").string(),
            (dir / "space_ship_hallway/space_ship_hallway.glb").string(),
            (dir / "japanese_bridge_garden/japanese_bridge_garden.gltf").string(),
            (dir / "dream_apartment/dream_apartment.gltf").string()};
}

} // namespace pb::studies
