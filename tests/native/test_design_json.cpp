// The design file (io/design_json.hpp): round trip with unknown fields kept, every bad field refused with a
// message naming it (or defaulted with a warning when not strict), the parts the app's worker reads by the same
// rules, 3D seam points projected onto the target (and refused far from it), targets from examples, files and
// inline meshes; and the CLI commands built on it (billow check, segment, design).
#include <gtest/gtest.h>
#include <unistd.h>

#include <climits>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "io/design_json.hpp"
#include "io/mesh_file.hpp"
#include "io/pattern_json.hpp"
#include "pattern/design_scene.hpp"
#include "simulate/materials.hpp"
#include "test_support.hpp"
#include "util/error.hpp"

using namespace billow;
using billow::test::dataPath;
using billow::test::examplesDir;
using nlohmann::json;

namespace {

json minimal() {
  return json::parse(R"({"format": "billow-design", "version": 1, "target": {"example": "sphere"},
    "size": {"height": 0.5}, "seams": [{"closed": true, "points": [[1, 0, 0], [-0.5, 0, 0.8], [-0.5, 0, -0.8]]}],
    "material": {"thickness": 2.5e-5, "youngs_modulus": 3e9}, "pressure": 1000})");
}

// Reading `doc` strictly fails with `code`, and the message mentions `words`.
void expectRefused(const json& doc, const std::string& code, const std::string& words) {
  try {
    readDesignJson(doc.dump());
    ADD_FAILURE() << "accepted: " << doc.dump();
  } catch (const Error& e) {
    EXPECT_EQ(e.code, code) << doc.dump();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

json with(json doc, const json::json_pointer& where, const json& value) {
  doc[where] = value;
  return doc;
}

}  // namespace

TEST(DesignJson, FixtureRoundTripKeepsEveryFieldAndUnknownOnes) {
  json doc = json::parse(readFileBytes(dataPath("sphere-gores.billow.json")));
  doc["seams"][1]["color"] = "#ff8800";  // unknown fields, at the top and inside a seam
  // A gusset band's record (web/src/app/band.js): the CLI reads the seam as any other and keeps the record.
  doc["seams"][0]["band"] = {{"id", 1},        {"part", "side 1"},    {"kind", "section"},
                             {"width_mm", 40}, {"normal", {0, 1, 0}}, {"origin", {1, 0, 0}}};
  doc["app"] = {{"camera", {1, 2, 3}}};
  const Design a = readDesignJson(doc.dump());
  ASSERT_EQ(a.seams.size(), 3u);
  EXPECT_EQ(a.target.kind, DesignTarget::Obj);
  EXPECT_EQ(a.target.name, "../../web/public/examples/sphere.obj");
  EXPECT_DOUBLE_EQ(a.height, 0.5);
  EXPECT_TRUE(a.seams[0].points[0].onSurface);
  EXPECT_EQ(a.seams[0].points[0].surface.face, 20);
  EXPECT_FALSE(a.seams[0].points[1].onSurface);
  EXPECT_EQ(a.seams[2].name, "meridian 3");
  // The band is known as one (the distance's hints ask a gusseted balloon for a wider gusset), the others not.
  EXPECT_TRUE(a.seams[0].band);
  EXPECT_FALSE(a.seams[1].band);
  const std::string text = writeDesignJson(a);
  const Design b = readDesignJson(text);
  EXPECT_EQ(writeDesignJson(b), text);
  const json back = json::parse(text);
  EXPECT_EQ(back["seams"][1]["color"], "#ff8800");
  EXPECT_EQ(back["seams"][0]["band"]["width_mm"], 40);
  EXPECT_EQ(back["seams"][0]["band"]["part"], "side 1");
  EXPECT_EQ(back["app"]["camera"][2], 3);
  EXPECT_EQ(back["seams"][0]["points"][0]["face"], 20);
  EXPECT_EQ(b.seams[1].points[1].position, a.seams[1].points[1].position);
  EXPECT_DOUBLE_EQ(b.material.youngsModulus, 3e9);
  EXPECT_DOUBLE_EQ(b.pressure, 1000);
}

TEST(DesignJson, DefaultsWhenFieldsAreMissing) {
  const Design d = readDesignJson(R"({"format": "billow-design", "version": 1})");
  EXPECT_EQ(d.target.kind, DesignTarget::Example);
  EXPECT_EQ(d.target.name, "spot");
  EXPECT_DOUBLE_EQ(d.height, 0.6);
  EXPECT_DOUBLE_EQ(d.scale, 0);
  EXPECT_TRUE(d.seams.empty());
  EXPECT_DOUBLE_EQ(d.material.thickness, 25e-6);
  EXPECT_DOUBLE_EQ(d.material.youngsModulus, 3e9);
  EXPECT_DOUBLE_EQ(d.pressure, 1000);
  const Design s = readDesignJson(with(minimal(), "/size"_json_pointer, {{"scale", 0.01}}).dump());
  EXPECT_DOUBLE_EQ(s.scale, 0.01);
  EXPECT_NE(writeDesignJson(s).find("\"scale\""), std::string::npos);
}

TEST(DesignJson, EveryBadFieldIsRefusedWithItsName) {
  for (const char* text : {"not json", "[1, 2]", "{\"format\": \"billow-design\""}) {
    try {
      readDesignJson(text);
      ADD_FAILURE() << text;
    } catch (const Error& e) {
      EXPECT_EQ(e.code, "design.json");
    }
  }
  const json m = minimal();
  expectRefused(with(m, "/format"_json_pointer, "billow-pattern"), "design.unknown-format", "not a Billow design");
  expectRefused(with(m, "/version"_json_pointer, 2), "design.version", "newer Billow");
  expectRefused(with(m, "/version"_json_pointer, "one"), "design.bad-value", "version");
  expectRefused(with(m, "/target"_json_pointer, 3), "design.bad-value", "target");
  expectRefused(with(m, "/target"_json_pointer, {{"example", "spot"}, {"obj", "a.obj"}}), "design.bad-value",
                "exactly one");
  expectRefused(with(m, "/target"_json_pointer, {{"example", "../secret"}}), "design.bad-value", "no example");
  expectRefused(with(m, "/target"_json_pointer, {{"obj", ""}}), "design.bad-value", "obj");
  const json tetra = {{"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
                      {"triangles", {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}}};
  expectRefused(with(m, "/target"_json_pointer, with(tetra, "/vertices/1"_json_pointer, {1, "x", 0})),
                "design.bad-value", "vertex 1");
  expectRefused(with(m, "/target"_json_pointer, with(tetra, "/triangles/2/1"_json_pointer, 4)), "design.bad-value",
                "triangle 2");
  expectRefused(with(m, "/size/height"_json_pointer, 0.001), "design.bad-value", "size.height");
  expectRefused(with(m, "/size/height"_json_pointer, "tall"), "design.bad-value", "size.height");
  expectRefused(with(m, "/size"_json_pointer, {{"height", 1}, {"scale", 2}}), "design.bad-value", "not both");
  expectRefused(with(m, "/size"_json_pointer, 0.6), "design.bad-value", "size");
  expectRefused(with(m, "/seams"_json_pointer, {{"points", 1}}), "design.bad-value", "seams");
  expectRefused(with(m, "/seams"_json_pointer, json::array({3})), "design.bad-value", "seams[0]");
  expectRefused(with(m, "/seams/0/points"_json_pointer, {{1, 0, 0}, {0, 1, 0}}), "design.bad-value", "at least 3");
  expectRefused(with(m, "/seams/0/closed"_json_pointer, "yes"), "design.bad-value", "seams[0].closed");
  expectRefused(with(m, "/seams/0/weight"_json_pointer, -1), "design.bad-value", "seams[0].weight");
  expectRefused(with(m, "/seams/0/name"_json_pointer, 7), "design.bad-value", "seams[0].name");
  expectRefused(with(m, "/seams/0/points/1"_json_pointer, {1, 2}), "design.bad-value", "seams[0].points[1]");
  expectRefused(with(m, "/seams/0/points/1"_json_pointer, {{"face", -1}, {"bary", {1, 0, 0}}}), "design.bad-value",
                "no triangle");
  expectRefused(with(m, "/seams/0/points/1"_json_pointer, {{"face", 3}, {"bary", {1.5, -0.5, 0}}}), "design.bad-value",
                "outside its triangle");
  expectRefused(with(m, "/seams/0/points/1"_json_pointer, {{"face", 3}, {"bary", {1, 0}}}), "design.bad-value",
                "three barycentric");
  expectRefused(with(m, "/connections"_json_pointer, {{{"seams", {0, 5}}}}), "design.bad-value", "connections[0]");
  expectRefused(with(m, "/connections"_json_pointer, 5), "design.bad-value", "connections");
  expectRefused(with(m, "/material/thickness"_json_pointer, 0), "design.bad-value", "material.thickness");
  expectRefused(with(m, "/material/youngs_modulus"_json_pointer, -3), "design.bad-value", "material.youngs_modulus");
  expectRefused(with(m, "/material"_json_pointer, "foil"), "design.bad-value", "material");
  expectRefused(with(m, "/pressure"_json_pointer, -10), "design.bad-value", "pressure");
  expectRefused(with(m, "/pressure"_json_pointer, nullptr), "design.bad-value", "pressure");
}

TEST(DesignJson, LenientReadingFallsBackWithWarnings) {
  json doc = minimal();
  doc["pressure"] = -5;
  doc["seams"].push_back({{"points", {{1, 0, 0}}}});  // too few points: dropped
  doc["material"]["thickness"] = "thin";
  DesignReadOptions o;
  o.strict = false;
  std::vector<DesignWarning> warnings;
  const Design d = readDesignJson(doc.dump(), o, &warnings);
  EXPECT_DOUBLE_EQ(d.pressure, 1000);
  EXPECT_DOUBLE_EQ(d.material.thickness, 25e-6);
  EXPECT_EQ(d.seams.size(), 1u);
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_EQ(warnings[0].field, "seams[1].points");
}

// The app turns an inside-out mesh the right way before the designer draws on it, so a design's surface points name
// the corners of the turned mesh: read natively, the target is turned the same way and the points land where they
// were drawn (before, the CLI read the mesh as it was and moved every such point within its triangle).
TEST(DesignJson, AnInsideOutTargetIsTurnedAsTheAppTurnsItAndItsSeamPointsLandWhereDrawn) {
  const std::string path = dataPath("sphere-gores.billow.json");
  const Design drawn = readDesignJson(readFileBytes(path));
  Design insideOut = drawn;
  insideOut.target.kind = DesignTarget::Inline;
  insideOut.target.mesh = loadDesignTarget(drawn, path, {examplesDir()});
  for (int f = 0; f < insideOut.target.mesh.numTriangles(); ++f)
    std::swap(insideOut.target.mesh.F(f, 1), insideOut.target.mesh.F(f, 2));
  const auto asDrawn = makeDesignScene(drawn, path, {examplesDir()});
  const auto turned = makeDesignScene(insideOut, path, {examplesDir()});
  EXPECT_TRUE(turned->target.F == asDrawn->target.F);
  const auto specsOf = [](const DesignScene& scene) {
    return designSeamSpecs(scene.design.seams, scene.target, *scene.projector, scene.scale);
  };
  const std::vector<SeamSpec> a = specsOf(*asDrawn), b = specsOf(*turned);
  ASSERT_EQ(a.size(), b.size());
  int surfacePoints = 0;
  for (size_t s = 0; s < a.size(); ++s) {
    ASSERT_EQ(a[s].controls.size(), b[s].controls.size());
    for (size_t i = 0; i < a[s].controls.size(); ++i) {
      surfacePoints += drawn.seams[s].points[i].onSurface;
      EXPECT_LT((position(asDrawn->target, a[s].controls[i]) - position(turned->target, b[s].controls[i])).norm(),
                1e-12);
    }
  }
  EXPECT_GT(surfacePoints, 0);
  ASSERT_EQ(turned->segmentation.segments.size(), asDrawn->segmentation.segments.size());
}

TEST(DesignJson, ThreeDimensionalPointsAreProjectedOntoTheScaledTarget) {
  const std::string path = dataPath("sphere-equator.billow.json");
  const Design d = readDesignJson(readFileBytes(path));
  const auto scene = makeDesignScene(d, path, {examplesDir()});
  EXPECT_NEAR(scene->scale, 0.25, 1e-6);
  const std::vector<SeamSpec> specs = designSeamSpecs(d.seams, scene->target, *scene->projector, scene->scale);
  ASSERT_EQ(specs.size(), 1u);
  ASSERT_EQ(specs[0].controls.size(), 3u);
  EXPECT_TRUE(specs[0].closed);
  for (size_t i = 0; i < 3; ++i) {
    const Eigen::Vector3d onSurface = position(scene->target, specs[0].controls[i]);
    EXPECT_NEAR(onSurface.norm(), 0.25, 0.25 * 5e-3);  // on the icosphere (its flat triangles sag < 0.5 %)
    EXPECT_LT((onSurface - 0.25 * d.seams[0].points[i].position).norm(), 0.25 * 5e-3);
  }
  // A surface point on a triangle the target does not have.
  Design bad = d;
  bad.seams[0].points[0].onSurface = true;
  bad.seams[0].points[0].surface.face = 99999;
  try {
    designSeamSpecs(bad.seams, scene->target, *scene->projector, scene->scale);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "design.bad-value");
    EXPECT_NE(std::string(e.what()).find("another target"), std::string::npos);
  }
}

namespace {

// `read` throws design.bad-value with a message holding `words`.
template <class Read>
void expectBadValue(Read read, const std::string& words) {
  try {
    read();
    ADD_FAILURE() << "accepted; expected: " << words;
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "design.bad-value") << e.what();
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

json seamWith(const json& points, const json& fields = json::object()) {
  json s = fields;
  s["points"] = points;
  return s;
}

}  // namespace

// The parts of a design the app's worker is sent (wasm/bindings/target_bindings.cpp) are read by the document's
// rules: the messages name the seam as the designer sees it and the field, a seam traced on its own included.
TEST(DesignJson, PartsAreReadByTheDocumentsRules) {
  const json on = {{"face", 3}, {"bary", {0.2, 0.3, 0.5}}};
  DesignSeam seam;
  ASSERT_TRUE(readDesignSeam(
      seamWith({on, {1, 0, 0}, {0, 1, 0}}, {{"name", "belly"}, {"closed", true}, {"weight", 0.5}}), -1, seam));
  EXPECT_EQ(seam.name, "belly");
  EXPECT_TRUE(seam.closed);
  EXPECT_DOUBLE_EQ(seam.weight, 0.5);
  ASSERT_EQ(seam.points.size(), 3u);
  EXPECT_TRUE(seam.points[0].onSurface);
  EXPECT_EQ(seam.points[0].surface.face, 3);
  EXPECT_FALSE(seam.points[1].onSurface);
  expectBadValue(
      [] {
        DesignSeam s;
        readDesignSeam(seamWith({{1, 0, 0}}, {{"name", "belly"}}), -1, s);
      },
      "The seam \"belly\" (seam) is open and needs at least 2 points, not 1.");
  const json two = {{1, 0, 0}, {0, 1, 0}};
  expectBadValue(
      [&] {
        readDesignSeams(json::array({seamWith(two), seamWith(two, {{"name", "tail"}, {"weight", "heavy"}})}));
      },
      "The weight of seam 2 \"tail\" (seams[1].weight) must be a number from 0 to 1000000");
  expectBadValue([&] { readDesignSeams(json::array({seamWith(two, {{"weight", 2e6}})})); }, "seams[0].weight");
  expectBadValue([&] { readDesignSeams(json::array({seamWith(two, {{"smooth", 1}})})); }, "seams[0].smooth");
  expectBadValue([] { readDesignSeams(json{{"points", 1}}); }, "The seams (seams) must be a list.");
  // Barycentric coordinates: at least 0 and summing to 1, within 1e-6 and 1e-3; within that they are made exact.
  for (const json& bary : {json{0.5, 0.5, 0.5}, json{1.01, -0.01, 0.0}, json{0.3, 0.3, 0.3}})
    expectBadValue(
        [&] {
          readDesignSeams(json::array({seamWith({{{"face", 3}, {"bary", bary}}, {1, 0, 0}})}));
        },
        "Point 1 of seam 1 (seams[0].points[0]) lies outside its triangle");
  ASSERT_TRUE(readDesignSeam(seamWith({{{"face", 3}, {"bary", {0.5, 0.5, 2e-4}}}, {1, 0, 0}}), 0, seam));
  EXPECT_NEAR(seam.points[0].surface.bary.sum(), 1.0, 1e-15);
  expectBadValue(
      [] {
        readDesignSeams(json::array({seamWith({{{"face", 2.5}, {"bary", {1, 0, 0}}}, {1, 0, 0}})}));
      },
      "names no triangle");
  // Internal connections in both forms the app sends; a seam joined to itself is the pattern builder's problem.
  const std::vector<DesignConnection> pairs =
      readDesignConnections(json::parse(R"([[0, 1], {"seams": [1, 0]}, [1, 1]])"), 2);
  ASSERT_EQ(pairs.size(), 3u);
  EXPECT_EQ(pairs[0].seams, (std::vector<int>{0, 1}));
  EXPECT_EQ(pairs[1].seams, (std::vector<int>{1, 0}));
  EXPECT_EQ(pairs[2].seams, (std::vector<int>{1, 1}));
  expectBadValue(
      [] { readDesignConnections(json::parse("[[0, 1], [0, 2]]"), 2); },
      "Internal connection 2 (connections[1]) joins seam 2 (counted from 0), but the design has only 2 seams.");
  expectBadValue([] { readDesignConnections(json::parse("[[-1, 0]]"), 2); }, "joins seam -1");
  for (const char* bad :
       {"[[0]]", "[[0, 1.5]]", "[{\"seams\": 1}]", "[\"0-1\"]", "[{\"pair\": [0, 1]}]", "[[0, 1, 2]]"})
    expectBadValue([&] { readDesignConnections(json::parse(bad), 2); },
                   "Internal connection 1 (connections[0]) must join two of the design's seams");
  expectBadValue([] { readDesignConnections(json("all"), 2); },
                 "The internal connections (connections) must be a list");
  // The material and the pressure, in the designer's units.
  const Material pvc = readDesignMaterial(json{{"name", "pvc"}, {"thickness", 5e-4}});
  EXPECT_EQ(pvc.name, "pvc");
  EXPECT_DOUBLE_EQ(pvc.thickness, 5e-4);
  EXPECT_DOUBLE_EQ(pvc.youngsModulus, findMaterialPreset("pvc")->material.youngsModulus);
  expectBadValue(
      [] {
        readDesignMaterial(json{{"name", "pvc"}, {"thickness", -1}});
      },
      "The sheet thickness (material.thickness) must be between 0.1 µm and 1 cm, not -1.");
  expectBadValue([] { readDesignMaterial(json{{"youngs_modulus", 1e20}}); }, "between 1 kPa and 10 TPa");
  expectBadValue([] { readDesignMaterial(json{{"name", 5}}); }, "material.name");
  expectBadValue([] { readDesignMaterial(json{{"density", -1}}); }, "material.density");
  expectBadValue([] { readDesignMaterial(json("pvc")); }, "The material (material) must be an object");
  EXPECT_DOUBLE_EQ(readDesignPressure(json(2500)), 2500);
  expectBadValue([] { readDesignPressure(json(0)); },
                 "The pressure (pressure) must be between 1 Pa and 10 MPa, not 0.");
  // Not strict: the same rules, the default kept and a warning naming the field.
  DesignReadOptions lenient;
  lenient.strict = false;
  std::vector<DesignWarning> warnings;
  EXPECT_DOUBLE_EQ(readDesignPressure(json(-3), 1000, lenient, &warnings), 1000);
  EXPECT_EQ(readDesignConnections(json::parse("[[0, 1], [0, 9]]"), 2, lenient, &warnings).size(), 1u);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0].field, "pressure");
  EXPECT_EQ(warnings[1].field, "connections[1]");
  // The document takes the pair form too, and writes the documented one.
  json doc = minimal();
  doc["seams"].push_back(seamWith(two));
  doc["connections"] = json::parse("[[1, 0]]");
  const Design d = readDesignJson(doc.dump());
  ASSERT_EQ(d.connections.size(), 1u);
  EXPECT_EQ(d.connections[0].seams, (std::vector<int>{1, 0}));
  EXPECT_EQ(json::parse(writeDesignJson(d))["connections"], json::parse(R"([{"seams": [1, 0]}])"));
}

// A 3D seam point farther from the target's surface than the target's size (its bounding-box diagonal) cannot
// be a place on it (another target, or millimetres for the target's units): it is refused naming the seam and
// the point, at any scale the target is placed at; one within is projected.
TEST(DesignJson, FarThreeDimensionalPointsAreRefused) {
  const std::string path = dataPath("sphere-equator.billow.json");
  Design d = readDesignJson(readFileBytes(path));
  d.seams[0].name = "belly";
  const auto scene = makeDesignScene(d, path, {examplesDir()});
  const TriMesh own = loadDesignTarget(d, path, {examplesDir()});
  const SurfaceProjector ownProjector(own);
  const double size = (own.V.colwise().maxCoeff() - own.V.colwise().minCoeff()).norm();
  const double surface = own.V.col(0).maxCoeff();  // the sphere's surface along +x
  const auto placed = [&](double x, int index) {
    DesignSeam s = d.seams[0];
    s.points[1].position = Eigen::Vector3d(x, 0, 0);
    const SeamSpec meters = designSeamSpec(s, index, scene->target, *scene->projector, scene->scale);
    const SeamSpec units = designSeamSpec(s, index, own, ownProjector);
    const Eigen::Vector3d at = position(own, units.controls[1]);
    EXPECT_LT((position(scene->target, meters.controls[1]) / scene->scale - at).norm(), 1e-9) << "the same place";
    return at;
  };
  EXPECT_GT(placed(surface + 0.5 * size, 0).x(), 0.9 * surface) << "half the size away: projected";
  expectBadValue([&] { placed(surface + 1.5 * size, 0); }, "Seam 1 \"belly\": point 2 [");
  expectBadValue([&] { placed(surface + 1.5 * size, -1); }, "The seam \"belly\": point 2");
  expectBadValue([&] { placed(surface + 1.5 * size, 0); }, "another target or in other units");
  // The design's points written in millimetres for a target in meters (or any unit 1000 times smaller).
  Design mm = d;
  for (DesignPoint& p : mm.seams[0].points) p.position *= 1000;
  expectBadValue([&] { designSeamSpecs(mm.seams, scene->target, *scene->projector, scene->scale); },
                 "Seam 1 \"belly\": point 1");
}

TEST(DesignJson, TargetsFromExamplesFilesAndInlineMeshes) {
  Design d = readDesignJson(minimal().dump());
  d.target.name = "no-such-example";
  try {
    loadDesignTarget(d, dataPath("x.billow.json"), {examplesDir()});
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "design.example-not-found");
  }
  // Relative obj paths resolve against the design file's folder.
  const TriMesh sphere = loadDesignTarget(readDesignJson(readFileBytes(dataPath("sphere-gores.billow.json"))),
                                          dataPath("sphere-gores.billow.json"), {});
  EXPECT_EQ(sphere.numTriangles(), 1280);
  // An inline octahedron, 2 units high, made 1 m high.
  json doc = minimal();
  doc["target"] = {
      {"vertices", {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}},
      {"triangles", {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}}}};
  doc["size"] = {{"height", 1.0}};
  doc["seams"] = json::array();
  const Design inl = readDesignJson(doc.dump());
  EXPECT_EQ(inl.target.kind, DesignTarget::Inline);
  EXPECT_EQ(readDesignJson(writeDesignJson(inl)).target.mesh.F, inl.target.mesh.F);
  const auto scene = makeDesignScene(inl, "", {});
  EXPECT_DOUBLE_EQ(scene->scale, 0.5);
  EXPECT_DOUBLE_EQ(scene->target.V.col(1).maxCoeff(), 0.5);
  // BILLOW_EXAMPLES is searched first.
  setenv("BILLOW_EXAMPLES", "/nowhere:/elsewhere", 1);
  const std::vector<std::string> dirs = exampleSearchPath("/opt/billow/bin");
  unsetenv("BILLOW_EXAMPLES");
  ASSERT_EQ(dirs.size(), 3u);
  EXPECT_EQ(dirs[1], "/elsewhere");
  EXPECT_EQ(dirs[2], "/opt/billow/bin/../../web/public/examples");
}

// target.up: the values of tests/data/up-axis-cases.json, which tests/node/up-axis.test.mjs feeds to the app's
// reader; the good ones are read and written back, the bad ones refused naming the field (or dropped with a
// warning when not strict).
TEST(DesignJson, UpAxisIsReadByTheSameRulesAsTheApp) {
  const json cases = json::parse(readFileBytes(dataPath("up-axis-cases.json")));
  for (const json& value : cases["good"]) {
    const Design d = readDesignJson(with(minimal(), "/target/up"_json_pointer, value).dump());
    EXPECT_EQ(toString(d.target.up), value.get<std::string>());
    const json written = json::parse(writeDesignJson(d));
    EXPECT_EQ(written["target"].contains("up"), value != "+y") << "Y up, the default, is left out";
    EXPECT_EQ(readDesignJson(written.dump()).target.up, d.target.up);
    Eigen::Matrix3d frame;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) frame(i, k) = cases["frames"][value.get<std::string>()][i][k].get<double>();
    EXPECT_EQ(upFrame(d.target.up), frame) << value;
    EXPECT_DOUBLE_EQ(frame.determinant(), 1.0) << value << " turns the target without mirroring it";
  }
  DesignReadOptions lenient;
  lenient.strict = false;
  for (const json& value : cases["bad"]) {
    const json doc = with(minimal(), "/target/up"_json_pointer, value);
    expectRefused(doc, "design.bad-value", "target.up");
    std::vector<DesignWarning> warnings;
    const Design d = readDesignJson(doc.dump(), lenient, &warnings);
    ASSERT_EQ(warnings.size(), 1u) << value;
    EXPECT_EQ(warnings[0].field, "target.up");
    EXPECT_EQ(d.target.up, UpAxis{}) << "Y up instead of " << value;
    EXPECT_EQ(d.target.name, "sphere") << "the target itself is kept";
    // The worker reads an up axis alone by the same rule.
    EXPECT_THROW(readDesignUp(value), Error) << value;
  }
  for (const json& value : cases["good"]) EXPECT_EQ(toString(readDesignUp(value)), value.get<std::string>());
}

// The height is the target's extent along its up axis (the app's heightScale has the same rule and the same
// cases): koala.obj is 5.34 units high standing Y up and 9.21 long, its height when the file is read Z up.
TEST(DesignJson, HeightIsMeasuredAlongTheUpAxis) {
  const json cases = json::parse(readFileBytes(dataPath("up-axis-cases.json")));
  for (const json& c : cases["sizes"]) {
    const TriMesh mesh = test::loadShared(c["mesh"].get<std::string>());
    Design d;
    d.height = 0.6;
    ASSERT_TRUE(parseUpAxis(c["up"].get<std::string>(), d.target.up));
    const double height = c["size"][1].get<double>();
    EXPECT_NEAR(designScale(d, mesh), 0.6 / height, 1e-9 * 0.6 / height) << c["up"];
    const Vertices turned = mesh.V * upFrame(d.target.up).transpose();
    const Eigen::Vector3d size = turned.colwise().maxCoeff() - turned.colwise().minCoeff();
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(size[i], c["size"][i].get<double>(), 1e-9) << c["up"] << " axis " << i;
  }
  // A target flat along its up axis has no height to scale by.
  TriMesh flat = test::loadShared("koala.obj");
  flat.V.col(2).setZero();
  Design d;
  d.target.up = {2, 1};
  try {
    designScale(d, flat);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.code, "design.bad-target");
    EXPECT_NE(std::string(e.what()).find("up axis (z)"), std::string::npos) << e.what();
  }
}

// Problems say where as the target stands: a seam ending near the sphere's +z pole ends "near the front" of a
// Y-up target and "near the top" of the same target read Z up.
TEST(DesignJson, ProblemPlacesAreWordedAsTheTargetStands) {
  json doc = minimal();
  doc["seams"] = {{{"points", {{0.15, 0.1, 0.98}, {-0.15, 0.1, 0.98}}}}};
  const auto endsWhere = [&](const json& design) {
    const auto scene = makeDesignScene(readDesignJson(design.dump()), "", {examplesDir()});
    for (const SegmentationProblem& p : scene->segmentation.problems)
      if (p.message.find("ends in the middle") != std::string::npos) return p.message;
    return std::string("(no problem about the seam's end)");
  };
  EXPECT_NE(endsWhere(doc).find("near the front of"), std::string::npos) << endsWhere(doc);
  const std::string zUp = endsWhere(with(doc, "/target/up"_json_pointer, "+z"));
  EXPECT_NE(zUp.find("near the top of"), std::string::npos) << zUp;
}

// ---- The CLI (native only: it runs the billow executable next to this test binary) ----

TEST(CliDesign, SegmentWritesSegmentsAndFailsOnNonDisks) {
#ifdef __EMSCRIPTEN__
  GTEST_SKIP() << "the CLI is native only";
#else
  const std::string out = testing::TempDir() + "billow-segments.json";
  ASSERT_EQ(test::runQuiet(test::cliPath() + " segment " + dataPath("sphere-gores.billow.json") + " --out " + out), 0);
  const json s = json::parse(readFileBytes(out));
  EXPECT_EQ(s["format"], "billow-segments");
  ASSERT_EQ(s["segments"].size(), 3u);
  double area = 0;
  for (const auto& g : s["segments"]) {
    EXPECT_TRUE(g["isDisk"].get<bool>());
    EXPECT_EQ(g["boundary"].size(), 1u);
    EXPECT_EQ(g["boundary"][0].size(), 2u);  // two meridian pieces
    area += g["area"].get<double>();
  }
  EXPECT_NEAR(area, 4 * 3.14159265 * 0.0625, 0.01 * 0.785);  // m^2: the 0.5 m sphere
  EXPECT_TRUE(s["ok"].get<bool>());
  // No seam: one closed segment, an error, a non-zero exit, and the file is still written.
  json doc = json::parse(readFileBytes(dataPath("sphere-equator.billow.json")));
  doc["seams"] = json::array();
  const std::string design = testing::TempDir() + "billow-noseam.billow.json";
  std::ofstream(design) << doc.dump();
  EXPECT_EQ(test::runQuiet(test::cliPath() + " segment " + design + " --out " + out), 1);
  EXPECT_FALSE(json::parse(readFileBytes(out))["ok"].get<bool>());
  EXPECT_EQ(test::runQuiet(test::cliPath() + " segment " + design), 2);  // usage
#endif
}

// billow check DESIGN.json reads a design as the app's worker reads it, and with --json replies as a binding does.
TEST(CliDesign, CheckReadsADesignAndRepliesAsABinding) {
#ifdef __EMSCRIPTEN__
  GTEST_SKIP() << "the CLI is native only";
#else
  std::string out;
  ASSERT_EQ(test::runCapture(test::cliPath() + " check " + dataPath("sphere-gores.billow.json") + " --json", out), 0)
      << out;
  const json ok = json::parse(out);
  EXPECT_EQ(ok["status"], "ok");
  EXPECT_EQ(ok["result"]["seams"], 3);
  EXPECT_EQ(ok["result"]["triangles"], 1280);
  json doc = json::parse(readFileBytes(dataPath("sphere-gores.billow.json")));
  doc["target"]["obj"] = dataPath("../../web/public/examples/sphere.obj");
  doc["seams"][1]["points"][1] = {0, 0, 5000};  // 5000 units from a sphere of radius 1
  const std::string design = testing::TempDir() + "billow-far-point.billow.json";
  std::ofstream(design) << doc.dump();
  ASSERT_EQ(test::runCapture(test::cliPath() + " check " + design + " --json", out), 1) << out;
  const json refused = json::parse(out);
  EXPECT_EQ(refused["status"], "error");
  EXPECT_EQ(refused["code"], "design.bad-value");
  EXPECT_NE(refused["message"].get<std::string>().find("Seam 2 \"meridian 2\": point 2"), std::string::npos) << out;
  EXPECT_EQ(test::runCapture(test::cliPath() + " check " + design, out), 1);
  EXPECT_NE(out.find("billow check: Seam 2"), std::string::npos) << out;
  // billow segment and billow design refuse it the same way, before any work.
  EXPECT_EQ(test::runCapture(test::cliPath() + " segment " + design + " --out " + testing::TempDir() + "x.json", out),
            1);
  EXPECT_NE(out.find("times the target's size away"), std::string::npos) << out;
#endif
}

// billow design's counts are read by the rule every command shares (cli/commands.hpp intOption): a short run of a
// few iterations is taken, and a count out of range is refused naming what it counts.
TEST(CliDesign, IterationAndTriangleCountsAreReadAsTheyAreNamed) {
#ifdef __EMSCRIPTEN__
  GTEST_SKIP() << "the CLI is native only";
#else
  json doc = json::parse(readFileBytes(dataPath("sphere-gores.billow.json")));
  doc["target"]["obj"] = dataPath("../../web/public/examples/sphere.obj");
  const std::string design = testing::TempDir() + "billow-counts.billow.json",
                    dir = testing::TempDir() + "billow-counts";
  std::ofstream(design) << doc.dump();
  const std::string base = test::cliPath() + " design " + design + " --out-dir " + dir + " --quiet";
  std::string out;
  EXPECT_EQ(test::runCapture(base + " --resolution 300 --max-iterations 3", out), 0) << out;
  const json report = json::parse(readFileBytes(dir + "/report.json"));
  int last = -1;
  for (const auto& h : report["optimize"]["history"]) last = std::max(last, h["iteration"].get<int>());
  EXPECT_GE(last, 1);
  EXPECT_LE(last, 3);
  EXPECT_EQ(test::runCapture(base + " --max-iterations 0", out), 1);
  EXPECT_NE(out.find("--max-iterations needs an iteration count from 1 to 100000, not '0'"), std::string::npos) << out;
  EXPECT_EQ(test::runCapture(base + " --resolution 5", out), 1);
  EXPECT_NE(out.find("--resolution needs a triangle count from 8 to 2000000, not '5'"), std::string::npos) << out;
#endif
}

// Seams of weight 0 slide: the report says so, the panels were meshed anew on the way, and the iteration cap
// holds; the same layout with its drawn weights does not slide.
TEST(CliDesign, DesignReportsSlidingSeams) {
#ifdef __EMSCRIPTEN__
  GTEST_SKIP() << "the CLI is native only";
#else
  json doc = json::parse(readFileBytes(dataPath("sphere-gores.billow.json")));
  doc["target"]["obj"] = dataPath("../../web/public/examples/sphere.obj");  // the copy lives elsewhere
  const auto run = [&](const std::string& name) {
    const std::string design = testing::TempDir() + name + ".billow.json", dir = testing::TempDir() + name;
    std::ofstream(design) << doc.dump();
    EXPECT_EQ(test::runQuiet(test::cliPath() + " design " + design + " --out-dir " + dir +
                             " --resolution 400 --max-iterations 25 --quiet"),
              0);
    return json::parse(readFileBytes(dir + "/report.json"));
  };
  const json held = run("billow-held-seams");
  for (auto& seam : doc["seams"]) seam["weight"] = 0;
  const json sliding = run("billow-sliding-seams");
  EXPECT_FALSE(held["optimize"]["sliding_seams"].get<bool>());
  EXPECT_TRUE(sliding["optimize"]["sliding_seams"].get<bool>());
  EXPECT_GE(sliding["optimize"]["remeshing_steps"].get<int>(), 1);
  int last = 0;
  for (const auto& h : sliding["optimize"]["history"]) last = std::max(last, h["iteration"].get<int>());
  EXPECT_LE(last, 25);
  EXPECT_GE(last, 20);  // (it goes on: the layout is far from its best with the seams where drawn)
  EXPECT_TRUE(sliding["optimized"].get<bool>());
#endif
}

TEST(CliDesign, DesignWritesPatternInflatedShapeAndReport) {
#ifdef __EMSCRIPTEN__
  GTEST_SKIP() << "the CLI is native only";
#else
  const std::string dir = testing::TempDir() + "billow-design-equator";
  ASSERT_EQ(test::runQuiet(test::cliPath() + " design " + dataPath("sphere-equator.billow.json") + " --out-dir " + dir +
                           " --no-optimize --resolution 1200"),
            0);
  std::vector<PatternWarning> warnings;
  const Pattern p = readPatternJson(readFileBytes(dir + "/pattern.json"), &warnings);
  ASSERT_EQ(p.panels.size(), 2u);
  ASSERT_EQ(p.inflated.size(), 2u);
  const SewnMesh sewn = sewPattern(p);
  const TriMesh inflated = readMeshBytes(readFileBytes(dir + "/inflated.obj"), "inflated.obj");
  EXPECT_EQ(inflated.numVertices(), sewn.numVertices);
  EXPECT_EQ(inflated.numTriangles(), sewn.numTriangles());
  const json report = json::parse(readFileBytes(dir + "/report.json"));
  EXPECT_TRUE(report["inflate"]["converged"].get<bool>());
  EXPECT_FALSE(report["optimized"].get<bool>());
  // Two flat discs puff up to a Mylar-balloon-like shape: a few percent from the sphere, not more than 25 %.
  EXPECT_GT(report["distance_to_target"]["rms"].get<double>(), 0.01);
  EXPECT_LT(report["distance_to_target"]["max"].get<double>(), 0.25);
  EXPECT_GE(report["seam_length_mismatch"]["max_piece"].get<double>(), 0.0);
  // The cut file: true scale in mm, one cut and one sewing line per panel.
  const std::string svg = readFileBytes(dir + "/pattern.svg");
  EXPECT_NE(svg.find("width=\"1000mm\""), std::string::npos);
  const size_t cut = svg.find("<g id=\"cut\""), sew = svg.find("<g id=\"sew\"");
  ASSERT_NE(cut, std::string::npos);
  ASSERT_NE(sew, std::string::npos);
  const auto pathsIn = [&](size_t from) {
    int n = 0;
    for (size_t at = svg.find("<path", from); at != std::string::npos && at < svg.find("</g>", from);
         at = svg.find("<path", at + 1))
      ++n;
    return n;
  };
  EXPECT_EQ(pathsIn(cut), 2);
  EXPECT_EQ(pathsIn(sew), 2);
#endif
}
