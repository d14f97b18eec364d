#pragma once
// A target device as data (profiles/devices/*.toml): the figures the frame-time model
// (FrameModel.h) needs - shader cores, clock, ALU lanes, texture units and rates, ROPs, caches,
// memory bandwidth, a fixed cost per draw - and the `probebench shaders` target whose compiler
// stands in for its shader costs. Every figure's public source is a comment in its file; the
// model never fits a figure to a measurement. GL-free.
#include "costmodel/TextureCache.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace pb::devicemodel {

struct DeviceSpec {
    std::string name;        // file stem: what --predict takes
    std::string label;       // "Nintendo Switch, handheld (Tegra X1 GM20B at 307.2 MHz)"
    std::string compiler;    // shaders::ShaderTarget name ("tegra-x1")
    std::string deviceClass; // handheld, phone, console, pc, datacentre
    std::string file;        // the TOML it came from

    int cores = 1;              // SMs, CUs, shader cores, SPs
    double clockMhz = 0;
    int fp32LanesPerCore = 0;   // FP32 FMA lanes per core per clock
    double fp16Rate = 1;        // fp16 arithmetic relative to fp32 (2: double rate)
    int textureUnitsPerCore = 0; // bilinear 32-bit texels per core per clock
    double trilinear3dRate = 0.5; // a trilinear 3D sample, relative to bilinear 2D
    double wideTexelRate = 0.5;   // a filtered 64-bit texel (RGBA16F), relative
    int ropPixelsPerClock = 0;    // 32-bit pixels written per clock, whole GPU
    double drawOverheadUs = 0;    // fixed GPU cost per draw

    double bandwidthGBs = 0; // DRAM, 10^9 B/s
    costmodel::CacheConfig l1, l2; // texture L1 per core; last-level cache, whole GPU

    double clockHz() const { return clockMhz * 1e6; }
    nlohmann::json toJson() const;
};

// Reads and checks one device file. Throws pb::Error "FILE:LINE: problem" (a missing key, a
// value out of range, an unknown key, a name that is not the file stem).
DeviceSpec loadDevice(const std::string& path);

// The device folders: $PROBEBENCH_DEVICES (':'-separated) first, then `builtIn`.
std::vector<std::string> deviceDirs(const std::string& builtIn);
// Device names (file stems of *.toml) in `dirs`, sorted, first folder wins.
std::vector<std::string> deviceNames(const std::vector<std::string>& dirs);
// A name from `dirs` or a path to a .toml. Throws pb::Error naming the devices (and the
// closest name) when there is none.
DeviceSpec findDevice(const std::string& nameOrPath, const std::vector<std::string>& dirs);
// "a,b" or "all": every device once, order kept.
std::vector<DeviceSpec> findDevices(const std::string& list, const std::vector<std::string>& dirs);

} // namespace pb::devicemodel
