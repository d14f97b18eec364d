// .gltf JSON + .bin through loadGltf (input: JSON, a NUL byte, the .bin bytes).
#include "fuzz/FuzzTarget.h"

PB_FUZZ_TARGET(pb::fuzz::runGltfWithBin(data, size, pb::fuzz::scratchDir()))
