// The probe data file: round trip, and clear errors for truncated, wrong-version and corrupted
// files; storage formats and the memory report's reference figures.
#include "probes/store/ProbeFile.h"
#include "ProbeTestScenes.h"
#include "SunlitFloorBake.h"
#include "core/Error.h"
#include "core/FileIO.h"
#include "probes/bake/Baker.h"
#include "probes/store/MemoryReport.h"
#include "support/TestEnv.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sstream>

using namespace pb::probes;

namespace {

ProbeSet smallBake(StorageFormat format) {
    const pb::scene::Scene s = pb::test::sunlitFloor();
    BakeRequest r = pb::test::sunlitFloorRequest(s);
    r.settings.format = format;
    return bakeProbes(s, r);
}

std::string probeFileReadError(const std::vector<std::uint8_t>& bytes) {
    try {
        parseProbeSet(bytes, "probes.pbp");
    } catch (const pb::Error& e) {
        return e.what();
    }
    return "(no error)";
}

} // namespace

TEST(ProbeFile, RoundTripsEveryFormat) {
    for (StorageFormat f : {StorageFormat::Rgba16f, StorageFormat::Rgba32f, StorageFormat::Bc6h}) {
        ProbeSet set = smallBake(f);
        auto path = (pb::test::outputDir() / "probes.pbp").string();
        writeProbeFile(path, set);
        ProbeSet back = readProbeFile(path);
        EXPECT_EQ(back.inputHash, set.inputHash);
        EXPECT_EQ(back.format(), f);
        ASSERT_EQ(back.volumes.size(), 1u);
        EXPECT_EQ(back.volumes[0].counts, set.volumes[0].counts);
        ASSERT_EQ(back.scenarios.size(), 2u);
        EXPECT_EQ(back.scenarios[1].name, "night");
        // The bake's in-memory texels are already the quantised ones the file decodes to.
        EXPECT_EQ(back.irradiance[0][0].texels, set.irradiance[0][0].texels) << formatName(f);
        EXPECT_EQ(back.visibility[0].texels, set.visibility[0].texels) << formatName(f);
        EXPECT_EQ(back.irradiance[1][0].stored.size(), storedBytes(irradianceShape({4, 2, 4}), f));
        EXPECT_EQ(serializeProbeSet(back), serializeProbeSet(set));
    }
}

TEST(ProbeFile, TruncatedFileIsAClearError) {
    std::vector<std::uint8_t> bytes = serializeProbeSet(smallBake(StorageFormat::Rgba16f));
    for (std::size_t keep :
         {std::size_t(0), std::size_t(5), std::size_t(30), bytes.size() / 2, bytes.size() - 1}) {
        std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + std::ptrdiff_t(keep));
        std::string e = probeFileReadError(cut);
        EXPECT_EQ(e.rfind("probes.pbp: ", 0), 0u) << e;
        EXPECT_TRUE(e.find("truncated") != std::string::npos ||
                    e.find("not a probebench probe file") != std::string::npos)
            << keep << ": " << e;
    }
}

TEST(ProbeFile, WrongVersionIsAClearError) {
    std::vector<std::uint8_t> bytes = serializeProbeSet(smallBake(StorageFormat::Rgba16f));
    bytes[8] = 99;
    std::string e = probeFileReadError(bytes);
    EXPECT_NE(e.find("version 99"), std::string::npos) << e;
    EXPECT_NE(e.find("re-bake"), std::string::npos) << e;
}

TEST(ProbeFile, FlippedBitIsCaughtByTheChecksum) {
    std::vector<std::uint8_t> bytes = serializeProbeSet(smallBake(StorageFormat::Rgba16f));
    for (std::size_t at :
         {std::size_t(40), bytes.size() / 3, bytes.size() - 20, bytes.size() - 3}) {
        std::vector<std::uint8_t> bad = bytes;
        bad[at] ^= 0x10;
        std::string e = probeFileReadError(bad);
        EXPECT_NE(e.find("checksum"), std::string::npos) << at << ": " << e;
    }
    std::vector<std::uint8_t> junk(bytes.size(), 0x41);
    EXPECT_NE(probeFileReadError(junk).find("not a probebench probe file"), std::string::npos);
}

TEST(ProbeFile, MissingFileAndFolderAreClearErrors) {
    EXPECT_THROW(readProbeFile("/nonexistent/probes.pbp"), pb::Error);
    EXPECT_THROW(writeProbeFile("/nonexistent/dir/probes.pbp", smallBake(StorageFormat::Rgba16f)),
                 pb::Error);
}

TEST(ProbeMemory, ReferenceTalkFigures32x8x32) {
    ProbeVolume v;
    v.name = "grid";
    v.counts = parseGrid("32x8x32");
    MemoryReport r = memoryReport({v});
    EXPECT_EQ(r.total.probes, 8192u);
    EXPECT_EQ(r.total.uncompressed.irradiance / 8192, 512u);
    EXPECT_EQ(r.total.uncompressed.visibility / 8192, 1024u);
    EXPECT_EQ(r.total.uncompressed.total() / 8192, 1536u);
    EXPECT_EQ(r.total.uncompressed.irradiance, 4u << 20);
    EXPECT_EQ(r.total.uncompressed.visibility, 8u << 20);
    EXPECT_EQ(r.total.uncompressed.total(), 12u << 20);
    EXPECT_EQ(r.total.bc6h.total() / 8192, 320u);
    EXPECT_EQ(r.total.bc6h.total(), (5u << 20) / 2);
    nlohmann::json j = memoryReportJson(r);
    EXPECT_EQ(j["total"]["uncompressed"]["per_probe"], 1536);
    EXPECT_EQ(j["total"]["bc6h"]["total"], 2621440);
    std::string text = formatMemoryReport(r);
    EXPECT_NE(text.find("12.00 MiB"), std::string::npos) << text;
    EXPECT_NE(text.find("2.50 MiB"), std::string::npos) << text;
    EXPECT_NE(text.find("512+1024"), std::string::npos) << text;
    EXPECT_NE(text.find("64+256"), std::string::npos) << text;
    EXPECT_EQ(bytesPerProbe(StorageFormat::Rgba32f).total(), 3072u);
}

TEST(ProbeMemory, GridParsingErrors) {
    EXPECT_EQ(parseGrid("4X2x3"), glm::ivec3(4, 2, 3));
    EXPECT_THROW(parseGrid("32x8"), pb::Error);
    EXPECT_THROW(parseGrid("0x8x8"), pb::Error);
    EXPECT_THROW(parseGrid("axbxc"), pb::Error);
}

TEST(ProbeFormat, HalfQuantisationClampsInsteadOfOverflowing) {
    EXPECT_EQ(quantiseHalf(1e9f), 65504.0f);
    EXPECT_EQ(quantiseHalf(-3.0f), 0.0f);
    EXPECT_EQ(quantiseHalf(NAN), 0.0f);
    EXPECT_NEAR(quantiseHalf(3.14159265f), 3.14159265f, 2e-3f);
}

TEST(ProbeFile, CacheReusesOnlyAnIntactFileWithTheSameInputs) {
    ProbeSet set = smallBake(StorageFormat::Rgba16f);
    auto path = (pb::test::outputDir() / "cache.pbp").string();
    std::string why;
    EXPECT_FALSE(readCachedProbeFile(path, set.inputHash, &why));
    EXPECT_EQ(why, "no file yet");
    writeProbeFile(path, set);
    auto hit = readCachedProbeFile(path, set.inputHash, &why);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->inputHash, set.inputHash);
    EXPECT_FALSE(readCachedProbeFile(path, set.inputHash + 1, &why));
    EXPECT_EQ(why, "inputs changed");
    std::vector<std::uint8_t> bytes = serializeProbeSet(set);
    bytes[bytes.size() / 2] ^= 1;
    pb::writeFileAtomic(path, bytes.data(), bytes.size());
    EXPECT_FALSE(readCachedProbeFile(path, set.inputHash, &why));
    EXPECT_NE(why.find("checksum"), std::string::npos) << why;
}

// The memory table names its counts as bake does (issue 25, item 10): "grid probes" (every
// probe of the grid) and "stored" (those with a tile), per volume and in total; the bytes and
// B/probe are of the stored ones. Before, one "probes" column showed the grid count beside
// bytes of the stored probes.
TEST(ProbeMemory, TableSaysGridAndStoredProbes) {
    ProbeVolume a, b;
    a.name = "outer";
    a.counts = parseGrid("8x4x8"); // 256 grid probes
    b.name = "inner";
    b.counts = parseGrid("4x4x4"); // 64
    const std::vector<std::size_t> stored{100, 64};
    const MemoryReport r = memoryReport({a, b}, StorageFormat::Rgba16f, &stored);
    const std::string text = formatMemoryReport(r);
    std::istringstream lines(text);
    std::string line, header, outer, total;
    while (std::getline(lines, line)) {
        if (line.rfind("volume", 0) == 0) header = line;
        if (line.rfind("outer", 0) == 0) outer = line;
        if (line.rfind("total", 0) == 0) total = line;
    }
    EXPECT_NE(header.find("grid probes"), std::string::npos) << text;
    EXPECT_NE(header.find("stored"), std::string::npos) << text;
    std::istringstream o(outer);
    std::string name, grid;
    std::size_t gridProbes = 0, storedProbes = 0;
    o >> name >> grid >> gridProbes >> storedProbes;
    EXPECT_EQ(gridProbes, 256u) << outer;
    EXPECT_EQ(storedProbes, 100u) << outer;
    std::istringstream t(total);
    t >> name >> gridProbes >> storedProbes;
    EXPECT_EQ(gridProbes, 320u) << total;
    EXPECT_EQ(storedProbes, 164u) << total;
    EXPECT_NE(text.find("sparse storage: 164 of 320 grid probes stored"), std::string::npos)
        << text;
}
