#pragma once
// The argument checks every image metric shares, so the error text is the same everywhere.
#include "image/Image.h"

namespace pb::metrics {

// Throws pb::Error "<metric>: ..." when either image is empty or the sizes differ.
void requireComparable(const char* metric, const image::Image8& test,
                       const image::Image8& reference);
// Same for float images; the channel counts must match as well.
void requireComparable(const char* metric, const image::ImageF& test,
                       const image::ImageF& reference);

} // namespace pb::metrics
