#pragma once
// One compiled shader's statistics as a Mesa driver reports them through KHR_debug (its
// shader-db line), parsed into named numbers, and the few figures every report compares.
//
// The lines, as Mesa 22.3 writes them:
//   freedreno  "FRAG shader: 96 inst, 10 nops, ..., 3 half, 8 full, ..., 16 waves, 0 loops"
//   Bifrost    "MESA_SHADER_FRAGMENT shader: 132 inst, ..., 4.000000 cycles, 3.8 arith,
//               4.0 texture, ..., 2 threads, 0 loops, 0:0 spills:fills"
//   Valhall    "MESA_SHADER_FRAGMENT shader: 163 inst, 2.0 cycles, 1.28 fma, 1.08 cvt, ...
//               2.0 t, 0.0 ls, ..., 2 threads, 0 loops, 0:0 spills:fills"
//   v3d        "MESA_SHADER_FRAGMENT shader: 116 inst, 4 threads, 0 loops, 12 uniforms,
//               27 max-temps, 0:0 spills:fills, ..."
//   nouveau    "type: 1, local: 0, shared: 0, gpr: 15, inst: 93, bytes: 744, cached: 0"
// Anything else (a driver's performance warning, an info log) is not a statistics line.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pb::shaders {

struct StageStatistics {
    std::string stage;                    // "vertex", "fragment", or the driver's own word
    std::string driverStage;              // as the driver wrote it: "FRAG", "MESA_SHADER_POSITION"
    std::map<std::string, double> fields; // every "<number> <name>" of the line

    double field(const std::string& name, double fallback = -1) const;
    bool has(const std::string& name) const { return fields.count(name) != 0; }

    // The figures the tables show; -1 where this driver does not report them.
    double instructions() const;
    double cycles() const; // the compiler's throughput bound (Mali only)
    double spills() const;
    double fills() const;
    // Registers: freedreno full and half, v3d max-temps, Midgard registers, nouveau gpr.
    double fullRegisters() const;
    double halfRegisters() const;
    double occupancy() const; // waves (freedreno) or threads (Mali, v3d) in flight
    // The unit with the largest cycle bound ("texture", "arith", "ls", ...), "" without units.
    std::string boundUnit() const;
    // The per-unit cycle figures this driver gives, in its own order.
    std::vector<std::pair<std::string, double>> unitCycles() const;
};

// Parses one debug message; nullopt when it is not a statistics line.
std::optional<StageStatistics> parseStatisticsLine(const std::string& message);

} // namespace pb::shaders
