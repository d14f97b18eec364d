#!/usr/bin/env python3
"""Writes the committed seed corpus of the glTF, GLB and volume-TOML fuzzers (tests/data/fuzz-seeds/).

Small valid files that between them reach every part of the loaders: indexed and non-indexed
triangles, u8/u16/u32 indices, interleaved strides, KHR_mesh_quantization attributes, normals,
UVs, PNG and JPEG textures in bufferViews, materials with emissive strength, a node hierarchy with
TRS and matrices, cameras, KHR_lights_punctual, the dynamic flag, a line primitive (skipped)
and a sparse accessor (rejected). Probe-file seeds come from `probebench bake` (fuzz/run.sh).
Run from anywhere: python3 fuzz/make_seeds.py
"""
import json
import pathlib
import struct
import zlib

OUT = pathlib.Path(__file__).resolve().parent.parent / "tests" / "data" / "fuzz-seeds"


def tiny_png(width=2, height=2):
    raw = b"".join(b"\x00" + bytes([255, 128 * (y & 1), 64, 255]) * width for y in range(height))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    ihdr = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(raw))
            + chunk(b"IEND", b""))


# A 4x4 baseline JPEG (quality 50), written once by stb_image_write's stbi_write_jpg.
TINY_JPEG = bytes.fromhex(
    "ffd8ffe000104a46494600010100000100010000ffdb008400100b0c0e0c0a100e0d0e1211101318281a1816"
    "16183123251d283a333d3c3933383740485c4e404457453738506d51575f626768673e4d71797064785c6567"
    "63011112121815182f1a1a2f6342384263636363636363636363636363636363636363636363636363636363"
    "63636363636363636363636363636363636363636363ffc00011080004000403012200021101031101ffc401"
    "a20000010501010101010100000000000000000102030405060708090a0b1000020103030204030505040400"
    "00017d01020300041105122131410613516107227114328191a1082342b1c11552d1f02433627282090a1617"
    "18191a25262728292a3435363738393a434445464748494a535455565758595a636465666768696a73747576"
    "7778797a838485868788898a92939495969798999aa2a3a4a5a6a7a8a9aab2b3b4b5b6b7b8b9bac2c3c4c5c6"
    "c7c8c9cad2d3d4d5d6d7d8d9dae1e2e3e4e5e6e7e8e9eaf1f2f3f4f5f6f7f8f9fa0100030101010101010101"
    "010000000000000102030405060708090a0b1100020102040403040705040400010277000102031104052131"
    "061241510761711322328108144291a1b1c109233352f0156272d10a162434e125f11718191a262728292a35"
    "363738393a434445464748494a535455565758595a636465666768696a737475767778797a82838485868788"
    "898a92939495969798999aa2a3a4a5a6a7a8a9aab2b3b4b5b6b7b8b9bac2c3c4c5c6c7c8c9cad2d3d4d5d6d7"
    "d8d9dae2e3e4e5e6e7e8e9eaf2f3f4f5f6f7f8f9faffda000c03010002110311003f00d6b5f0de99e40fdc54"
    "dff08de99ff3c2b46d7fd40a9aa847ffd9")


class Doc:
    def __init__(self):
        self.bin = bytearray()
        self.doc = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": []}],
                    "nodes": [], "meshes": [], "accessors": [], "bufferViews": [],
                    "buffers": []}

    def view(self, data, stride=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        bv = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if stride:
            bv["byteStride"] = stride
        self.bin += data
        self.doc["bufferViews"].append(bv)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, view, ctype, count, kind, **extra):
        a = {"bufferView": view, "componentType": ctype, "count": count, "type": kind}
        a.update(extra)
        self.doc["accessors"].append(a)
        return len(self.doc["accessors"]) - 1

    def floats(self, values, kind):
        n = {"VEC2": 2, "VEC3": 3}[kind]
        data = struct.pack("<%df" % len(values), *values)
        extra = {}
        if kind == "VEC3":
            extra = {"min": [min(values[i::3]) for i in range(3)],
                     "max": [max(values[i::3]) for i in range(3)]}
        return self.accessor(self.view(data), 5126, len(values) // n, kind, **extra)

    def indices(self, idx, ctype=5123):
        fmt = {5121: "B", 5123: "H", 5125: "I"}[ctype]
        return self.accessor(self.view(struct.pack("<%d%s" % (len(idx), fmt), *idx)), ctype,
                             len(idx), "SCALAR")

    def mesh(self, primitives, name):
        self.doc["meshes"].append({"name": name, "primitives": primitives})
        return len(self.doc["meshes"]) - 1

    def node(self, node, root=True):
        self.doc["nodes"].append(node)
        i = len(self.doc["nodes"]) - 1
        if root:
            self.doc["scenes"][0]["nodes"].append(i)
        return i

    def gltf_with_bin(self):
        """The fuzz_gltf input format: JSON, a NUL byte, the .bin (named fuzz.bin)."""
        d = json.loads(json.dumps(self.doc))
        d["buffers"] = [{"byteLength": len(self.bin), "uri": "fuzz.bin"}]
        return json.dumps(d, separators=(",", ":")).encode() + b"\x00" + bytes(self.bin)

    def glb(self):
        d = json.loads(json.dumps(self.doc))
        d["buffers"] = [{"byteLength": len(self.bin)}]
        text = json.dumps(d, separators=(",", ":")).encode()
        text += b" " * (-len(text) % 4)
        binary = bytes(self.bin) + b"\x00" * (-len(self.bin) % 4)
        total = 12 + 8 + len(text) + 8 + len(binary)
        return (struct.pack("<III", 0x46546C67, 2, total) + struct.pack("<II", len(text), 0x4E4F534A)
                + text + struct.pack("<II", len(binary), 0x004E4942) + binary)


QUAD = [0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1]


def textured_scene():
    d = Doc()
    pos = d.floats(QUAD, "VEC3")
    nrm = d.floats([0, 1, 0] * 4, "VEC3")
    uv = d.floats([0, 0, 1, 0, 1, 1, 0, 1], "VEC2")
    idx = d.indices([0, 2, 1, 0, 3, 2])
    png, jpeg = d.view(tiny_png()), d.view(TINY_JPEG)
    d.doc["images"] = [{"bufferView": png, "mimeType": "image/png", "name": "checker"},
                       {"bufferView": jpeg, "mimeType": "image/jpeg", "name": "noise"}]
    d.doc["samplers"] = [{"magFilter": 9729}]
    d.doc["textures"] = [{"source": 0, "sampler": 0}, {"source": 1}]
    d.doc["extensionsUsed"] = ["KHR_materials_emissive_strength", "KHR_lights_punctual"]
    d.doc["materials"] = [{
        "name": "floor", "doubleSided": True, "alphaMode": "MASK", "alphaCutoff": 0.4,
        "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.7, 0.6, 1], "baseColorTexture": {"index": 0}},
        "emissiveFactor": [1, 0.5, 0.2], "emissiveTexture": {"index": 1},
        "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 3}}}]
    m = d.mesh([{"attributes": {"POSITION": pos, "NORMAL": nrm, "TEXCOORD_0": uv},
                 "indices": idx, "material": 0}], "floor")
    d.doc["cameras"] = [{"type": "perspective", "name": "cam",
                         "perspective": {"yfov": 0.9, "znear": 0.05, "aspectRatio": 1.5}}]
    d.doc["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"type": "directional", "name": "sun", "color": [1, 0.9, 0.8], "intensity": 3},
        {"type": "point", "name": "bulb", "intensity": 10, "range": 5},
        {"type": "spot", "name": "spot", "intensity": 20,
         "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}}]}}
    child = d.node({"name": "child", "mesh": m, "translation": [0, 0.5, 0], "scale": [0.5, 1, 0.5],
                    "extras": {"dynamic": True}}, root=False)
    lamp = d.node({"name": "lamp", "translation": [0.5, 2, 0.5],
                   "extensions": {"KHR_lights_punctual": {"light": 1}}}, root=False)
    d.node({"name": "root", "mesh": m, "children": [child, lamp],
            "rotation": [0, 0.3826834, 0, 0.9238795]})
    d.node({"name": "camera", "camera": 0, "translation": [0.5, 1, 3]})
    d.node({"name": "sun", "rotation": [-0.5, 0, 0, 0.8660254],
            "extensions": {"KHR_lights_punctual": {"light": 0}}})
    d.node({"name": "spot", "matrix": [1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0.5, 3, 0.5, 1],
            "extensions": {"KHR_lights_punctual": {"light": 2}}})
    return d


def quantized_scene():
    """KHR_mesh_quantization: normalised shorts/bytes, an interleaved strided view, u8 and
    u32 indices, a non-indexed primitive, a line primitive and a sparse accessor."""
    d = Doc()
    d.doc["extensionsUsed"] = ["KHR_mesh_quantization"]
    d.doc["extensionsRequired"] = ["KHR_mesh_quantization"]
    # interleaved: position i16x3 + pad (8 bytes), normal i8x3 + pad (4 bytes) -> stride 12
    verts = [(0, 0, 0), (32767, 0, 0), (32767, 0, 32767), (0, 0, 32767)]
    data = b"".join(struct.pack("<hhhh", *v, 0) + struct.pack("<bbbb", 0, 127, 0, 0) for v in verts)
    view = d.view(data, stride=12)
    pos = d.accessor(view, 5122, 4, "VEC3", normalized=True, min=[0, 0, 0], max=[1, 0, 1])
    nrm = d.accessor(view, 5120, 4, "VEC3", normalized=True, byteOffset=8)
    uv = d.accessor(d.view(struct.pack("<8H", 0, 0, 65535, 0, 65535, 65535, 0, 65535)), 5123, 4,
                    "VEC2", normalized=True)
    i8 = d.indices([0, 2, 1, 0, 3, 2], 5121)
    i32 = d.indices([0, 1, 2], 5125)
    plain = d.floats([0, 1, 0, 1, 1, 0, 0, 2, 0], "VEC3")
    sparse = d.accessor(d.view(struct.pack("<9f", *[0.0] * 9)), 5126, 3, "VEC3",
                        sparse={"count": 1,
                                "indices": {"bufferView": d.view(struct.pack("<H", 1) + b"\0\0"),
                                            "componentType": 5123},
                                "values": {"bufferView": d.view(struct.pack("<3f", 1, 2, 3))}})
    m0 = d.mesh([{"attributes": {"POSITION": pos, "NORMAL": nrm, "TEXCOORD_0": uv}, "indices": i8},
                 {"attributes": {"POSITION": pos}, "indices": i32},
                 {"attributes": {"POSITION": plain}},
                 {"attributes": {"POSITION": plain}, "mode": 1}], "quantized")
    d.node({"name": "q", "mesh": m0, "scale": [2, 2, 2]})
    d.node({"name": "s", "mesh": d.mesh([{"attributes": {"POSITION": sparse}}], "sparse")})
    return d


def minimal_scene():
    d = Doc()
    d.node({"mesh": d.mesh([{"attributes": {"POSITION": d.floats([0, 0, 0, 1, 0, 0, 0, 1, 0],
                                                                  "VEC3")}}], "tri")})
    return d


def write(name, data):
    path = OUT / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(data)


def main():
    textured, quantized, minimal = textured_scene(), quantized_scene(), minimal_scene()
    write("gltf/textured.gltfbin", textured.gltf_with_bin())
    write("gltf/minimal.gltfbin", minimal.gltf_with_bin())
    # The sparse accessor is rejected; a copy without it loads.
    write("gltf/quantized_sparse.gltfbin", quantized.gltf_with_bin())
    quantized.doc["scenes"][0]["nodes"] = [0]
    write("gltf/quantized.gltfbin", quantized.gltf_with_bin())
    write("glb/textured.glb", textured.glb())
    write("glb/quantized.glb", quantized.glb())
    write("glb/minimal.glb", minimal.glb())
    write("volume_toml/nested.toml", b"""\
[[volume]]
name = "world"
center = [0.0, 2.5, 0.0]
half_extents = [8.0, 2.5, 4.0]
probes = [9, 4, 5]

[[volume]]
name = "room"
parent = "world"
center = [2.0, 1.5, 0.0]
half_extents = [2.0, 1.0, 2.0]
probes = [5, 3, 5]
rotation = [0.0, 30.0, 0.0]
edge_blend = 0.5

[[volume]]
name = "tilted"
center = [0.0, 1.0, 20.0]
half_extents = [1.0, 1.0, 1.0]
probes = [1, 2, 3]
quaternion = [0.0, 0.382683, 0.0, 0.92388]

[[scenario]]
name = "dusk"
sun = { direction = [-0.8, 0.25, 0.2], intensity = 1.5, color = [1.0, 0.55, 0.3] }
sky = [0.08, 0.06, 0.09]

[[scenario]]
name = "dark"
sun = "off"
""")
    write("volume_toml/single.toml",
          b'[[volume]]\nname = "v"\ncenter = [0, 0, 0]\nhalf_extents = [1, 1, 1]\nprobes = [2, 2, 2]\n')


if __name__ == "__main__":
    main()
