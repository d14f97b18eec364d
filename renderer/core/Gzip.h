#pragma once
// gzip (RFC 1952) of a whole buffer, through zlib: for data committed to the repository that
// would otherwise be large (the gate's probe file beside its baseline, bench/baselines/).
#include <cstddef>
#include <string>
#include <vector>

namespace pb {

// gzip-compressed bytes of `data` (best compression; deterministic: no name, no time stamp).
std::vector<unsigned char> gzipCompress(const void* data, std::size_t size);

// The decompressed bytes of a gzip stream. Throws pb::Error "<what>: not a gzip stream" or
// "<what>: truncated or corrupt gzip data" (what: the file it came from).
std::vector<unsigned char> gzipDecompress(const std::vector<unsigned char>& gz,
                                          const std::string& what);

} // namespace pb
