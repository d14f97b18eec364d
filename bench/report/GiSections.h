#pragma once
// Which timed sections are the cost of GI, for the "GI ms" column, `gi_pass_ms` and
// `gi_over_floor` (issue 25, item 2): summing only names starting with "gi-" left out the
// temporal upsample (7.7 ms of handheld's frame), so a profile looked cheaper than the
// reference while it was dearer.
#include <string>

namespace pb::bench {

// The "gi-" sections - gi-apply, its stencil fill gi-fill, gi-depth-copy, gi-dynamic-sh (the
// SH projection for dynamic objects) - and "upsample" (GiUpsamplePass: it exists only for
// gi.resolution below full). Not the fetch floor, which is a separate measurement.
bool isGiSection(const std::string& name);

// What the GI column sums, in words, for the reports' notes.
inline constexpr const char* kGiSectionsText =
    "gi-apply + gi-fill (stencil) + gi-depth-copy + gi-dynamic-sh (SH projection) + upsample";

} // namespace pb::bench
