#!/usr/bin/env python3
"""Writes the morph target fixtures of tests/assets/gltf_morph_test.cpp (morph_*.gltf in this
folder), reusing the glTF writer of make_fixtures.py. Deterministic: rerunning it rewrites
identical files. Python 3 standard library only. Every value is small and exact in binary so
that the tests can state expected positions computed by hand.

Usage: python3 tests/data/gltf/morph_fixtures.py
"""
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_fixtures import FLOAT, U16, Doc, QUAD_INDICES, QUAD_NORMALS, QUAD_POSITIONS  # noqa: E402

ZERO = (0, 0, 0)


def sparse_deltas(doc, count, index, value):
    """A VEC3 accessor without a bufferView (all zero) but for element `index` = `value`."""
    return doc.add("accessors", {
        "componentType": FLOAT, "count": count, "type": "VEC3",
        "sparse": {
            "count": 1,
            "indices": {"bufferView": doc.view(struct.pack("<H", index)), "componentType": U16},
            "values": {"bufferView": doc.view(struct.pack("<3f", *value))}}})


def vec3s(doc, values):
    return doc.accessor(values, FLOAT, "VEC3")


def lit_quad(doc, targets):
    """The unit quad of make_fixtures.py (POSITION, NORMAL, indices) with `targets`."""
    return {"attributes": {"POSITION": vec3s(doc, QUAD_POSITIONS),
                           "NORMAL": vec3s(doc, QUAD_NORMALS)},
            "indices": doc.accessor(QUAD_INDICES, U16, "SCALAR"),
            "targets": targets}


def morph_quad():
    """Mesh "MorphQuad", weights [0.25, 0], targets named "Lift" and "Slide":
    primitives[0]: the unit quad with normals. Lift raises vertices 2, 3 by z = 2 and tilts
      their normals by (0, -1, 0); Slide (a sparse accessor) moves vertex 1 by x = 0.5 and has
      a TANGENT delta, which is ignored without a warning.
    primitives[1]: the quad moved to x = 2, no NORMAL, so flat normals unshare its corners
      [0, 1, 2, 0, 2, 3] into six vertices. Lift raises its vertex 0 by z = 1 (and has NORMAL
      deltas, dropped: there are no normals to move); Slide moves its vertex 3 by x = 1.
    primitives[2]: a triangle at y = 2 with normals and no targets: zero deltas."""
    doc = Doc()
    lift = {"POSITION": vec3s(doc, [ZERO, ZERO, (0, 0, 2), (0, 0, 2)]),
            "NORMAL": vec3s(doc, [ZERO, ZERO, (0, -1, 0), (0, -1, 0)])}
    slide = {"POSITION": sparse_deltas(doc, 4, 1, (0.5, 0, 0)),
             "TANGENT": vec3s(doc, [(1, 0, 0)] * 4)}
    flat = {"attributes": {"POSITION": vec3s(doc, [(x + 2, y, z) for x, y, z in QUAD_POSITIONS])},
            "indices": doc.accessor(QUAD_INDICES, U16, "SCALAR"),
            "targets": [
                {"POSITION": vec3s(doc, [(0, 0, 1), ZERO, ZERO, ZERO]),
                 "NORMAL": vec3s(doc, [(1, 0, 0)] * 4)},
                {"POSITION": vec3s(doc, [ZERO, ZERO, ZERO, (1, 0, 0)])}]}
    still = {"attributes": {"POSITION": vec3s(doc, [(0, 2, 0), (1, 2, 0), (0, 3, 0)]),
                            "NORMAL": vec3s(doc, [(0, 0, 1)] * 3)}}
    doc.add("meshes", {"name": "MorphQuad", "weights": [0.25, 0],
                       "extras": {"targetNames": ["Lift", "Slide"]},
                       "primitives": [lit_quad(doc, [lift, slide]), flat, still]})
    doc.scene([doc.node(mesh=0)])
    doc.save_gltf("morph_quad.gltf")


def morph_nodes():
    """Mesh "Shared" (one unnamed target raising every vertex by z = 1, weights [0]) used by
    three nodes: nodes[0] with weights [1] (the pose the mesh takes), nodes[1] with [0.5] and
    nodes[2] with none (the mesh's [0]): both warned about. The target also has a TEXCOORD_0
    delta, which glTF does not define for targets: warned about and ignored."""
    doc = Doc()
    target = {"POSITION": vec3s(doc, [(0, 0, 1)] * 4),
              "TEXCOORD_0": doc.accessor([(0, 0)] * 4, FLOAT, "VEC2")}
    doc.add("meshes", {"name": "Shared", "weights": [0], "primitives": [lit_quad(doc, [target])]})
    doc.scene([doc.node(mesh=0, weights=[1]), doc.node(mesh=0, weights=[0.5]), doc.node(mesh=0)])
    doc.save_gltf("morph_nodes.gltf")


def malformed_quad(name, targets=None, mesh_weights=None, node_weights=None, second=None):
    """One broken thing on a quad whose targets are `targets(doc)`; `second(doc)` adds a
    second primitive."""
    doc = Doc()
    primitives = [lit_quad(doc, targets(doc))]
    if second:
        primitives.append(second(doc))
    mesh = {"primitives": primitives}
    if mesh_weights is not None:
        mesh["weights"] = mesh_weights
    doc.add("meshes", mesh)
    node = {"mesh": 0}
    if node_weights is not None:
        node["weights"] = node_weights
    doc.scene([doc.node(**node)])
    doc.save_gltf(name)


def one_target(doc):
    return [{"POSITION": vec3s(doc, [(0, 0, 1)] * 4)}]


def two_targets(doc):
    return one_target(doc) + one_target(doc)


def malformed():
    # targets[1].POSITION has 3 elements for the primitive's 4 vertices.
    malformed_quad("morph_bad_count.gltf", lambda doc: one_target(doc) + [
        {"POSITION": vec3s(doc, [(0, 0, 1)] * 3)}])
    # targets[0].POSITION is a VEC2 accessor.
    malformed_quad("morph_bad_type.gltf", lambda doc: [
        {"POSITION": doc.accessor([(0, 0)] * 4, FLOAT, "VEC2")}])
    # targets[0].NORMAL element 1 is NaN.
    malformed_quad("morph_nan.gltf", lambda doc: [
        {"NORMAL": doc.accessor([ZERO, (float("nan"), 0, 0), ZERO, ZERO], FLOAT, "VEC3",
                                min=[0, 0, 0], max=[0, 0, 0])}])
    # primitives[1] has one target where primitives[0] has two.
    malformed_quad("morph_target_mismatch.gltf", two_targets,
                   second=lambda doc: lit_quad(doc, one_target(doc)))
    # meshes[0].weights has three weights for two targets.
    malformed_quad("morph_bad_weights.gltf", two_targets, mesh_weights=[0, 0, 0])
    # nodes[0].weights has two weights for one target.
    malformed_quad("morph_bad_node_weights.gltf", one_target, node_weights=[1, 2])


if __name__ == "__main__":
    morph_quad()
    morph_nodes()
    malformed()
