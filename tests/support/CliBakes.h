#pragma once
// Probe files the CLI tests bake through probebench as a user would.
#include <filesystem>

namespace pb::test {

// `probebench bake` of the built-in rooms scene with bench/volumes/rooms_nested.toml (the
// default bench's volumes), 32 rays, 1 bounce, to `file`; a failed bake fails the calling test.
// The bake cache makes a second call with the same file cheap.
std::filesystem::path bakeNestedRooms(const std::filesystem::path& file);

// A coarse, quick `probebench bake` of rooms (auto-uniform, spacing 0.8, 32 rays, 1 bounce)
// to `file`, for tests that need some GI rather than particular probes; a failed bake fails
// the calling test. The bake cache shares it across test processes, atomic writes keep
// parallel runs safe.
std::filesystem::path bakeCoarseRooms(const std::filesystem::path& file);

} // namespace pb::test
