#pragma once
// Which instruction set Embree traces with. Embree 3 picks the best ISA of the CPU among the
// ones its build has (Debian 12's libembree3: SSE2, SSE4.2, AVX, AVX2, AVX-512), and its BVH
// layout and intersection arithmetic differ per ISA, so a bake may differ in the last bits
// between machines (bench/baselines/README.md has what was measured). PB_EMBREE_ISA pins it
// for tests and experiments (`PB_EMBREE_ISA=avx2 probebench bake ...`); the regression gate
// pins SSE2 (pinEmbreeIsa) so that its bake is the same bytes on every x86-64 CPU. On other
// architectures Embree keeps its own choice and these names do not apply.
#include <string>

namespace pb::raytrace {

// The ISAs PB_EMBREE_ISA accepts, in Embree's config spelling, from the oldest.
inline constexpr const char* kEmbreeIsas[] = {"sse2", "sse4.2", "avx", "avx2", "avx512"};

// The ISA every later Embree device of this process uses unless PB_EMBREE_ISA is set (an
// explicit experiment wins); "" lets Embree choose again. Call before any RayScene exists;
// throws like PB_EMBREE_ISA.
void pinEmbreeIsa(const std::string& isa);

// The rtcNewDevice config string: "" (Embree chooses) or "isa=<PB_EMBREE_ISA or pin>". Throws
// pb::Error "PB_EMBREE_ISA: ..." for a name Embree would not know (Embree itself falls back to
// SSE2 silently) or one this CPU cannot run.
std::string embreeDeviceConfig();

// The ISA Embree traces with in this process: PB_EMBREE_ISA when set, else the pin, else the
// best of kEmbreeIsas this CPU supports (what Embree 3's own selection gives with Debian's
// build); "native" on a CPU that is not x86.
std::string embreeIsa();

} // namespace pb::raytrace
