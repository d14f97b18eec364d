// Platform profiles (profiles/*.toml, `--profile F.toml`) through parseProfileToml. No search
// folders: `inherit = "NAME"` looks only next to the input (the working folder).
#include "fuzz/FuzzTarget.h"
#include "profile/ProfileLoader.h"

PB_FUZZ_TARGET(pb::fuzz::runToml(data, size, &pb::fuzz::parseProfileText))
