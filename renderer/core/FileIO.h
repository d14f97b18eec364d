#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace pb {

// Writes `bytes` to `path` atomically (temporary file in the same folder + rename): a crash or
// a full disk never leaves a partial file behind. Throws pb::Error naming the path.
void writeFileAtomic(const std::string& path, const void* bytes, std::size_t size);

// Reads a whole regular file; throws pb::Error naming the path when it cannot (missing, a
// folder, a device or FIFO, unreadable).
std::vector<unsigned char> readFileBytes(const std::string& path);

} // namespace pb
