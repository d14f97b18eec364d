// probebench bake-merge: joins the part files of a split bake (`bake --split scenario --part
// I/N`) into the probe file one bake of the same inputs writes, byte for byte
// (renderer/probes/store/ProbeFileParts.h says why it is exact and what it checks).
#include "CommandRegistry.h"
#include "OutputPaths.h"
#include "core/Error.h"
#include "probes/store/ProbeFile.h"
#include "probes/store/ProbeFileParts.h"

#include <iostream>

namespace pb::app {
namespace {

struct BakeMergeArgs {
    std::vector<std::string> parts;
    std::string out;
    bool mkdir = false; // --mkdir: create --out's folder
};

int runBakeMerge(const BakeMergeArgs& a) {
    prepareOutputParent("--out", a.out, a.mkdir); // OutputPaths.h: before reading any part
    std::vector<probes::ProbeFilePart> parts;
    for (const std::string& path : a.parts)
        parts.push_back(probes::readProbeFilePart(path));
    probes::ProbeSet set = probes::mergeProbeFileParts(parts, a.parts);
    probes::writeProbeFile(a.out, set);
    std::cout << "merged " << parts.size() << " part(s), " << set.scenarios.size()
              << " scenario(s):";
    for (const auto& s : set.scenarios)
        std::cout << " " << s.name;
    std::cout << "\nwrote " << a.out << "\n";
    return 0;
}

const RegisterCommand registerBakeMerge{{
    "bake-merge",
    "Join the part files of a split bake (bake --split) into one probe file",
    31,
    [](CLI::App& cmd) -> std::function<int()> {
        auto a = std::make_shared<BakeMergeArgs>();
        cmd.add_option("parts", a->parts,
                       "The part files, in any order: every part of one bake, each once")
            ->required();
        cmd.add_option("--out", a->out,
                       "The probe file to write (identical to the one a single bake of the same "
                       "inputs writes)")
            ->required();
        cmd.add_flag("--mkdir", a->mkdir, "Create the missing parent folder of --out (else a missing folder is an error, before any work)");
        return [a] { return runBakeMerge(*a); };
    },
}};

} // namespace
} // namespace pb::app
