#!/usr/bin/env python3
"""Writes the skin and animation fixtures of tests/assets/gltf/gltf_animation_test.cpp
(anim_*.gltf and skin_*.gltf in this folder), reusing the glTF writer of make_fixtures.py.
Deterministic; Python 3 standard library only.

Usage: python3 tests/data/gltf/animation_fixtures.py
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_fixtures import FLOAT, U8, Doc  # noqa: E402

IDENTITY = (1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1)


def animated_quad(name, times, translations, interpolation="LINEAR"):
    """A quad whose node 0 is moved by a translation channel."""
    doc = Doc()
    doc.mesh([doc.quad_primitive()])
    sampler = {"input": doc.accessor(times, FLOAT, "SCALAR", min=[min(times)], max=[max(times)]),
               "output": doc.accessor(translations, FLOAT, "VEC3"), "interpolation": interpolation}
    doc.add("animations", {"name": "slide", "samplers": [sampler],
                           "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]})
    doc.scene([doc.node(mesh=0)])
    doc.save_gltf(name)


def skinned_quad(name, joints, weights, joint_count=2, lift=None):
    """A quad (node 0) skinned by `joint_count` joints (nodes 1..), with JOINTS_0/WEIGHTS_0 per
    vertex as given; `lift` (times, translations) adds an animation "lift" moving joint 1."""
    doc = Doc()
    primitive = doc.quad_primitive()
    primitive["attributes"]["JOINTS_0"] = doc.accessor(joints, U8, "VEC4")
    primitive["attributes"]["WEIGHTS_0"] = doc.accessor(weights, FLOAT, "VEC4")
    doc.mesh([primitive])
    joint_nodes = [doc.node(translation=[0, i, 0]) for i in range(joint_count)]
    doc.add("skins", {"joints": joint_nodes,
                      "inverseBindMatrices": doc.accessor([IDENTITY] * joint_count, FLOAT, "MAT4")})
    if lift:
        times, translations = lift
        sampler = {"input": doc.accessor(times, FLOAT, "SCALAR", min=[min(times)], max=[max(times)]),
                   "output": doc.accessor(translations, FLOAT, "VEC3"), "interpolation": "LINEAR"}
        doc.add("animations", {"name": "lift", "samplers": [sampler],
                               "channels": [{"sampler": 0, "target": {"node": joint_nodes[1], "path": "translation"}}]})
    doc.scene([doc.node(mesh=0, skin=0)] + joint_nodes)
    doc.save_gltf(name)


if __name__ == "__main__":
    # The quad slides one unit along x in the first second (pt-render render --frames).
    animated_quad("anim_slide.gltf", [0, 1], [(0, 0, 0), (1, 0, 0)])
    # The third key time goes back: animations[0].samplers[0] is refused.
    animated_quad("anim_bad_times.gltf", [0, 1, 0.5], [(0, 0, 0), (1, 0, 0), (2, 0, 0)])
    # Vertex 2 is weighted on joint 3 of a two-joint skin.
    skinned_quad("skin_bad_joint.gltf", [(0, 0, 0, 0), (0, 0, 0, 0), (3, 0, 0, 0), (1, 0, 0, 0)],
                 [(1, 0, 0, 0)] * 4)
    # Every vertex half on each joint but the last, whose weights sum to 0.5: normalised with
    # one warning. Joint 1 rests one unit up (its inverse bind matrix is the identity), so the
    # skin lifts a vertex by its weight on joint 1.
    skinned_quad("skin_weights.gltf", [(0, 1, 0, 0)] * 4,
                 [(0.5, 0.5, 0, 0)] * 3 + [(0.25, 0.25, 0, 0)])
    # Every vertex half on each joint; "lift" raises joint 1 from one unit up to two in a
    # second, so the quad rises from half a unit to one (the editor's timeline tests).
    skinned_quad("skin_lift.gltf", [(0, 1, 0, 0)] * 4, [(0.5, 0.5, 0, 0)] * 4,
                 lift=([0, 1], [(0, 1, 0), (0, 2, 0)]))
