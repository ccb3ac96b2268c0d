// The up axis guessed when a mesh file is opened (mesh/up_axis.hpp): every shared mesh as it is (Y up) and turned Z up,
// as CAD and 3D-printing tools write it, and the validation report that carries the guess to the app.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>

#include "mesh/up_axis.hpp"
#include "mesh/validate.hpp"
#include "test_support.hpp"

namespace billow {
namespace {

// A Y-up mesh as a Z-up tool writes it: (x, y, z) -> (x, -z, y), a quarter turn about x.
TriMesh turnedZUp(TriMesh mesh) {
  for (int i = 0; i < mesh.V.rows(); ++i) {
    const double y = mesh.V(i, 1), z = mesh.V(i, 2);
    mesh.V(i, 1) = -z, mesh.V(i, 2) = y;
  }
  return mesh;
}

// Those that stand on their bottom when turned Z up are guessed Z up; the others stand on no side firmly (the fish,
// the goat's bust with its horns lower than its cut, the octopus on its curled tentacles; the sphere on every side).
// Nothing shipped Y up is ever flipped.
TEST(UpGuess, EverySharedMeshStaysYUpAndTheOnesThatStandAreFoundTurnedZUp) {
  const std::set<std::string> standing = {"bunny.obj", "cat.obj",     "elephant.obj", "hand.obj",
                                          "koala.obj", "penguin.obj", "spot.obj",     "stuffedtoy.obj"};
  for (const char* name : {"sphere.obj", "spot.obj", "bunny.obj", "blub.obj", "penguin.obj", "stuffedtoy.obj",
                           "elephant.obj", "koala.obj", "goathead.obj", "cat.obj", "octopus.obj", "hand.obj"}) {
    const TriMesh mesh = test::loadShared(name);
    const UpGuess asItIs = guessUp(mesh);
    EXPECT_EQ(toString(asItIs.up), "+y") << name << " stands " << asItIs.standsY << " / " << asItIs.standsZ;
    const UpGuess turned = guessUp(turnedZUp(mesh));
    EXPECT_EQ(toString(turned.up), standing.count(name) ? "+z" : "+y")
        << name << " turned stands " << turned.standsY << " / " << turned.standsZ;
    // Turned, it stands on its Z bottom as it stood on its Y bottom.
    EXPECT_NEAR(turned.standsZ, asItIs.standsY, 1e-12) << name;
  }
}

// The report the worker returns holds the guess; a mesh that cannot be used gets none.
TEST(UpGuess, TheValidationReportCarriesIt) {
  TriMesh koala = turnedZUp(test::loadShared("koala.obj"));
  const nlohmann::json report = nlohmann::json::parse(toJson(validateTarget(koala)));
  EXPECT_EQ(report["stats"]["up"], "+z");
  EXPECT_GT(report["stats"]["stands_z"].get<double>(), 0.005);
  EXPECT_LT(report["stats"]["stands_y"].get<double>(), 0.005);
  TriMesh open = test::loadShared("koala.obj");
  open.F.conservativeResize(open.F.rows() - 1, 3);
  const nlohmann::json refused = nlohmann::json::parse(toJson(validateTarget(open)));
  EXPECT_FALSE(refused["ok"].get<bool>());
  EXPECT_EQ(refused["stats"]["up"], "+y");
}

}  // namespace
}  // namespace billow
