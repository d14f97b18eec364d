#pragma once
// Small helpers for the self-contained HTML report: escaping and data: URIs.
#include <cstdint>
#include <string>
#include <vector>

namespace pb::bench {

std::string htmlEscape(const std::string& s);
std::string base64(const std::vector<unsigned char>& bytes);
// "data:image/png;base64,..." of a PNG file; throws pb::Error naming the file.
std::string pngDataUri(const std::string& path);

} // namespace pb::bench
