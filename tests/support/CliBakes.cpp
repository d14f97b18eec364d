#include "support/CliBakes.h"

#include "support/RunCommand.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>

namespace pb::test {

std::filesystem::path bakeNestedRooms(const std::filesystem::path& file) {
    const auto r = runProbebench({"bake", "--scene", "rooms", "--volumes",
                                  (sourceDir() / "bench/volumes/rooms_nested.toml").string(),
                                  "--rays", "32", "--bounces", "1", "--out", file.string()});
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return file;
}

std::filesystem::path bakeCoarseRooms(const std::filesystem::path& file) {
    const auto r =
        runProbebench({"bake", "--scene", "rooms", "--volumes", "auto-uniform", "--spacing", "0.8",
                       "--rays", "32", "--bounces", "1", "--out", file.string()});
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return file;
}

} // namespace pb::test
