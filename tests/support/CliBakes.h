#pragma once
// Probe files the CLI tests bake through probebench as a user would.
#include <filesystem>

namespace pb::test {

// `probebench bake` of the built-in rooms scene with bench/volumes/rooms_nested.toml (the
// default bench's volumes), 32 rays, 1 bounce, to `file`; a failed bake fails the calling test.
// The bake cache makes a second call with the same file cheap.
std::filesystem::path bakeNestedRooms(const std::filesystem::path& file);

} // namespace pb::test
