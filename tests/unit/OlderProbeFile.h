#pragma once
// A probe file as an older version wrote it, for the tests that read old files: `bytes` is a
// file this build wrote, `cut` how many bytes of records the older version lacks at its end
// (before the checksum); the version, size and checksum are redone.
#include "core/Hash.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace pb::test {

inline std::vector<std::uint8_t> asOlderProbeFile(std::vector<std::uint8_t> bytes, std::size_t cut,
                                                  std::uint32_t version) {
    bytes.resize(bytes.size() - 8 - cut);
    std::memcpy(bytes.data() + 8, &version, 4);
    const std::uint64_t size = bytes.size() + 8;
    std::memcpy(bytes.data() + 12, &size, 8);
    const std::uint64_t sum = pb::fnv1a64(bytes.data(), bytes.size());
    bytes.resize(bytes.size() + 8);
    std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
    return bytes;
}

} // namespace pb::test
