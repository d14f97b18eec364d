// Probe data files (.pbp) through parseProbeSet, raw and with the checksum made to match.
#include "fuzz/FuzzTarget.h"

PB_FUZZ_TARGET(pb::fuzz::runProbeFile(data, size))
