#!/usr/bin/env python3
"""Writes small glTF models, one per glTF material extension that no shared sample asset shows,
for scenes/extensions.json and the tests that render it (CPU, and CPU against CUDA):

  sheen_cloth.gltf                a draped cloth, KHR_materials_sheen with a colour/roughness texture
  diffuse_transmission_leaf.gltf  a curled leaf, KHR_materials_diffuse_transmission

Deterministic (rerunning rewrites identical files); Python 3 standard library only.
Usage: python3 scenes/models/make_extension_samples.py
"""
import base64
import json
import math
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
FLOAT, U16 = 5126, 5123


def png_rgba(width, height, pixels):
    """pixels: rows of (r, g, b, a) tuples, 8 bits each."""
    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))
    raw = b"".join(b"\x00" + bytes(v for p in row for v in p) for row in pixels)
    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def grid(nu, nv, surface):
    """A (nu+1) x (nv+1) vertex grid over [0,1]^2 mapped by surface(u, v) -> position; normals
    from central differences, two triangles a cell."""
    positions, normals, uvs = [], [], []
    e = 1e-4
    for j in range(nv + 1):
        for i in range(nu + 1):
            u, v = i / nu, j / nv
            p = surface(u, v)
            du = [a - b for a, b in zip(surface(u + e, v), surface(u - e, v))]
            dv = [a - b for a, b in zip(surface(u, v + e), surface(u, v - e))]
            n = (du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2], du[0] * dv[1] - du[1] * dv[0])
            length = math.sqrt(sum(c * c for c in n))
            positions.append(tuple(round(c, 6) for c in p))
            normals.append(tuple(round(c / length, 6) for c in n))
            uvs.append((u, v))
    indices = []
    for j in range(nv):
        for i in range(nu):
            a = j * (nu + 1) + i
            indices += [a, a + 1, a + nu + 2, a, a + nu + 2, a + nu + 1]
    return positions, normals, uvs, indices


def model(positions, normals, uvs, indices, material, extensions, images=None):
    binary = bytearray()
    views, accessors = [], []

    def add(values, fmt, ctype, kind, count, bounds=None):
        while len(binary) % 4:
            binary.append(0)
        data = struct.pack("<%d%s" % (len(values), fmt), *values)
        views.append({"buffer": 0, "byteOffset": len(binary), "byteLength": len(data)})
        binary.extend(data)
        accessor = {"bufferView": len(views) - 1, "componentType": ctype, "count": count, "type": kind}
        if bounds:
            accessor["min"], accessor["max"] = bounds
        accessors.append(accessor)
        return len(accessors) - 1

    flat = lambda items: [c for item in items for c in item]
    bounds = ([min(p[k] for p in positions) for k in range(3)], [max(p[k] for p in positions) for k in range(3)])
    attributes = {
        "POSITION": add(flat(positions), "f", FLOAT, "VEC3", len(positions), bounds),
        "NORMAL": add(flat(normals), "f", FLOAT, "VEC3", len(normals)),
        "TEXCOORD_0": add(flat(uvs), "f", FLOAT, "VEC2", len(uvs)),
    }
    index_accessor = add(indices, "H", U16, "SCALAR", len(indices))
    doc = {
        "asset": {"version": "2.0", "generator": "make_extension_samples.py"},
        "extensionsUsed": extensions,
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": material["name"]}],
        "meshes": [{"primitives": [{"attributes": attributes, "indices": index_accessor, "material": 0}]}],
        "materials": [material],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": len(binary),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(binary)).decode()}],
    }
    if images:
        doc["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(image).decode()} for image in images]
        doc["textures"] = [{"source": i} for i in range(len(images))]
    return doc


def write(name, doc):
    with open(os.path.join(HERE, name), "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


def sheen_cloth():
    # A 2 x 2 cloth draped in folds, 1 unit high at its middle.
    def surface(u, v):
        x, z = 2.0 * u - 1.0, 2.0 * v - 1.0
        y = 0.12 * math.sin(7.0 * x + 1.5 * z) + 0.35 * math.exp(-3.0 * (x * x + z * z))
        return (x, y, z)
    # Stripes: a pink sheen of roughness 0.3 across a blue one of roughness 0.8 (alpha channel).
    stripes = [[(255, 150, 200, 77) if (i // 2) % 2 == 0 else (120, 170, 255, 204) for i in range(8)]] * 8
    material = {
        "name": "velvet",
        "pbrMetallicRoughness": {"baseColorFactor": [0.08, 0.02, 0.05, 1.0], "metallicFactor": 0.0,
                                 "roughnessFactor": 0.9},
        "doubleSided": True,
        "extensions": {"KHR_materials_sheen": {
            "sheenColorFactor": [1.0, 1.0, 1.0], "sheenColorTexture": {"index": 0},
            "sheenRoughnessFactor": 1.0, "sheenRoughnessTexture": {"index": 0}}},
    }
    write("sheen_cloth.gltf", model(*grid(32, 32, surface), material, ["KHR_materials_sheen"],
                                    [png_rgba(8, 8, stripes)]))


def diffuse_transmission_leaf():
    # A leaf 1.2 long and 0.6 wide at its widest, curled about its midrib.
    def surface(u, v):
        s = 1.2 * u
        half_width = 0.3 * math.sin(math.pi * (0.02 + 0.96 * u)) ** 0.8  # pointed, not degenerate
        w = (2.0 * v - 1.0) * half_width
        return (w, s, 0.25 * w * w / 0.09 * 0.3 + 0.1 * math.sin(math.pi * u))
    material = {
        "name": "leaf",
        "pbrMetallicRoughness": {"baseColorFactor": [0.12, 0.3, 0.05, 1.0], "metallicFactor": 0.0,
                                 "roughnessFactor": 0.55},
        "doubleSided": True,
        "extensions": {"KHR_materials_diffuse_transmission": {
            "diffuseTransmissionFactor": 0.6, "diffuseTransmissionColorFactor": [0.55, 0.9, 0.2]}},
    }
    write("diffuse_transmission_leaf.gltf",
          model(*grid(24, 8, surface), material, ["KHR_materials_diffuse_transmission"]))


if __name__ == "__main__":
    sheen_cloth()
    diffuse_transmission_leaf()
