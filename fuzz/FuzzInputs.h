#pragma once
// One fuzz input through one reader, shared by the libFuzzer targets (fuzz/fuzz_*.cpp) and the
// regression test that replays every input that once failed (tests/unit/FuzzRegressionTest).
//
// The contract checked for every input: the reader returns, or throws a pb::Error whose
// message is one line starting with the file's name. Anything else - another exception, a
// multi-line message, a loaded probe set whose lookups are not finite - throws
// ContractViolation; a crash, a hang or a sanitizer report is caught by the caller's process.
#include "core/Error.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace pb::fuzz {

struct ContractViolation : std::logic_error {
    using std::logic_error::logic_error;
};

enum class Outcome { Loaded, Rejected };

// .gltf + .bin: the input is the JSON up to the first NUL byte, the rest is `fuzz.bin`, which
// the JSON's buffers may name as their uri. Both are written to `dir` and loaded from there.
Outcome runGltfWithBin(const std::uint8_t* data, std::size_t size,
                       const std::filesystem::path& dir);
// .glb: the input is the whole file, written to `dir` and loaded from there.
Outcome runGlb(const std::uint8_t* data, std::size_t size, const std::filesystem::path& dir);
// A TOML file through `parse(text, name)`, e.g. probes::parseVolumeToml: one line per TOML
// reader (a profile parser joins the same way).
template <class Parse> Outcome runToml(const std::uint8_t* data, std::size_t size, Parse&& parse);
// A platform profile through profile::parseProfileToml with no search folders (the parse
// that runToml hands a profile to; `inherit` finds only files next to `name`).
void parseProfileText(std::string_view text, const std::string& name);
// A probe data file (renderer/probes/ProbeFile), parsed as is, then with its size field and
// checksum made to match (so the parser behind the checksum is reached); a set that loads is
// sampled by the CPU reference sampler, which must return finite irradiance.
Outcome runProbeFile(const std::uint8_t* data, std::size_t size);

// The error contract for any reader: runs `load`, returns Loaded, or Rejected for a pb::Error
// whose message is one line starting with `name`; throws ContractViolation otherwise.
template <class Load> Outcome expectCleanResult(const std::string& name, Load&& load) {
    try {
        load();
        return Outcome::Loaded;
    } catch (const pb::Error& e) {
        const std::string message = e.what();
        if (message.find('\n') != std::string::npos || message.find('\r') != std::string::npos)
            throw ContractViolation("error message is not one line: " + message);
        if (message.rfind(printable(name), 0) != 0)
            throw ContractViolation("error message does not start with the file name '" + name +
                                    "': " + message);
        return Outcome::Rejected;
    } catch (const ContractViolation&) {
        throw;
    } catch (const std::exception& e) {
        throw ContractViolation(std::string("not a pb::Error: ") + e.what());
    }
}

template <class Parse> Outcome runToml(const std::uint8_t* data, std::size_t size, Parse&& parse) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    return expectCleanResult("fuzz.toml", [&] { parse(text, std::string("fuzz.toml")); });
}

// A per-process scratch folder (in /dev/shm when there is one) for the file-based targets.
std::filesystem::path scratchDir();

} // namespace pb::fuzz
