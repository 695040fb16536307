#!/usr/bin/env python3
"""Writes the glTF and image fixtures of tests/assets/gltf_import_test.cpp and
image_read_test.cpp into this folder (and the PNG the OBJ fixtures use into ../obj).
Deterministic: rerunning it rewrites identical files. Python 3 standard library only.

Each fixture is small and made for one behaviour; the malformed ones break exactly one
thing, named in the comment above the function that writes it.

Usage: python3 tests/data/gltf/make_fixtures.py
"""
import base64
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
OBJ_DIR = os.path.join(HERE, "..", "obj")

FLOAT, U8, U16, U32, I16 = 5126, 5121, 5123, 5125, 5122
FORMATS = {FLOAT: "f", U8: "B", U16: "H", U32: "I", I16: "h"}
COMPONENTS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}

# A unit quad in the XY plane facing +Z, as two triangles.
QUAD_POSITIONS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
QUAD_NORMALS = [(0, 0, 1)] * 4
QUAD_UVS = [(0, 1), (1, 1), (1, 0), (0, 0)]
QUAD_INDICES = [0, 1, 2, 0, 2, 3]


# --- images -------------------------------------------------------------------------------

def png(width, height, rows, color_type=6, bit_depth=8):
    """rows: list of bytes objects, one per scanline (without the filter byte)."""
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))
    raw = b"".join(b"\x00" + row for row in rows)
    header = struct.pack(">IIBBBBB", width, height, bit_depth, color_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


# 2x2 RGBA: red, half-transparent green / fully transparent blue (its color must survive:
# straight alpha), white.
CHECKER = png(2, 2, [bytes([255, 0, 0, 255, 0, 255, 0, 128]),
                     bytes([0, 0, 255, 0, 255, 255, 255, 255])])
GRAY = png(2, 1, [bytes([0, 200])], color_type=0)
RGBA16 = png(1, 1, [struct.pack(">HHHH", 65535, 32896, 0, 65535)], bit_depth=16)


def rgbe(r, g, b):
    m = max(r, g, b)
    mantissa, exponent = math.frexp(m)
    scale = mantissa * 256.0 / m
    return bytes([int(r * scale), int(g * scale), int(b * scale), exponent + 128])


# Radiance HDR, 2x1, flat (uncompressed) scanline: (1, 0.5, 0.25) and (2, 4, 8), exact in RGBE.
TINY_HDR = (b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 2\n" +
            rgbe(1.0, 0.5, 0.25) + rgbe(2.0, 4.0, 8.0))
KTX2 = b"\xabKTX 20\xbb\r\n\x1a\n" + bytes(64)
BROKEN_PNG = CHECKER[:40]  # signature and IHDR, then the file stops


# --- glTF documents -------------------------------------------------------------------------

class Doc:
    def __init__(self):
        self.json = {"asset": {"version": "2.0", "generator": "make_fixtures.py"}}
        self.bin = bytearray()

    def add(self, key, item):
        self.json.setdefault(key, []).append(item)
        return len(self.json[key]) - 1

    def view(self, data, stride=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if stride:
            view["byteStride"] = stride
        self.bin += data
        return self.add("bufferViews", view)

    def accessor(self, values, ctype, kind, normalized=False, **extra):
        flat = [v for item in values for v in (item if isinstance(item, tuple) else (item,))]
        view = self.view(struct.pack("<%d%s" % (len(flat), FORMATS[ctype]), *flat))
        acc = {"bufferView": view, "componentType": ctype, "count": len(values), "type": kind}
        if normalized:
            acc["normalized"] = True
        if kind == "VEC3" and ctype == FLOAT and "min" not in extra:
            acc["min"] = [min(v[i] for v in values) for i in range(3)]
            acc["max"] = [max(v[i] for v in values) for i in range(3)]
        acc.update(extra)
        return self.add("accessors", acc)

    def quad_primitive(self, index_type=U16, material=None, uvs=True, normals=True):
        attributes = {"POSITION": self.accessor(QUAD_POSITIONS, FLOAT, "VEC3")}
        if normals:
            attributes["NORMAL"] = self.accessor(QUAD_NORMALS, FLOAT, "VEC3")
        if uvs:
            attributes["TEXCOORD_0"] = self.accessor(QUAD_UVS, FLOAT, "VEC2")
        primitive = {"attributes": attributes}
        if index_type is not None:
            primitive["indices"] = self.accessor(QUAD_INDICES, index_type, "SCALAR")
        if material is not None:
            primitive["material"] = material
        return primitive

    def mesh(self, primitives, name=None):
        mesh = {"primitives": primitives}
        if name:
            mesh["name"] = name
        return self.add("meshes", mesh)

    def node(self, **fields):
        return self.add("nodes", fields)

    def scene(self, nodes):
        self.json["scenes"] = [{"nodes": nodes}]
        self.json["scene"] = 0

    def finish_buffer(self, uri):
        while len(self.bin) % 4:
            self.bin.append(0)
        buffer = {"byteLength": len(self.bin)}
        if uri is not None:
            buffer["uri"] = uri
        self.json["buffers"] = [buffer]

    def save_gltf(self, name, embed=True):
        """embed: data-URI buffer; else an external <name>.bin next to it."""
        if embed:
            self.finish_buffer("data:application/octet-stream;base64," +
                               base64.b64encode(bytes(self.bin)).decode())
        else:
            bin_name = name.replace(".gltf", ".bin")
            self.finish_buffer(bin_name)
            write(bin_name, bytes(self.bin))
        write(name, json.dumps(self.json, indent=1).encode())

    def glb_bytes(self):
        self.finish_buffer(None)
        text = json.dumps(self.json).encode()
        text += b" " * (-len(text) % 4)
        chunks = (struct.pack("<II", len(text), 0x4E4F534A) + text +
                  struct.pack("<II", len(self.bin), 0x004E4942) + bytes(self.bin))
        return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def write(name, data, folder=HERE):
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def single_quad(index_type=U16, **node_fields):
    doc = Doc()
    doc.mesh([doc.quad_primitive(index_type)])
    doc.scene([doc.node(mesh=0, **node_fields)])
    return doc


# --- valid fixtures -----------------------------------------------------------------------

def materials_fixture():
    """Three primitives: every material feature, an empty material (glTF defaults), none
    (the default material). One image used with two samplers, one data-URI image."""
    doc = Doc()
    doc.json["extensionsUsed"] = [
        "KHR_materials_emissive_strength", "KHR_materials_ior", "KHR_materials_transmission",
        "KHR_materials_volume", "KHR_materials_clearcoat", "KHR_materials_specular",
        "KHR_texture_transform"]
    doc.json["images"] = [
        {"uri": "checker.png"},
        {"uri": "data:image/png;base64," + base64.b64encode(GRAY).decode()}]
    doc.json["samplers"] = [{"wrapS": 33071, "wrapT": 33648, "magFilter": 9728}, {}]
    doc.json["textures"] = [{"source": 0, "sampler": 0}, {"source": 0, "sampler": 1},
                            {"source": 1}]
    transform = {"KHR_texture_transform": {"offset": [0.1, 0.2], "scale": [2, 3],
                                           "rotation": 0.5}}
    doc.json["materials"] = [{
        "name": "Everything",
        "pbrMetallicRoughness": {
            "baseColorFactor": [0.5, 0.25, 0.125, 0.75], "metallicFactor": 0.3,
            "roughnessFactor": 0.6, "baseColorTexture": {"index": 0, "extensions": transform},
            "metallicRoughnessTexture": {"index": 1}},
        "normalTexture": {"index": 2, "scale": 0.7},
        "emissiveTexture": {"index": 0},
        "emissiveFactor": [1, 0.5, 0],
        "alphaMode": "MASK", "alphaCutoff": 0.3, "doubleSided": True,
        "extensions": {
            "KHR_materials_emissive_strength": {"emissiveStrength": 5},
            "KHR_materials_ior": {"ior": 1.33},
            "KHR_materials_transmission": {"transmissionFactor": 0.8,
                                           "transmissionTexture": {"index": 2}},
            "KHR_materials_volume": {"thicknessFactor": 0.2, "attenuationColor": [0.9, 0.8, 0.7],
                                     "attenuationDistance": 3},
            "KHR_materials_clearcoat": {"clearcoatFactor": 0.4, "clearcoatRoughnessFactor": 0.1},
            "KHR_materials_specular": {"specularFactor": 0.9,
                                       "specularColorFactor": [0.8, 0.7, 0.6]}}},
        {"name": "Defaults"}]
    doc.mesh([doc.quad_primitive(material=0), doc.quad_primitive(material=1),
              doc.quad_primitive()], name="ThreeSlots")
    doc.scene([doc.node(mesh=0, name="Quad")])
    doc.save_gltf("materials.gltf", embed=False)


def minimal_glb():
    """A .glb whose material's texture is a PNG inside a bufferView."""
    doc = Doc()
    doc.json["images"] = [{"bufferView": doc.view(CHECKER), "mimeType": "image/png"}]
    doc.json["textures"] = [{"source": 0}]
    doc.json["materials"] = [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]
    doc.mesh([doc.quad_primitive(material=0)])
    doc.scene([doc.node(mesh=0)])
    write("minimal.glb", doc.glb_bytes())


def shared_mesh():
    doc = Doc()
    doc.mesh([doc.quad_primitive()])
    doc.scene([doc.node(mesh=0, name="Left", translation=[-2, 0, 0]),
               doc.node(mesh=0, name="Right", translation=[2, 0, 0])])
    doc.save_gltf("shared_mesh.gltf")


def transforms():
    """A mirrored node, and a matrix node (rotate 90 degrees about Z, move (1, 2, 3)) with a
    TRS child (move +1 in x, scale 2)."""
    doc = Doc()
    doc.mesh([doc.quad_primitive()])
    mirrored = doc.node(mesh=0, name="Mirrored", scale=[-1, 1, 1])
    child = doc.node(mesh=0, name="Child", translation=[1, 0, 0], scale=[2, 2, 2])
    parent = doc.node(mesh=0, name="Matrix", children=[child],
                      matrix=[0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1])
    doc.scene([mirrored, parent])
    doc.save_gltf("transforms.gltf")


def index_types():
    doc = Doc()
    for i, (ctype, name) in enumerate([(U8, "u8"), (U16, "u16"), (U32, "u32")]):
        doc.mesh([doc.quad_primitive(ctype)], name=name)
        doc.node(mesh=i, name=name)
    doc.scene([0, 1, 2])
    doc.save_gltf("index_types.gltf")


def non_indexed_flat():
    """Two triangles as six loose vertices, no NORMAL: flat normals must be generated."""
    doc = Doc()
    positions = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 0), (0, 1, 0), (0, 0, -1)]
    doc.mesh([{"attributes": {"POSITION": doc.accessor(positions, FLOAT, "VEC3")}}])
    doc.scene([doc.node(mesh=0)])
    doc.save_gltf("non_indexed.gltf")


def topologies():
    """mesh 0: a strip of 5 vertices (3 triangles); mesh 1: a fan of 5 (3 triangles);
    mesh 2: POINTS, LINES and one TRIANGLES primitive."""
    doc = Doc()
    strip = [(0, 0, 0), (0, 1, 0), (1, 0, 0), (1, 1, 0), (2, 0, 0)]
    doc.mesh([{"attributes": {"POSITION": doc.accessor(strip, FLOAT, "VEC3")},
               "indices": doc.accessor([0, 1, 2, 3, 4], U16, "SCALAR"), "mode": 5}], "strip")
    fan = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (-1, 1, 0)]
    doc.mesh([{"attributes": {"POSITION": doc.accessor(fan, FLOAT, "VEC3")}, "mode": 6}], "fan")
    points = doc.accessor(QUAD_POSITIONS, FLOAT, "VEC3")
    doc.mesh([{"attributes": {"POSITION": points}, "mode": 0},
              {"attributes": {"POSITION": points}, "mode": 1},
              doc.quad_primitive()], "mixed")
    doc.scene([doc.node(mesh=0), doc.node(mesh=1), doc.node(mesh=2)])
    doc.save_gltf("topologies.gltf")


def cameras():
    """An orthographic camera node first (warned, skipped), then a perspective one at
    (0, 1, 5) turned 90 degrees about +Y (looking down -X)."""
    doc = Doc()
    doc.json["cameras"] = [
        {"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}},
        {"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}]
    s = math.sqrt(0.5)
    doc.mesh([doc.quad_primitive()])
    doc.scene([doc.node(camera=0), doc.node(camera=1, translation=[0, 1, 5],
                                            rotation=[0, s, 0, s]), doc.node(mesh=0)])
    doc.save_gltf("camera.gltf")


def uv_formats():
    """TEXCOORD_0 as floats, normalized unsigned bytes and normalized unsigned shorts."""
    doc = Doc()
    u8 = [(0, 255), (255, 255), (255, 0), (0, 0)]
    u16 = [(0, 65535), (65535, 65535), (65535, 0), (0, 0)]
    for i, (values, ctype) in enumerate([(QUAD_UVS, FLOAT), (u8, U8), (u16, U16)]):
        primitive = doc.quad_primitive(uvs=False)
        primitive["attributes"]["TEXCOORD_0"] = doc.accessor(values, ctype, "VEC2",
                                                             normalized=ctype != FLOAT)
        doc.mesh([primitive])
        doc.node(mesh=i)
    doc.scene([0, 1, 2])
    doc.save_gltf("uv_formats.gltf")


def sparse_positions():
    """POSITION is the quad with vertex 2 replaced by (5, 5, 5) through a sparse block."""
    doc = Doc()
    primitive = doc.quad_primitive()
    accessor = doc.json["accessors"][primitive["attributes"]["POSITION"]]
    accessor["sparse"] = {
        "count": 1,
        "indices": {"bufferView": doc.view(struct.pack("<H", 2)), "componentType": U16},
        "values": {"bufferView": doc.view(struct.pack("<3f", 5, 5, 5))}}
    accessor["max"] = [5, 5, 5]
    doc.mesh([primitive])
    doc.scene([doc.node(mesh=0)])
    doc.save_gltf("sparse.gltf")


def missing_image():
    """Two materials use one texture whose image file is missing: one warning, both fall back."""
    doc = Doc()
    doc.json["images"] = [{"uri": "does_not_exist.png"}]
    doc.json["textures"] = [{"source": 0}]
    doc.json["materials"] = [
        {"name": "A", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
        {"name": "B", "emissiveTexture": {"index": 0}, "emissiveFactor": [1, 1, 1]}]
    doc.mesh([doc.quad_primitive(material=0), doc.quad_primitive(material=1)])
    doc.scene([doc.node(mesh=0)])
    doc.save_gltf("missing_image.gltf")


def unsupported_extensions():
    doc = single_quad()
    doc.json["extensionsUsed"] = ["KHR_lights_punctual", "EXT_lights_image_based",
                                  "KHR_texture_transform"]
    doc.json["extensionsRequired"] = ["EXT_lights_image_based"]
    doc.save_gltf("unsupported_extensions.gltf")


def primitive_extensions():
    """A mesh of two quads: the first maps a material variant through KHR_materials_variants,
    an optional extension (so the quad keeps its default material, 0); the second is
    compressed with KHR_draco_mesh_compression, which the file requires (so it is skipped)."""
    doc = Doc()
    doc.json["materials"] = [{"name": "default"}, {"name": "variant red"}]
    variant = doc.quad_primitive(material=0)
    variant["extensions"] = {"KHR_materials_variants": {"mappings": [{"material": 1, "variants": [0]}]}}
    draco = doc.quad_primitive(material=0)
    draco["extensions"] = {"KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": 0}}}
    doc.mesh([variant, draco])
    doc.scene([doc.node(mesh=0)])
    doc.json["extensions"] = {"KHR_materials_variants": {"variants": [{"name": "red"}]}}
    doc.json["extensionsUsed"] = ["KHR_materials_variants", "KHR_draco_mesh_compression"]
    doc.json["extensionsRequired"] = ["KHR_draco_mesh_compression"]
    doc.save_gltf("primitive_extensions.gltf")


def material_variants():
    """KHR_materials_variants: variants "Leather" and "Linen" (and an unnamed third). Mesh 0
    has a seat (default material "seat", "leather" under Leather, "linen" under Linen) and a
    frame (default "frame", "gilt" under Linen; unmapped under Leather); two nodes place it.
    Mesh 1 (a second node) has no mapping. Broken mappings that must be ignored with a warning:
    a material index past the end, a variant index past the end, a mapping without variants.
    The emissive "glow" is what the third variant gives the frame."""
    doc = Doc()
    doc.json["materials"] = [
        {"name": "seat", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]}},
        {"name": "leather", "pbrMetallicRoughness": {"baseColorFactor": [0.4, 0.2, 0.1, 1]}},
        {"name": "linen", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.85, 0.7, 1]}},
        {"name": "frame", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.2, 0.2, 1]}},
        {"name": "gilt", "pbrMetallicRoughness": {"baseColorFactor": [1, 0.8, 0.3, 1], "metallicFactor": 1}},
        {"name": "glow", "emissiveFactor": [1, 1, 1]},
    ]
    seat = doc.quad_primitive(material=0)
    seat["extensions"] = {"KHR_materials_variants": {"mappings": [
        {"material": 1, "variants": [0]}, {"material": 2, "variants": [1, 7]},
        {"material": 9, "variants": [0]}, {"material": 4}]}}
    frame = doc.quad_primitive(material=3)
    frame["extensions"] = {"KHR_materials_variants": {"mappings": [
        {"material": 4, "variants": [1]}, {"material": 5, "variants": [2]}]}}
    doc.mesh([seat, frame], name="chair")
    doc.mesh([doc.quad_primitive(material=0)], name="cushion")
    doc.scene([doc.node(mesh=0, name="chair A"), doc.node(mesh=0, name="chair B", translation=[2, 0, 0]),
               doc.node(mesh=1, name="cushion")])
    doc.json["extensions"] = {"KHR_materials_variants": {"variants": [
        {"name": "Leather"}, {"name": "Linen"}, {"name": ""}]}}
    doc.json["extensionsUsed"] = ["KHR_materials_variants"]
    doc.save_gltf("variants.gltf")


def lights_fixture():
    """KHR_lights_punctual: a point light on a moved node, a spot under a parent turned to
    shine down (-90 degrees about X), a directional light turned 90 degrees about Y (shining
    along -X); and a quad with TANGENT (one non-unit tangent, one zero). bad_light_index.gltf
    names light 3 of 3."""
    s = math.sqrt(0.5)
    for name, light_index in (("lights.gltf", 1), ("bad_light_index.gltf", 3)):
        doc = Doc()
        doc.json["extensionsUsed"] = ["KHR_lights_punctual"]
        doc.json["extensions"] = {"KHR_lights_punctual": {"lights": [
            {"name": "bulb", "type": "point", "color": [1, 0.5, 0.25], "intensity": 40, "range": 10},
            {"type": "spot", "intensity": 100, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.6}},
            {"name": "sun", "type": "directional", "intensity": 3}]}}
        primitive = doc.quad_primitive()
        primitive["attributes"]["TANGENT"] = doc.accessor(
            [(2, 0, 0, -1), (1, 0, 0, -1), (0, 0, 0, 1), (1, 0, 0, -1)], FLOAT, "VEC4")
        doc.mesh([primitive])
        light = lambda index: {"KHR_lights_punctual": {"light": index}}
        quad = doc.node(mesh=0, name="Quad")
        bulb = doc.node(name="Bulb node", translation=[1, 2, 3], extensions=light(0))
        spot = doc.node(extensions=light(light_index))
        parent = doc.node(name="Spot parent", translation=[0, 5, 0], rotation=[-s, 0, 0, s], children=[spot])
        sun = doc.node(name="Sun node", rotation=[0, s, 0, s], extensions=light(2))
        doc.scene([quad, bulb, parent, sun])
        doc.save_gltf(name)


def no_scenes():
    """No scenes: every root node is shown (node 0 with child 1, and node 2)."""
    doc = Doc()
    doc.mesh([doc.quad_primitive()])
    doc.node(mesh=0, children=[1])
    doc.node(mesh=0, translation=[0, 0, 1])
    doc.node(mesh=0, translation=[0, 0, 2])
    doc.save_gltf("no_scenes.gltf")


# --- malformed fixtures: each breaks one thing ------------------------------------------

def malformed():
    # POSITION accessor 0 claims 5 vertices; its bufferView holds 4.
    doc = single_quad()
    doc.json["accessors"][0]["count"] = 5
    doc.save_gltf("accessor_past_view.gltf")

    # bufferViews[1] (NORMAL) starts 4 bytes before the end of the buffer.
    doc = single_quad()
    doc.json["bufferViews"][1]["byteOffset"] = len(doc.bin) - 4
    doc.save_gltf("view_past_buffer.gltf")

    # Index 7 with 4 vertices (element 5 of the indices accessor).
    doc = Doc()
    doc.mesh([{"attributes": {"POSITION": doc.accessor(QUAD_POSITIONS, FLOAT, "VEC3")},
               "indices": doc.accessor([0, 1, 2, 0, 2, 7], U16, "SCALAR")}])
    doc.scene([doc.node(mesh=0)])
    doc.save_gltf("index_past_vertex_count.gltf")

    # Vertex 2 of POSITION accessor 0 has a NaN (an infinite) y.
    for name, bad in [("nan_position.gltf", float("nan")), ("inf_position.gltf", float("inf"))]:
        doc = Doc()
        positions = list(QUAD_POSITIONS)
        positions[2] = (1, bad, 0)
        accessor = doc.accessor(positions, FLOAT, "VEC3", min=[0, 0, 0], max=[1, 1, 0])
        doc.mesh([{"attributes": {"POSITION": accessor},
                   "indices": doc.accessor(QUAD_INDICES, U16, "SCALAR")}])
        doc.scene([doc.node(mesh=0)])
        doc.save_gltf(name)

    # buffers[0].byteLength is 1e300 (a float, and absurdly large).
    doc = single_quad()
    doc.save_gltf("bytelength_1e300.gltf")
    data = json.loads(open(os.path.join(HERE, "bytelength_1e300.gltf")).read())
    data["buffers"][0]["byteLength"] = 1e300
    write("bytelength_1e300.gltf", json.dumps(data, indent=1).encode())

    # The buffer's .bin file does not exist.
    doc = single_quad()
    doc.finish_buffer("missing.bin")
    write("missing_bin.gltf", json.dumps(doc.json, indent=1).encode())

    # nodes 0 and 1 are each other's child.
    doc = single_quad()
    doc.json["nodes"][0]["children"] = [1]
    doc.node(children=[0])
    doc.save_gltf("node_cycle.gltf")

    # Out-of-range indices of each kind the brief lists.
    for name, edit in [
            ("bad_material_index.gltf", lambda j: j["meshes"][0]["primitives"][0].update(material=5)),
            ("bad_mesh_index.gltf", lambda j: j["nodes"][0].update(mesh=3)),
            ("bad_node_index.gltf", lambda j: j["scenes"][0].update(nodes=[0, 9])),
            ("bad_accessor_index.gltf",
             lambda j: j["meshes"][0]["primitives"][0]["attributes"].update(NORMAL=40)),
            ("bad_texture_index.gltf", lambda j: j.update(materials=[
                {"pbrMetallicRoughness": {"baseColorTexture": {"index": 9}}}]))]:
        doc = single_quad()
        edit(doc.json)
        doc.save_gltf(name)

    # Not JSON at all.
    write("bad_json.gltf", b'{"asset": {"version": "2.0"}, "nodes": [')

    glb = single_quad().glb_bytes()
    # The BIN chunk's length runs 8 bytes past the end of the file (tinygltf 2.7 would read
    # those 8 bytes).
    json_length = struct.unpack("<I", glb[12:16])[0]
    bin_header = 20 + json_length
    bin_length = struct.unpack("<I", glb[bin_header:bin_header + 4])[0]
    write("truncated.glb", glb[:bin_header] + struct.pack("<I", bin_length + 8) +
          glb[bin_header + 4:])

    # An image's bufferView runs past the end of the buffer (tinygltf 2.7 reads it unchecked).
    doc = Doc()
    doc.json["images"] = [{"bufferView": doc.view(CHECKER), "mimeType": "image/png"}]
    doc.mesh([doc.quad_primitive()])
    doc.scene([doc.node(mesh=0)])
    doc.finish_buffer(None)
    doc.json["bufferViews"][0]["byteOffset"] = 4096
    write("image_view_past_buffer.glb", doc.glb_bytes())


def images():
    write("checker.png", CHECKER)
    write("gray.png", GRAY)
    write("rgba16.png", RGBA16)
    write("tiny.hdr", TINY_HDR)
    write("fake.ktx2", KTX2)
    write("broken.png", BROKEN_PNG)
    write("checker.png", CHECKER, OBJ_DIR)


if __name__ == "__main__":
    images()
    materials_fixture()
    minimal_glb()
    shared_mesh()
    transforms()
    index_types()
    non_indexed_flat()
    topologies()
    cameras()
    uv_formats()
    sparse_positions()
    missing_image()
    unsupported_extensions()
    primitive_extensions()
    material_variants()
    lights_fixture()
    no_scenes()
    malformed()
