#!/usr/bin/env python3
"""Re-makes the hand-made probe-file regressions (tests/data/fuzz-regressions/probe_file/
*-handmade) from the cornell rgba16f seed after a probe-file format change.

Each regression is the seed with one field replaced by a value the reader must refuse (NaN,
infinity, a storage scale that is not a power of two). The fields are found by walking the
file's layout (renderer/probes/README.md, "File format"), so a new record moves the offsets
here, not by hand. The checksum is recomputed, so the bad value reaches its check.

    fuzz/make_probe_regressions.py tests/data/fuzz-seeds/probe_file/cornell_rgba16f.pbp \\
        tests/data/fuzz-regressions/probe_file
"""
import pathlib
import struct
import sys

EXPECTED_VERSION = 3  # renderer/probes/store/ProbeFile.h kProbeFileVersion


def field_offsets(b):
    """Byte offset of each field a regression patches, for a dense or sparse version-3 file."""
    version = struct.unpack_from("<I", b, 8)[0]
    if version != EXPECTED_VERSION:
        sys.exit(f"seed is probe file version {version}, this script knows {EXPECTED_VERSION}")
    # magic, version, size, input hash, format, rays, bounces, seed, relocate, threshold, tiles
    o = 8 + 4 + 8 + 8 + 4 + 4 + 4 + 8 + 1 + 4 + 4 + 4
    fields = {}

    def skip_string(o):
        return o + 4 + struct.unpack_from("<I", b, o)[0]

    volume_count = struct.unpack_from("<I", b, o)[0]
    o += 4
    probes = []
    for _ in range(volume_count):
        o = skip_string(skip_string(o))  # name, parent
        o += 12 + 16 + 12  # centre, rotation, half extents
        x, y, z = struct.unpack_from("<3i", b, o)
        probes.append(x * y * z)
        o += 12 + 4  # counts, edge blend
    scenario_count = struct.unpack_from("<I", b, o)[0]
    o += 4
    for s in range(scenario_count):
        o = skip_string(o)
        fields[f"scenario{s}.sun_intensity"] = o + 1 + 12 + 12
        o += 1 + 12 + 12 + 4 + 12  # sun on, direction, colour, intensity, sky
    for s in range(scenario_count):
        fields[f"scenario{s}.storage_scale"] = o
        o += 4
    for v, n in enumerate(probes):
        fields[f"volume{v}.states"] = o
        o += 17 * n  # offset vec3, back-face ratio, valid
    for v, n in enumerate(probes):  # storage record
        layout = b[o]
        o += 1
        if layout == 1:
            o += 4 + (n + 7) // 8
    for v in range(volume_count):
        o += 8 + struct.unpack_from("<Q", b, o)[0]  # visibility
    fields["irradiance0.0"] = o + 8
    return fields


def fnv1a64(data):
    h = 0xCBF29CE484222325
    for byte in data:
        h = ((h ^ byte) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h


def patched(seed, at, value):
    b = bytearray(seed)
    b[at : at + len(value)] = value
    b[-8:] = struct.pack("<Q", fnv1a64(b[:-8]))  # the checksum of every byte before it
    return bytes(b)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    seed = pathlib.Path(sys.argv[1]).read_bytes()
    out = pathlib.Path(sys.argv[2])
    f = field_offsets(seed)
    nan = struct.pack("<I", 0x7FC00000)
    regressions = {
        # A sun of infinite intensity (the scenario check).
        "inf-sun-intensity-handmade": (
            f["scenario0.sun_intensity"],
            struct.pack("<f", float("inf")),
        ),
        # Storage scales: NaN, and 3 (not a power of two).
        "nan-storage-scale-handmade": (f["scenario0.storage_scale"], nan),
        "three-storage-scale-handmade": (f["scenario1.storage_scale"], struct.pack("<f", 3.0)),
        # Probe 1 of volume 0: its relocation offset's x is NaN.
        "nan-probe-offset-handmade": (f["volume0.states"] + 17, nan),
        # The first irradiance texel's alpha as a half-float infinity (the stored-value check).
        "inf-stored-half-handmade": (f["irradiance0.0"] + 6, struct.pack("<H", 0x7C00)),
    }
    for name, (at, value) in regressions.items():
        (out / name).write_bytes(patched(seed, at, value))
        print(f"{out / name}: {len(value)} bytes at offset {at}")


if __name__ == "__main__":
    main()
