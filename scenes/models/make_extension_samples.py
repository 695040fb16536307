#!/usr/bin/env python3
"""Writes small glTF models, one per glTF material extension that no shared sample asset shows,
for scenes/extensions.json and the tests that render it (CPU, and CPU against CUDA):

  sheen_cloth.gltf                a draped cloth, KHR_materials_sheen with a colour/roughness texture
  diffuse_transmission_leaf.gltf  a curled leaf, KHR_materials_diffuse_transmission
  anisotropic_disc.gltf           a circularly brushed metal lid, KHR_materials_anisotropy whose
                                  texture turns the direction about the centre
  iridescent_sphere.gltf          a dark sphere under a soap-bubble film, KHR_materials_iridescence
                                  with a film thickness texture varying from pole to pole
  dispersive_prism.gltf           a glass prism, KHR_materials_dispersion (Abbe number 20) with
                                  KHR_materials_transmission and _volume

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


def model(positions, normals, uvs, indices, material, extensions, images=None, tangents=None):
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
    if tangents:
        attributes["TANGENT"] = add(flat(tangents), "f", FLOAT, "VEC4", len(tangents))
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


def anisotropic_disc():
    # A flat disc of radius 0.5 in the XZ plane facing +Y, a fan of 64 triangles, its UVs a plan
    # view (u along +X, v along -Z) and its TANGENT +X (bitangent = normal x tangent = -Z, the
    # direction of increasing v).
    segments, radius = 64, 0.5
    positions, uvs = [(0.0, 0.0, 0.0)], [(0.5, 0.5)]
    for k in range(segments):
        a = 2.0 * math.pi * k / segments
        x, z = round(radius * math.cos(a), 6), round(radius * math.sin(a), 6)
        positions.append((x, 0.0, z))
        uvs.append((round(0.5 + 0.5 * x / radius, 6), round(0.5 - 0.5 * z / radius, 6)))
    normals = [(0.0, 1.0, 0.0)] * len(positions)
    tangents = [(1.0, 0.0, 0.0, 1.0)] * len(positions)
    indices = []
    for k in range(segments):
        indices += [0, 1 + (k + 1) % segments, 1 + k]  # counter-clockwise seen from +Y
    # The lid was brushed in circles: its grooves are concentric, so its roughness is raised
    # across them, along the radius (the extension stretches the highlight along its direction;
    # a point light draws a radial streak, as on a real pot lid). RG: the radial direction in
    # (tangent, bitangent) = (x, -z) / r, as (d + 1) / 2; B: the strength, faded to 0 at the centre
    # where the direction turns too fast for a texel.
    size = 32
    texels = []
    for j in range(size):
        row = []
        for i in range(size):
            x, z = (i + 0.5) / size * 2.0 - 1.0, 1.0 - (j + 0.5) / size * 2.0  # over the texel, / radius
            r = math.hypot(x, z)
            row.append((round(255 * (0.5 + 0.5 * x / r)), round(255 * (0.5 - 0.5 * z / r)),
                        round(255 * min(1.0, r / 0.1)), 255))
        texels.append(row)
    material = {
        "name": "brushed steel",
        "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.92, 1.0], "metallicFactor": 1.0,
                                 "roughnessFactor": 0.3},
        "doubleSided": True,
        "extensions": {"KHR_materials_anisotropy": {
            "anisotropyStrength": 0.8, "anisotropyTexture": {"index": 0}}},
    }
    write("anisotropic_disc.gltf", model(positions, normals, uvs, indices, material, ["KHR_materials_anisotropy"],
                                         [png_rgba(size, size, texels)], tangents))


def iridescent_sphere():
    # A UV sphere of radius 0.35 centred 0.35 above the origin (resting on y = 0): 24 segments
    # by 12 rings, normals radial, v from 0 at the top pole to 1 at the bottom one.
    segments, rings, radius = 24, 12, 0.35
    positions, normals, uvs = [], [], []
    for j in range(rings + 1):
        theta = math.pi * j / rings
        for i in range(segments + 1):
            phi = 2.0 * math.pi * i / segments
            n = (math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi))
            n = tuple(round(c, 6) + 0.0 for c in n)
            normals.append(n)
            positions.append((round(radius * n[0], 6), round(radius + radius * n[1], 6), round(radius * n[2], 6)))
            uvs.append((i / segments, j / rings))
    indices = []
    for j in range(rings):
        for i in range(segments):
            a = j * (segments + 1) + i
            b = a + segments + 1
            if j > 0:
                indices += [a, b, a + 1]
            if j < rings - 1:
                indices += [a + 1, b, b + 1]
    # The film's thickness, min + G * (max - min) nanometres: thin at the top, thick at the
    # bottom, so that bands of colour run round the sphere.
    height = 32
    texels = [[(0, round(255 * (j + 0.5) / height), 0, 255)] * 4 for j in range(height)]
    material = {
        "name": "soap film",
        "pbrMetallicRoughness": {"baseColorFactor": [0.02, 0.02, 0.025, 1.0], "metallicFactor": 0.0,
                                 "roughnessFactor": 0.25},
        "extensions": {"KHR_materials_iridescence": {
            "iridescenceFactor": 1.0, "iridescenceIor": 1.3, "iridescenceThicknessMinimum": 200,
            "iridescenceThicknessMaximum": 600, "iridescenceThicknessTexture": {"index": 0}}},
    }
    write("iridescent_sphere.gltf", model(positions, normals, uvs, indices, material,
                                          ["KHR_materials_iridescence"], [png_rgba(4, height, texels)]))


def dispersive_prism():
    # An upright prism 0.6 tall whose section is an equilateral triangle of side 0.4 (apex
    # towards -Z), standing on y = 0: flat faces, so each face has its own vertices.
    side, tall = 0.4, 0.6
    h = side * math.sqrt(3.0) / 2.0
    corners = [(0.0, -2.0 * h / 3.0), (-side / 2.0, h / 3.0), (side / 2.0, h / 3.0)]  # (x, z)
    positions, normals, uvs, indices = [], [], [], []

    def face(points, normal):
        base = len(positions)
        for p in points:
            positions.append(tuple(round(c, 6) for c in p))
            normals.append(tuple(round(c, 6) + 0.0 for c in normal))
            uvs.append((0.0, 0.0))
        for k in range(1, len(points) - 1):
            indices.extend([base, base + k, base + k + 1])
    face([(x, tall, z) for x, z in corners], (0.0, 1.0, 0.0))          # counter-clockwise from +Y
    face([(x, 0.0, z) for x, z in reversed(corners)], (0.0, -1.0, 0.0))
    for k in range(3):
        (x0, z0), (x1, z1) = corners[k], corners[(k + 1) % 3]
        nx, nz = z0 - z1, x1 - x0  # outward: the corners run counter-clockwise seen from +Y
        length = math.hypot(nx, nz)
        face([(x0, 0.0, z0), (x1, 0.0, z1), (x1, tall, z1), (x0, tall, z0)], (nx / length, 0.0, nz / length))
    material = {
        "name": "flint glass",
        "pbrMetallicRoughness": {"baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0,
                                 "roughnessFactor": 0.0},
        "extensions": {
            "KHR_materials_transmission": {"transmissionFactor": 1.0},
            "KHR_materials_volume": {"thicknessFactor": 0.35},
            "KHR_materials_ior": {"ior": 1.5},
            # dispersion = 20 / Abbe number: 1 is a dense flint glass (Abbe 20).
            "KHR_materials_dispersion": {"dispersion": 1.0}},
    }
    write("dispersive_prism.gltf", model(positions, normals, uvs, indices, material, [
        "KHR_materials_transmission", "KHR_materials_volume", "KHR_materials_ior", "KHR_materials_dispersion"]))


if __name__ == "__main__":
    sheen_cloth()
    diffuse_transmission_leaf()
    anisotropic_disc()
    iridescent_sphere()
    dispersive_prism()
