#include "support/TestEnv.h"

namespace pb::test {

std::filesystem::path outputDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = info ? std::string(info->test_suite_name()) + "." + info->name() : "misc";
    for (char& c : name)
        if (c == '/') c = '_';
    auto dir = std::filesystem::path(PB_TEST_OUTPUT_DIR) / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace pb::test
