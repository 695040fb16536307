// End-to-end tests of `pt-render gen`: the generated files are read back through the real
// loader (and byte by byte where the glTF spec says what they must hold).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <unordered_map>

#include "app/cli_runner.h"
#include "assets/image/image_write.h"
#include "render/scene/morph.h"
#include "render/scene/scene_animation.h"
#include "support/load_scene.h"
#include "support/test_paths.h"
#include "support/vertex_distance.h"

namespace pt {
namespace {

namespace fs = std::filesystem;
using test::runCli;

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

nlohmann::json infoJson(const std::string& path) {
    const auto r = runCli("info '" + path + "' --json");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return r.exitCode == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

// A fresh folder per test, so files of one test never stand in for another's.
std::string folder(const std::string& name) {
    const std::string dir = test::tempDir() + "/" + name;
    fs::create_directories(dir);
    return dir;
}

// Every edge used once in each direction: closed, two triangles per edge, consistent winding.
void expectClosedAndConsistent(const Mesh& mesh) {
    std::unordered_map<uint64_t, int> directed;
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        for (int k = 0; k < 3; ++k) {
            const uint64_t a = mesh.indices[i + size_t(k)], b = mesh.indices[i + size_t(k + 1) % 3];
            ++directed[a << 32 | b];
        }
    }
    size_t bad = 0;
    for (const auto& [edge, uses] : directed) {
        const auto reverse = directed.find((edge & 0xffffffffu) << 32 | edge >> 32);
        if (uses != 1 || reverse == directed.end() || reverse->second != 1) ++bad;
    }
    EXPECT_EQ(bad, 0u) << "edges not shared by exactly two consistently wound triangles";
    // A closed genus-0 surface with no duplicate vertices: V - E + F = 2.
    const int64_t euler =
        int64_t(mesh.positions.size()) - int64_t(directed.size() / 2) + int64_t(mesh.indices.size() / 3);
    EXPECT_EQ(euler, 2);
}

TEST(GenCommand, SphereHasTheStatedTriangleCount) {
    const std::string out = folder("count") + "/s.gltf";
    const auto r = runCli("gen sphere -o " + out + " --triangles 20000 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::istringstream lines(r.out);
    std::string gltf, bin;
    uint64_t stated = 0;
    lines >> gltf >> bin >> stated;
    EXPECT_EQ(gltf, out);
    EXPECT_EQ(bin, fs::path(out).replace_extension(".bin").string());
    EXPECT_EQ(stated, 12u * 41u * 41u);  // the cube-sphere count nearest 20,000
    const nlohmann::json info = infoJson(out);
    EXPECT_EQ(info["triangles"], stated);
    EXPECT_EQ(info["meshes"], 1);
    EXPECT_EQ(info["instances"], 1);
    EXPECT_EQ(info["punctual_lights"], 2);
    EXPECT_EQ(info["warnings"], 0);
}

TEST(GenCommand, SphereIsClosedDisplacedWithinAmplitudeAndNormalsPointOut) {
    const std::string out = folder("closed") + "/s.gltf";
    const double amplitude = 0.15;
    const auto r = runCli("gen sphere -o " + out + " --triangles 20000 --displace 0.15 --seed 3 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Scene scene = test::loadSceneOrFail(out);
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    expectClosedAndConsistent(mesh);

    float lo = 1e30f, hi = 0.0f;
    size_t notUnit = 0, inward = 0;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const float radius = length(mesh.positions[v]);
        lo = std::min(lo, radius);
        hi = std::max(hi, radius);
        notUnit += std::abs(length(mesh.normals[v]) - 1.0f) > 1e-4f;
        inward += !(dot(mesh.normals[v], mesh.positions[v]) > 0.0f);
    }
    EXPECT_GE(lo, 1.0 - amplitude - 1e-5);
    EXPECT_LE(hi, 1.0 + amplitude + 1e-5);
    EXPECT_GT(hi - lo, 0.5 * amplitude) << "the noise should visibly displace the sphere";
    EXPECT_EQ(notUnit, 0u);
    EXPECT_EQ(inward, 0u);

    // Triangles face outward, and the smooth normals are those of the displaced surface (a
    // sign error in the noise's slope would tilt them away from the facets).
    double volume = 0.0, agreement = 0.0;
    size_t facingIn = 0;
    const size_t triangles = mesh.indices.size() / 3;
    for (size_t t = 0; t < triangles; ++t) {
        const uint32_t* i = &mesh.indices[3 * t];
        const Vec3 a = mesh.positions[i[0]], b = mesh.positions[i[1]], c = mesh.positions[i[2]];
        const Vec3 facet = cross(b - a, c - a);
        volume += dot(a, cross(b, c)) / 6.0;
        facingIn += !(dot(facet, a + b + c) > 0.0f);
        agreement +=
            dot(normalize(facet), normalize(mesh.normals[i[0]] + mesh.normals[i[1]] + mesh.normals[i[2]]));
    }
    EXPECT_EQ(facingIn, 0u);
    EXPECT_NEAR(volume, 4.0 / 3.0 * 3.14159265, 0.6);
    EXPECT_GT(agreement / double(triangles), 0.999);  // 0.99994 here; 0.985 with the slope's sign flipped
}

// The skinned column loads as a rig whose rest pose is its bind pose, sways under its
// animation with its foot (weighted wholly to the unanimated root joint) in place, and loops.
TEST(GenCommand, SkinnedColumnLoadsAsARigThatSwaysAndLoops) {
    const std::string out = folder("skinned") + "/column.gltf";
    const auto r = runCli("gen skinned -o " + out + " --triangles 5000 --joints 6 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("6 joints, animation \"sway\""), std::string::npos) << r.out;
    Scene scene = test::loadSceneOrFail(out);
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    ASSERT_EQ(scene.rigs.size(), 1u);
    const AnimationRig& rig = scene.rigs[0];
    ASSERT_EQ(rig.skins.size(), 1u);
    EXPECT_EQ(rig.skins[0].joints.size(), 6u);
    ASSERT_EQ(rig.animations.size(), 1u);
    EXPECT_EQ(rig.animations[0].name, "sway");
    EXPECT_FLOAT_EQ(rig.animations[0].duration(), 2.0f);
    ASSERT_EQ(rig.skinnedMeshes.size(), 1u);
    const SkinnedMesh& skinned = rig.skinnedMeshes[0];
    const std::vector<Vec3>& p = scene.meshes[skinned.mesh].positions;
    ASSERT_EQ(p.size(), skinned.bindPositions.size());
    EXPECT_LT(test::largestDistance(p, skinned.bindPositions), 1e-5f) << "the rest pose is the bind pose";

    const auto pose = [&](float time) {
        poseAnimations(scene, {0}, time);
        return scene.meshes[skinned.mesh].positions;
    };
    const std::vector<Vec3> start = pose(0.0f), quarter = pose(0.5f), end = pose(2.0f);
    float footMoved = 0.0f, topMoved = 0.0f;
    for (size_t v = 0; v < p.size(); ++v) {
        const float y = skinned.bindPositions[v].y, moved = length(quarter[v] - start[v]);
        if (y < -3.0f) footMoved = std::max(footMoved, moved);
        if (y > 3.0f) topMoved = std::max(topMoved, moved);
    }
    EXPECT_EQ(footMoved, 0.0f);
    EXPECT_GT(topMoved, 0.5f);
    EXPECT_LT(test::largestDistance(end, start), 1e-4f) << "the animation loops";
}

// The POSITION accessor, and the morph target's (which the spec holds to the same bounds).
TEST(GenCommand, BufferMatchesTheAccessorsAndPositionBounds) {
    const std::string out = folder("accessors") + "/s.gltf";
    ASSERT_EQ(runCli("gen sphere -o " + out + " --triangles 3000 --seed 5 --morph --quiet").exitCode, 0);
    const nlohmann::json doc = nlohmann::json::parse(slurp(out));
    const std::string bin = slurp(fs::path(out).replace_extension(".bin").string());
    ASSERT_EQ(doc["buffers"].size(), 1u);
    EXPECT_EQ(doc["buffers"][0]["uri"], "s.bin");
    EXPECT_EQ(doc["buffers"][0]["byteLength"].get<size_t>(), bin.size());
    const nlohmann::json& primitive = doc["meshes"][0]["primitives"][0];
    const auto expectExactBounds = [&](const nlohmann::json& position, const std::string& what) {
        const nlohmann::json& view = doc["bufferViews"][position["bufferView"].get<size_t>()];
        const size_t count = position["count"], offset = view.value("byteOffset", 0u);
        ASSERT_LE(offset + count * 12, bin.size()) << what;
        std::vector<float> xyz(count * 3);
        std::memcpy(xyz.data(), bin.data() + offset,
                    count * 12);  // the file is little-endian, as is this host
        for (int axis = 0; axis < 3; ++axis) {
            float lo = xyz[size_t(axis)], hi = lo;
            for (size_t v = 0; v < count; ++v) {
                lo = std::min(lo, xyz[3 * v + size_t(axis)]);
                hi = std::max(hi, xyz[3 * v + size_t(axis)]);
            }
            // Exact, as the spec asks.
            EXPECT_EQ(position["min"][axis].get<float>(), lo) << what << " axis " << axis;
            EXPECT_EQ(position["max"][axis].get<float>(), hi) << what << " axis " << axis;
        }
    };
    expectExactBounds(doc["accessors"][primitive["attributes"]["POSITION"].get<size_t>()], "POSITION");
    ASSERT_EQ(primitive["targets"].size(), 1u);
    expectExactBounds(doc["accessors"][primitive["targets"][0]["POSITION"].get<size_t>()], "target POSITION");
}

// --morph: one target "bulge" at weight 0 that, at weight 1, pushes every vertex outward along
// its radius by up to 15% (the usage's figure) of its distance from the centre: all of that at
// the equator, none at the poles. Without --morph the mesh has no targets.
TEST(GenCommand, MorphGivesTheSphereOneBulgeTarget) {
    const std::string dir = folder("morph");
    // 12 x 12^2 triangles: the cube-sphere's r = 12 is even, so vertices lie on the equator
    // and at the poles.
    const auto r = runCli("gen sphere -o " + dir + "/m.gltf --triangles 1728 --seed 4 --morph --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("morph target \"bulge\""), std::string::npos) << r.out;
    Scene scene = test::loadSceneOrFail(dir + "/m.gltf");
    EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
    ASSERT_EQ(scene.meshes.size(), 1u);
    Mesh& mesh = scene.meshes[0];
    EXPECT_TRUE(hasMorphTargets(mesh));
    ASSERT_EQ(mesh.morphTargets.size(), 1u);
    EXPECT_EQ(mesh.morphTargets[0].name, "bulge");
    ASSERT_EQ(mesh.morphWeights, std::vector<float>{0.0f});
    EXPECT_EQ(mesh.defaultMorphWeights, std::vector<float>{0.0f});
    ASSERT_EQ(mesh.basePositions.size(), mesh.positions.size());
    EXPECT_EQ(test::largestDistance(mesh.positions, mesh.basePositions), 0.0f) << "weight 0: undeformed";

    mesh.morphWeights[0] = 1.0f;
    applyMorphWeights(mesh);
    constexpr float kBulge = 0.15f;
    float largest = 0.0f, nearestPoleMoved = -1.0f, nearestPoleUp = -1.0f;
    size_t tooFar = 0, notOutward = 0;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const Vec3 base = mesh.basePositions[v], moved = mesh.positions[v] - base;
        const Vec3 radial = normalize(base);
        const float fraction = length(moved) / length(base);
        largest = std::max(largest, fraction);
        tooFar += fraction > kBulge * (1.0f + 1e-5f);
        notOutward += dot(moved, radial) < 0.0f || length(cross(moved, radial)) > 1e-5f;
        if (radial.y > nearestPoleUp) {
            nearestPoleUp = radial.y;
            nearestPoleMoved = length(moved);
        }
    }
    EXPECT_EQ(tooFar, 0u) << "largest offset " << largest << " of the radius";
    EXPECT_EQ(notOutward, 0u);
    EXPECT_NEAR(largest, kBulge, 1e-5f) << "the equator swells by the whole bulge";
    EXPECT_GT(nearestPoleUp, 0.99999f);
    EXPECT_EQ(nearestPoleMoved, 0.0f) << "the pole stays";

    ASSERT_EQ(runCli("gen sphere -o " + dir + "/plain.gltf --triangles 1728 --quiet").exitCode, 0);
    const Scene plain = test::loadSceneOrFail(dir + "/plain.gltf");
    ASSERT_EQ(plain.meshes.size(), 1u);
    EXPECT_FALSE(hasMorphTargets(plain.meshes[0]));
    EXPECT_TRUE(plain.meshes[0].morphWeights.empty());
}

TEST(GenCommand, SameSeedGivesIdenticalFilesAndAnotherSeedDifferentOnes) {
    const std::string a = folder("seed-a") + "/s.gltf", b = folder("seed-b") + "/s.gltf",
                      c = folder("seed-c") + "/s.gltf";
    ASSERT_EQ(runCli("gen sphere -o " + a + " --triangles 5000 --seed 7 --quiet").exitCode, 0);
    ASSERT_EQ(runCli("gen sphere -o " + b + " --triangles 5000 --seed 7 --quiet").exitCode, 0);
    ASSERT_EQ(runCli("gen sphere -o " + c + " --triangles 5000 --seed 8 --quiet").exitCode, 0);
    auto bin = [](const std::string& gltf) {
        return slurp(fs::path(gltf).replace_extension(".bin").string());
    };
    EXPECT_EQ(slurp(a), slurp(b));
    EXPECT_EQ(bin(a), bin(b));
    EXPECT_NE(bin(a), bin(c));

    const std::string fa = folder("field-a") + "/f.gltf", fb = folder("field-b") + "/f.gltf",
                      fc = folder("field-c") + "/f.gltf";
    ASSERT_EQ(runCli("gen field -o " + fa + " --count 50 --seed 7 --quiet").exitCode, 0);
    ASSERT_EQ(runCli("gen field -o " + fb + " --count 50 --seed 7 --quiet").exitCode, 0);
    ASSERT_EQ(runCli("gen field -o " + fc + " --count 50 --seed 8 --quiet").exitCode, 0);
    EXPECT_EQ(slurp(fa), slurp(fb));
    EXPECT_EQ(bin(fa), bin(fb));
    EXPECT_NE(slurp(fa), slurp(fc));
}

TEST(GenCommand, FieldIsManyInstancesOfOneMesh) {
    const std::string out = folder("field") + "/f.gltf";
    const auto r = runCli("gen field -o " + out + " --count 500 --seed 2 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("500 instances"), std::string::npos) << r.out;
    const nlohmann::json info = infoJson(out);
    EXPECT_EQ(info["meshes"], 1);
    EXPECT_EQ(info["instances"], 500);
    EXPECT_EQ(info["unique_triangles"], 12 * 9 * 9);  // the default mesh: about 1,000 triangles
    EXPECT_EQ(info["triangles"], 500 * 12 * 9 * 9);

    const Scene scene = test::loadSceneOrFail(out);
    ASSERT_EQ(scene.instances.size(), 500u);
    std::set<float> rotations, scales;
    for (const Instance& instance : scene.instances) {
        EXPECT_EQ(instance.mesh, 0u);
        rotations.insert(instance.objectToWorld.rows[0].y);
        scales.insert(std::abs(instance.objectToWorld.determinant()));
    }
    EXPECT_GT(rotations.size(), 450u) << "each instance gets its own rotation";
    EXPECT_GT(scales.size(), 450u) << "each instance gets its own scale";

    // The camera sees the whole field, and the field fills most of the view.
    Vec3 lo, hi;
    scene.worldBounds(lo, hi);
    const Camera& camera = scene.camera;
    const Vec3 forward = normalize(camera.lookAt - camera.position);
    const Vec3 right = normalize(cross(forward, camera.up)), up = cross(right, forward);
    const float tanHalf = std::tan(0.5f * camera.verticalFovDegrees * 3.14159265f / 180.0f);
    float widest = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p{corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z};
        const float depth = dot(p - camera.position, forward);
        ASSERT_GT(depth, 0.0f) << "corner " << corner << " behind the camera";
        const float spread =
            std::max(std::abs(dot(p - camera.position, right)), std::abs(dot(p - camera.position, up)));
        EXPECT_LE(spread / depth, tanHalf * 1.0001f) << "corner " << corner << " out of view";
        widest = std::max(widest, spread / depth);
    }
    EXPECT_GT(widest, 0.8f * tanHalf) << "the field is framed, not a speck in the middle";
}

// A source file's placements are baked into the one mesh: a mirrored node keeps its facets
// facing along its normals, and every placed copy is kept.
TEST(GenCommand, FieldMergesTheMeshesOfASourceFile) {
    const std::string source = test::testDataPath("gltf/transforms.gltf");
    const Scene original = test::loadSceneOrFail(source);
    const std::string out = folder("merge") + "/f.gltf";
    const auto r = runCli("gen field -o " + out + " --count 30 --mesh '" + source + "' --spacing 5 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const Scene field = test::loadSceneOrFail(out);
    ASSERT_EQ(field.meshes.size(), 1u);
    EXPECT_EQ(field.instances.size(), 30u);
    const Mesh& mesh = field.meshes[0];
    EXPECT_EQ(mesh.indices.size() / 3, original.triangleCount());
    Vec3 lo, hi;
    original.worldBounds(lo, hi);
    Vec3 mlo = mesh.positions[0], mhi = mlo;
    for (const Vec3& p : mesh.positions) {
        mlo = vmin(mlo, p);
        mhi = vmax(mhi, p);
    }
    EXPECT_LT(length(mlo - lo) + length(mhi - hi), 1e-5f);
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const Vec3 a = mesh.positions[mesh.indices[i]], b = mesh.positions[mesh.indices[i + 1]],
                   c = mesh.positions[mesh.indices[i + 2]];
        EXPECT_GT(dot(cross(b - a, c - a), mesh.normals[mesh.indices[i]]), 0.0f) << "triangle " << i / 3;
    }
}

TEST(GenCommand, NamesThatNeedEscapingStillLoad) {
    const std::string out = folder("escape") + "/my sphere+1.gltf";
    const auto r = runCli("gen sphere -o '" + out + "' --triangles 100 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(folder("escape") + "/my sphere+1.bin"));
    EXPECT_EQ(test::loadSceneOrFail(out).triangleCount(), 12u * 3u * 3u);
}

TEST(GenCommand, RendersLitAndFramed) {
    PT_REQUIRE_OIIO();  // renders to EXR
    const std::string dir = folder("render");
    ASSERT_EQ(runCli("gen sphere -o " + dir + "/s.gltf --triangles 2000 --quiet").exitCode, 0);
    const auto r = runCli("render " + dir + "/s.gltf -o " + dir + "/s.exr --spp 2 --size 32x32 --quiet");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    uint32_t w = 0, h = 0;
    const std::vector<float> rgba = readImageRgba(dir + "/s.exr", w, h);
    ASSERT_EQ(rgba.size(), size_t(32 * 32 * 4));
    auto pixel = [&](uint32_t x, uint32_t y) {
        const float* p = &rgba[(size_t(y) * w + x) * 4];
        return p[0] + p[1] + p[2];
    };
    EXPECT_GT(pixel(16, 16), 0.05f) << "the sphere in the middle is lit";
    EXPECT_EQ(pixel(0, 0), 0.0f) << "the corners see past the sphere (no environment)";
}

TEST(GenCommand, BadUsageExits2AndBadInputExits1WithOneLine) {
    const std::string dir = folder("errors");
    const std::string out = " -o " + dir + "/x.gltf";
    struct Case {
        std::string args;
        int code;
        std::string needle;
    };
    const Case cases[] = {
        {"gen sphere --triangles 100", 2, "-o OUT.gltf"},
        {"gen sphere" + out, 2, "--triangles"},
        {"gen sphere" + out + " --triangles 0", 2, "--triangles"},
        {"gen sphere" + out + " --triangles 10000001", 2, "--triangles"},
        {"gen sphere" + out + " --triangles 100 --displace 1.5", 2, "--displace"},
        {"gen sphere" + out + " --triangles 100 --count 3", 2, "--count"},
        {"gen sphere -o " + dir + "/x.glb --triangles 100", 2, ".gltf"},
        {"gen field" + out + " --count 1000001", 2, "--count"},
        {"gen field" + out + " --count 0", 2, "--count"},
        {"gen field" + out + " --count 5 --spacing -1", 2, "--spacing"},
        {"gen field" + out + " --count 5 --triangles 9", 2, "--triangles"},
        {"gen cube" + out, 2, "cube"},
        {"gen", 2, "sphere, skinned or field"},
        {"gen skinned" + out + " --triangles 100 --joints 1", 2, "--joints"},
        {"gen skinned" + out, 2, "--triangles"},
        {"gen field" + out + " --count 5 --mesh /nonexistent/m.gltf", 1, "/nonexistent/m.gltf"},
        {"gen field" + out + " --count 5 --mesh '" + test::testDataPath("gltf/bad_json.gltf") + "'", 1,
         "bad_json.gltf"},
        {"gen sphere -o /nonexistent-dir/x.gltf --triangles 10", 1, "/nonexistent-dir"},
    };
    for (const Case& c : cases) {
        const auto r = runCli(c.args);
        EXPECT_EQ(r.exitCode, c.code) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << "\nstderr: " << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << "\nstderr: " << r.err;
    }
    EXPECT_FALSE(fs::exists(dir + "/x.gltf")) << "nothing is written on error";
}

}  // namespace
}  // namespace pt
