#!/usr/bin/env python3
"""Independent count of what importGltf should produce for a glTF file, for the expected
values hard-coded in tests/assets/gltf_import_test.cpp. Reads only the JSON (never the
importer's code): walks the default scene (else scene 0, else all root nodes), and for each
node with a mesh adds one placement and the triangles of its primitives (TRIANGLES: count/3,
strips and fans: count-2, points and lines: 0, where count is the index accessor's count or
else the POSITION accessor's). Materials and textures are counted as the importer adds them:
once per glTF material used by a reached primitive (plus one default material when a
primitive has none), and once per (image, wrapS, wrapT, magFilter) referenced by the
imported slots of those materials.

Usage: count_gltf_facts.py FILE.gltf|FILE.glb ...
"""
import json
import struct
import sys

SLOTS = [("pbrMetallicRoughness", "baseColorTexture"),
         ("pbrMetallicRoughness", "metallicRoughnessTexture"),
         (None, "normalTexture"), (None, "emissiveTexture"),
         ("extensions/KHR_materials_transmission", "transmissionTexture"),
         ("extensions/KHR_materials_diffuse_transmission", "diffuseTransmissionTexture"),
         ("extensions/KHR_materials_diffuse_transmission", "diffuseTransmissionColorTexture"),
         ("extensions/KHR_materials_sheen", "sheenColorTexture"),
         ("extensions/KHR_materials_sheen", "sheenRoughnessTexture"),
         ("extensions/KHR_materials_anisotropy", "anisotropyTexture"),
         ("extensions/KHR_materials_iridescence", "iridescenceTexture"),
         ("extensions/KHR_materials_iridescence", "iridescenceThicknessTexture")]


def load(path):
    data = open(path, "rb").read()
    if data[:4] == b"glTF":
        length = struct.unpack("<I", data[12:16])[0]
        return json.loads(data[20:20 + length])
    return json.loads(data)


def roots(doc):
    scenes = doc.get("scenes", [])
    if scenes:
        return scenes[doc.get("scene", 0)].get("nodes", [])
    children = {c for n in doc.get("nodes", []) for c in n.get("children", [])}
    return [i for i in range(len(doc.get("nodes", []))) if i not in children]


def triangles(doc, primitive):
    count = doc["accessors"][primitive["indices"] if "indices" in primitive
                             else primitive["attributes"]["POSITION"]]["count"]
    mode = primitive.get("mode", 4)
    return count // 3 if mode == 4 else max(count - 2, 0) if mode in (5, 6) else 0


def texture_keys(doc, material):
    keys = set()
    for parent, slot in SLOTS:
        holder = material
        for part in (parent.split("/") if parent else []):
            holder = holder.get(part, {})
        if slot in holder:
            texture = doc["textures"][holder[slot]["index"]]
            sampler = doc.get("samplers", [])[texture["sampler"]] if "sampler" in texture else {}
            keys.add((texture.get("source"), sampler.get("wrapS", 10497),
                      sampler.get("wrapT", 10497), sampler.get("magFilter", 9729)))
    return keys


def facts(path):
    doc = load(path)
    placements = tris = 0
    materials, textures, stack = set(), set(), list(roots(doc))
    while stack:
        node = doc["nodes"][stack.pop()]
        stack.extend(node.get("children", []))
        if "mesh" not in node:
            continue
        placements += 1
        for primitive in doc["meshes"][node["mesh"]]["primitives"]:
            tris += triangles(doc, primitive)
            materials.add(primitive.get("material", "default"))
    for m in materials - {"default"}:
        textures |= texture_keys(doc, doc["materials"][m])
    images = doc.get("images", [])
    undecodable = {k for k in textures if images[k[0]].get("uri", "").endswith(".ktx2")}
    return dict(placements=placements, triangles=tris, materials=len(materials),
                textures=len(textures - undecodable), undecodable_images=len(
                    {k[0] for k in undecodable}), meshes=len(doc.get("meshes", [])),
                nodes=len(doc.get("nodes", [])))


if __name__ == "__main__":
    for p in sys.argv[1:]:
        print(p, facts(p))
