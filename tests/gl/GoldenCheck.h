#pragma once
// The golden-image step every golden test ends with (tests/README.md "Golden images"): under
// PB_UPDATE_GOLDENS=1 write `actual` as the new golden and say so (the caller then skips);
// else compare with the golden within kGoldenTolerance and, on failure, write
// actual/expected/diff PNGs to the test's output folder.
#include "image/Image.h"
#include "support/ImageCompare.h"
#include "support/TestEnv.h"

#include <cstdlib>
#include <filesystem>
#include <gtest/gtest.h>
#include <string>

namespace pb::test {

// True when the golden was written (update mode): the caller reports it with GTEST_SKIP.
inline bool updateOrCompareGolden(const image::Image8& actual,
                                  const std::filesystem::path& golden) {
    const char* update = std::getenv("PB_UPDATE_GOLDENS");
    if (update && std::string(update) == "1") {
        image::writePng(golden.string(), actual);
        return true;
    }
    if (!std::filesystem::exists(golden)) {
        ADD_FAILURE() << "no golden image " << golden
                      << " (create it with PB_UPDATE_GOLDENS=1, see tests/README.md)";
        return false;
    }
    const image::Image8 expected = image::readPng(golden.string());
    const ImageDiff d = compareImages(actual, expected, kGoldenTolerance);
    if (!withinTolerance(d, kGoldenTolerance)) {
        const std::filesystem::path dir = outputDir();
        writeFailureImages(dir, actual, expected);
        ADD_FAILURE() << d.describe() << "; actual/expected/diff images in " << dir;
    }
    return false;
}

} // namespace pb::test
