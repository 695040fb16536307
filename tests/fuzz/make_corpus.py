#!/usr/bin/env python3
"""Writes the seed corpus of the fuzz targets (tests/fuzz/corpus/<target>/) from the project's
own files: scenes/ and tests/data/. Deterministic: rerunning it rewrites identical files.
Python 3 standard library only.

Each target loads one file with nothing beside it (fuzz_load.h), so glTF seeds get their
external buffers and images inlined as data URIs, and OBJ seeds carry their MTL text with
"mtllib model.mtl" (fuzz_obj.cpp reads the input as both files).

With --shared DIR, seeds derived from the shared sample assets (../shared/assets, whose
licenses are not the project's) are written to DIR instead, for fuzzing locally; they are
never committed. Small assets are inlined whole; large ones are skipped.

Usage: python3 tests/fuzz/make_corpus.py [--shared DIR]
"""
import base64
import glob
import hashlib
import json
import os
import re
import shutil
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
DATA = os.path.join(ROOT, "tests", "data")
MAX_INLINED = 64 * 1024  # bytes of one external file inlined into a glTF seed
MAX_SEED = 96 * 1024     # a seed larger than this is left out


def read(path):
    with open(path, "rb") as f:
        return f.read()


def write_seeds(folder, seeds):
    """seeds: {name: bytes}. Replaces the folder's contents."""
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    for name, data in sorted(seeds.items()):
        if len(data) <= MAX_SEED:
            with open(os.path.join(folder, name), "wb") as f:
                f.write(data)


def data_uri(path):
    mime = {".png": "image/png", ".jpg": "image/jpeg", ".jpeg": "image/jpeg"}.get(
        os.path.splitext(path)[1].lower(), "application/octet-stream")
    return "data:%s;base64,%s" % (mime, base64.b64encode(read(path)).decode())


def inline_gltf(path):
    """The .gltf's text with every external buffer and image that exists and is small
    inlined as a data URI; others stay as they are (and will be missing)."""
    try:
        doc = json.loads(read(path))
    except ValueError:
        return read(path)  # malformed on purpose: keep it byte for byte
    for key in ("buffers", "images"):
        for entry in doc.get(key, []) if isinstance(doc.get(key), list) else []:
            uri = entry.get("uri") if isinstance(entry, dict) else None
            if not isinstance(uri, str) or uri.startswith("data:"):
                continue
            external = os.path.join(os.path.dirname(path), uri)
            if os.path.isfile(external) and os.path.getsize(external) <= MAX_INLINED:
                entry["uri"] = data_uri(external)
    return json.dumps(doc, separators=(",", ":")).encode()


def obj_with_mtl(path):
    """The OBJ's text with its MTL files' text appended and every mtllib naming model.mtl."""
    text = read(path)
    mtl = b""
    for line in text.splitlines():
        if line.startswith(b"mtllib"):
            for name in line.split()[1:]:
                mtl_path = os.path.join(os.path.dirname(path), name.decode())
                if os.path.isfile(mtl_path):
                    mtl += b"\n" + read(mtl_path)
    text = re.sub(rb"(?m)^mtllib .*$", b"mtllib model.mtl", text)
    return text + mtl


def seed_name(path, base=ROOT):
    return os.path.relpath(path, base).replace(os.sep, "_")


def image_seeds(paths, base=ROOT):
    return {seed_name(p, base): read(p) for p in paths}


def pfm(magic, width, height, scale, values):
    order = "<" if scale < 0 else ">"
    header = b"%s\n%d %d\n%g\n" % (magic, width, height, scale)
    return header + struct.pack(order + "%df" % len(values), *values)


def project_seeds():
    gltf = sorted(glob.glob(os.path.join(DATA, "gltf", "*.gltf")) +
                  glob.glob(os.path.join(DATA, "json", "models", "*.gltf")) +
                  glob.glob(os.path.join(ROOT, "scenes", "**", "*.gltf"), recursive=True))
    glb = sorted(glob.glob(os.path.join(DATA, "gltf", "*.glb")))
    objs = sorted(glob.glob(os.path.join(DATA, "**", "*.obj"), recursive=True) +
                  glob.glob(os.path.join(ROOT, "scenes", "**", "*.obj"), recursive=True))
    scenes = sorted(glob.glob(os.path.join(ROOT, "scenes", "**", "*.json"), recursive=True) +
                    glob.glob(os.path.join(DATA, "json", "**", "*.json"), recursive=True))
    images = sorted(p for ext in ("png", "hdr", "tga", "bmp", "ktx2")
                    for p in glob.glob(os.path.join(DATA, "**", "*." + ext), recursive=True))
    # One file per distinct content: tests/data holds the same checker.png three times.
    unique_images = {}
    for p in images:
        unique_images.setdefault(hashlib.sha1(read(p)).hexdigest(), p)
    images = sorted(unique_images.values())
    ramp = [i / 11.0 for i in range(12)]
    return {
        "fuzz_gltf": {**{seed_name(p): inline_gltf(p) for p in gltf},
                      **{seed_name(p): read(p) for p in glb}},
        "fuzz_obj": {seed_name(p): obj_with_mtl(p) for p in objs},
        "fuzz_scene_json": {seed_name(p): read(p) for p in scenes},
        "fuzz_image": image_seeds(images),
        "fuzz_pfm": {
            "rgb_little.pfm": pfm(b"PF", 2, 2, -1.0, ramp),
            "rgb_big.pfm": pfm(b"PF", 2, 2, 1.0, ramp),
            "gray_little.pfm": pfm(b"Pf", 3, 2, -1.0, ramp[:6]),
            "gray_big.pfm": pfm(b"Pf", 2, 3, 2.0, ramp[6:]),
        },
    }


def shared_seeds(assets):
    """Seeds from the shared assets: small glTF/GLB files (external files inlined), the
    Cornell box OBJ's MTL, and small images. Files over MAX_SEED are left out."""
    files = sorted(glob.glob(os.path.join(assets, "**", "*"), recursive=True))
    def small(p, ext):
        return p.lower().endswith(ext) and os.path.getsize(p) <= MAX_SEED
    return {
        "fuzz_gltf": {**{seed_name(p, assets): inline_gltf(p) for p in files if small(p, ".gltf")},
                      **{seed_name(p, assets): read(p) for p in files if small(p, ".glb")}},
        "fuzz_obj": {seed_name(p, assets): read(p) for p in files if small(p, ".mtl")},
        "fuzz_image": image_seeds((p for p in files if small(p, ".png") or small(p, ".jpeg")), assets),
    }


def main():
    if len(sys.argv) == 3 and sys.argv[1] == "--shared":
        out = sys.argv[2]
        assets = os.path.join(ROOT, "..", "shared", "assets")
        for target, seeds in shared_seeds(assets).items():
            write_seeds(os.path.join(out, target), seeds)
        return
    if len(sys.argv) != 1:
        sys.exit(__doc__)
    for target, seeds in project_seeds().items():
        write_seeds(os.path.join(HERE, "corpus", target), seeds)


if __name__ == "__main__":
    main()
