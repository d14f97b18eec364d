// .glb through loadGltf.
#include "fuzz/FuzzTarget.h"

PB_FUZZ_TARGET(pb::fuzz::runGlb(data, size, pb::fuzz::scratchDir()))
