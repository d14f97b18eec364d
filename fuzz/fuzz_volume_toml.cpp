// The volumes TOML file (`bake --volumes F.toml`) through parseVolumeToml.
#include "fuzz/FuzzTarget.h"
#include "probes/store/VolumeFile.h"

PB_FUZZ_TARGET(pb::fuzz::runToml(data, size, &pb::probes::parseVolumeToml))
