#pragma once

namespace pb {

// Makes the C allocator keep large freed blocks in the process for the next allocation,
// instead of handing them back to the kernel. Call once, first thing in main().
//
// Why: a bake allocates and frees probe textures of tens to hundreds of MiB, and the
// placement's lattice search bakes up to 22 trial sets in a row. glibc serves every block over
// its mmap threshold (128 KiB to 32 MiB, adapting) with a fresh mapping and unmaps it on free,
// so each trial page-faults and the kernel zeroes all of its memory again. On the 2-core VM
// that was about 40% of a default `bake --scene courtyard` (13.7 s -> 6.8 s wall with this; the
// output is byte-identical, studies/results/2026-11-29-allocator-reuse.md). The cost: the
// process keeps its peak heap until it exits, and a block that fits no freed hole takes new
// memory: peak RSS +4% on that bake, +2% on Sponza's.
//
// This covers the main thread's heap. Worker threads allocate from arenas of their own, which
// still map and unmap blocks of tens of MiB; HugePages.h keeps those of its arrays.
//
// glibc only (mallopt); elsewhere, and under AddressSanitizer's allocator, a no-op.
void reuseFreedMemory();

} // namespace pb
