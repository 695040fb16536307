#!/usr/bin/env python3
"""Writes torus_knot.gltf + torus_knot.bin: a (2,3) torus knot tube, the mesh that
scenes/instances.json instances many times. Run from this folder; output is deterministic."""
import base64, json, math, struct

P, Q = 2, 3                 # knot winding numbers
SEGMENTS, SIDES = 256, 24   # along the knot, around the tube
TUBE = 0.12

def knot(t):
    r = 0.5 + 0.25 * math.cos(Q * t)
    return (r * math.cos(P * t), 0.25 * math.sin(Q * t), r * math.sin(P * t))

def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def cross(a, b): return (a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0])
def norm(a):
    l = math.sqrt(sum(x * x for x in a)); return tuple(x / l for x in a)

positions, normals, indices = [], [], []
for i in range(SEGMENTS):
    t = 2 * math.pi * i / SEGMENTS
    c, ahead = knot(t), knot(t + 1e-3)
    tangent = norm(sub(ahead, c))
    side = norm(cross(tangent, (0.0, 1.0, 0.0)))
    up = cross(side, tangent)
    for j in range(SIDES):
        a = 2 * math.pi * j / SIDES
        n = tuple(math.cos(a) * s + math.sin(a) * u for s, u in zip(side, up))
        positions.append(tuple(cc + TUBE * nn for cc, nn in zip(c, n)))
        normals.append(n)
for i in range(SEGMENTS):
    for j in range(SIDES):
        a = i * SIDES + j
        b = ((i + 1) % SEGMENTS) * SIDES + j
        c = ((i + 1) % SEGMENTS) * SIDES + (j + 1) % SIDES
        d = i * SIDES + (j + 1) % SIDES
        indices += [a, b, c, a, c, d]

pos_bytes = b"".join(struct.pack("<3f", *p) for p in positions)
nrm_bytes = b"".join(struct.pack("<3f", *n) for n in normals)
idx_bytes = b"".join(struct.pack("<I", i) for i in indices)
blob = pos_bytes + nrm_bytes + idx_bytes
lo = [min(p[k] for p in positions) for k in range(3)]
hi = [max(p[k] for p in positions) for k in range(3)]
gltf = {
    "asset": {"version": "2.0", "generator": "pathtracer scenes/models/make_torus_knot.py"},
    "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"name": "TorusKnot", "mesh": 0}],
    "meshes": [{"name": "TorusKnot", "primitives": [{
        "attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
    "materials": [{"name": "knot", "pbrMetallicRoughness": {
        "baseColorFactor": [0.8, 0.55, 0.2, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.4}}],
    "buffers": [{"uri": "torus_knot.bin", "byteLength": len(blob)}],
    "bufferViews": [
        {"buffer": 0, "byteOffset": 0, "byteLength": len(pos_bytes), "target": 34962},
        {"buffer": 0, "byteOffset": len(pos_bytes), "byteLength": len(nrm_bytes), "target": 34962},
        {"buffer": 0, "byteOffset": len(pos_bytes) + len(nrm_bytes), "byteLength": len(idx_bytes), "target": 34963}],
    "accessors": [
        {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3", "min": lo, "max": hi},
        {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
        {"bufferView": 2, "componentType": 5125, "count": len(indices), "type": "SCALAR"}],
}
open("torus_knot.bin", "wb").write(blob)
open("torus_knot.gltf", "w").write(json.dumps(gltf, indent=1) + "\n")
print(f"{len(indices) // 3} triangles, {len(positions)} vertices")
