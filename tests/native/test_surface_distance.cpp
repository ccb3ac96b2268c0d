// Distance between a shape and its target both ways (seams/surface_distance.hpp): the target-to-shape side
// sees what a shape leaves out, which the shape-to-target side alone reads as close.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "crease_shapes.hpp"
#include "io/distance_json.hpp"
#include "seams/surface_distance.hpp"
#include "test_support.hpp"

namespace billow {
namespace {

// The unit square [0, 1]^2 at z = 0, n x m cells of two triangles each, columns spaced by `x(i)`.
template <class Column>
TriMesh grid(int n, int m, Column x) {
  TriMesh g;
  g.V.resize((n + 1) * (m + 1), 3);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) g.V.row(i * (m + 1) + j) << x(i), double(j) / m, 0;
  g.F.resize(2 * n * m, 3);
  for (int i = 0, f = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      const int a = i * (m + 1) + j, b = a + m + 1;
      g.F.row(f++) << a, b, b + 1;
      g.F.row(f++) << a, b + 1, a + 1;
    }
  return g;
}

// The triangles of `mesh` whose centroid passes `keep`.
template <class Keep>
Triangles trianglesWhere(const TriMesh& mesh, Keep keep) {
  std::vector<int> kept;
  for (int f = 0; f < mesh.numTriangles(); ++f) {
    const Eigen::Vector3d c =
        (mesh.V.row(mesh.F(f, 0)) + mesh.V.row(mesh.F(f, 1)) + mesh.V.row(mesh.F(f, 2))).transpose() / 3;
    if (keep(c)) kept.push_back(f);
  }
  Triangles F(kept.size(), 3);
  for (size_t k = 0; k < kept.size(); ++k) F.row(k) = mesh.F.row(kept[k]);
  return F;
}

TEST(TargetCoverage, AreaWeightedRmsMatchesTheIntegralWhateverTheMeshing) {
  // The shape covers the left half of the square: the target lies max(0, x - 1/2) from it, whose RMS over the
  // square's area is sqrt(1/24).
  const double exact = std::sqrt(1.0 / 24);
  // Fine on the right, coarse on the left: a plain average over vertices would be dominated by the right.
  const TriMesh uneven = grid(60, 40, [](int i) { return i <= 10 ? 0.05 * i : 0.5 + 0.01 * (i - 10); });
  const TriMesh even = grid(40, 40, [](int i) { return i / 40.0; });
  for (const TriMesh* target : {&uneven, &even}) {
    const Triangles left = trianglesWhere(*target, [](const Eigen::Vector3d& c) { return c.x() < 0.5; });
    const TargetCoverage c = targetCoverage(*target, target->V, left, 1.0);
    EXPECT_NEAR(c.summary.rms, exact, 0.03 * exact);
    EXPECT_NEAR(c.summary.max, 0.5, 1e-12);
    const double plain = std::sqrt(c.distances.cwiseAbs2().mean());
    if (target == &uneven) {
      EXPECT_GT(plain, 1.2 * exact) << "the meshing would have weighed in";
    }
  }
}

TEST(TargetCoverage, OneWayAloneMissesAHalfLeftOutAndBothWaysSeeIt) {
  // Spot's back half alone (z below the middle of its box) lies on Spot everywhere: one way reads 0, the
  // other sees the front half missing, as a region near the front.
  const TriMesh spot = test::loadShared("spot.obj");
  const SurfaceProjector projector(spot);
  const double midZ = 0.5 * (spot.V.col(2).minCoeff() + spot.V.col(2).maxCoeff());
  const Triangles back = trianglesWhere(spot, [&](const Eigen::Vector3d& c) { return c.z() < midZ; });
  const TwoWayDistance d = measureDistance(spot, projector, spot.V, back, UpAxis{});
  EXPECT_LT(d.inflatedToTarget.rms, 1e-12);
  EXPECT_GT(d.targetToInflated.summary.rms, 0.05);
  EXPECT_GT(d.targetToInflated.summary.max, 0.2);
  EXPECT_EQ(d.worse().rms, d.targetToInflated.summary.rms);
  ASSERT_FALSE(d.uncovered.empty());
  const UncoveredRegion& front = d.uncovered.front();
  EXPECT_NE(front.where.find("front"), std::string::npos) << front.where;
  EXPECT_GT(front.areaFraction, 0.2);
  EXPECT_LT(front.areaFraction, 0.6);
  EXPECT_NEAR(front.maxDistance, d.targetToInflated.summary.max, 1e-12);
  EXPECT_GT(front.farthest.z(), midZ);
  // And the whole of Spot against itself: nothing left out either way.
  const TwoWayDistance same = measureDistance(spot, projector, spot.V, spot.F, UpAxis{});
  EXPECT_LT(same.worse().max, 1e-12);
  EXPECT_TRUE(same.uncovered.empty());
  // Without a surface there is one way only (the points of a shape with no triangles).
  const TwoWayDistance oneWay = measureDistance(spot, projector, spot.V, Triangles(), UpAxis{});
  EXPECT_EQ(oneWay.targetToInflated.distances.size(), 0);
  EXPECT_TRUE(oneWay.uncovered.empty());
}

// The app streams each iterate's distances both ways, the other way as the optimizer measured it already: given,
// it gives what measuring again gives, what helps included.
TEST(TargetCoverage, MeasuredDistancesGivenGiveTheSameFiguresAsMeasuringAgain) {
  const TriMesh spot = test::loadShared("spot.obj");
  const SurfaceProjector projector(spot);
  const double midZ = 0.5 * (spot.V.col(2).minCoeff() + spot.V.col(2).maxCoeff());
  const Triangles back = trianglesWhere(spot, [&](const Eigen::Vector3d& c) { return c.z() < midZ; });
  const Eigen::VectorXd measured = targetCoverage(spot, spot.V, back, 1.0).distances;
  const TwoWayDistance fresh = measureDistance(spot, projector, spot.V, back, UpAxis{});
  const TwoWayDistance given = measureDistance(spot, projector, spot.V, back, UpAxis{}, &measured);
  EXPECT_EQ(given.targetToInflated.distances, fresh.targetToInflated.distances);
  EXPECT_EQ(given.targetToInflated.summary.rms, fresh.targetToInflated.summary.rms);
  EXPECT_EQ(given.targetToInflated.summary.max, fresh.targetToInflated.summary.max);
  EXPECT_EQ(given.inflatedToTarget.rms, fresh.inflatedToTarget.rms);
  ASSERT_EQ(given.uncovered.size(), fresh.uncovered.size());
  ASSERT_FALSE(fresh.uncovered.empty());
  for (size_t k = 0; k < fresh.uncovered.size(); ++k) {
    EXPECT_EQ(given.uncovered[k].triangles, fresh.uncovered[k].triangles);
    EXPECT_EQ(given.uncovered[k].insideFraction, fresh.uncovered[k].insideFraction);
    EXPECT_EQ(given.uncovered[k].offFlatSide, fresh.uncovered[k].offFlatSide);
    EXPECT_EQ(uncoveredMessage(given.uncovered[k]), uncoveredMessage(fresh.uncovered[k]));
  }
}

TEST(UncoveredRegions, SeparatePartsAreSeparateRegionsLargestFirstAndSmallOnesIgnored) {
  // The square's middle band is covered; its left strip (x < 0.3) and a smaller right strip (x > 0.85) are
  // not: two regions, the left one first.
  const TriMesh square = grid(50, 10, [](int i) { return i / 50.0; });
  const Triangles middle = trianglesWhere(square, [](const Eigen::Vector3d& c) { return c.x() > 0.3 && c.x() < 0.85; });
  const TargetCoverage c = targetCoverage(square, square.V, middle, 1.0);
  const std::vector<UncoveredRegion> regions = uncoveredRegions(square, c.distances, 1.0, UpAxis{}, 0.03, 0.01);
  ASSERT_EQ(regions.size(), 2u);
  EXPECT_NE(regions[0].where.find("left"), std::string::npos) << regions[0].where;
  EXPECT_NE(regions[1].where.find("right"), std::string::npos) << regions[1].where;
  // Stood on its x axis, the left strip is the bottom of the shape.
  const std::vector<UncoveredRegion> standing = uncoveredRegions(square, c.distances, 1.0, UpAxis{0, 1}, 0.03, 0.01);
  ASSERT_EQ(standing.size(), 2u);
  EXPECT_NE(standing[0].where.find("bottom"), std::string::npos) << standing[0].where;
  // Beyond 0.03 from the band: x < 0.27 (27 %) and x > 0.88 (12 %) of the area.
  EXPECT_NEAR(regions[0].areaFraction, 0.26, 0.02);
  EXPECT_NEAR(regions[1].areaFraction, 0.12, 0.02);
  EXPECT_NEAR(regions[0].maxDistance, 0.3, 1e-12);
  EXPECT_NEAR(regions[0].farthest.x(), 0.0, 1e-12);
  EXPECT_GT(regions[0].radius, 0.25);
  // Each region's triangles, to draw it: its area, and all lying on its side.
  for (const UncoveredRegion& r : regions) {
    double area = 0;
    for (int f : r.triangles)
      area += 0.5 * (square.V.row(square.F(f, 1)) - square.V.row(square.F(f, 0)))
                        .cross(square.V.row(square.F(f, 2)) - square.V.row(square.F(f, 0)))
                        .norm();
    EXPECT_NEAR(area, r.areaFraction, 1e-12) << "the unit square's area is 1";
  }
  for (int f : regions[0].triangles) EXPECT_LT(square.V(square.F(f, 0), 0), 0.3);
  // A region smaller than the area asked for is not one.
  EXPECT_EQ(uncoveredRegions(square, c.distances, 1.0, UpAxis{}, 0.03, 0.2).size(), 1u);
  // Nearer than the threshold is not left out.
  EXPECT_TRUE(uncoveredRegions(square, c.distances, 1.0, UpAxis{}, 0.31, 0.0).empty());
  // Two parts that read the same (both near the left: two strips beside each other, with a covered strip
  // between) are one region of two parts, said once.
  const Triangles gap =
      trianglesWhere(square, [](const Eigen::Vector3d& centre) { return centre.x() > 0.12 && centre.x() < 0.16; });
  Triangles shown(middle.rows() + gap.rows(), 3);
  shown << middle, gap;
  const TargetCoverage twoLeft = targetCoverage(square, square.V, shown, 1.0);
  const std::vector<UncoveredRegion> pair = uncoveredRegions(square, twoLeft.distances, 1.0, UpAxis{}, 0.03, 0.01);
  ASSERT_FALSE(pair.empty());
  EXPECT_EQ(pair[0].parts, 2) << pair[0].where;
  EXPECT_EQ(std::count_if(pair.begin(), pair.end(), [&](const UncoveredRegion& r) { return r.where == pair[0].where; }),
            1);
  EXPECT_NE(uncoveredMessage(pair[0]).find("leaves out 2 parts of the target"), std::string::npos)
      << uncoveredMessage(pair[0]);
  EXPECT_GT(pair[0].radius, 0.2);  // the ball holds both strips, for Show where
  // A part: where it is and what helps.
  const std::string part = uncoveredMessage(regions[0]);
  EXPECT_NE(part.find("leaves out part of the target " + regions[0].where + ": 26."), std::string::npos) << part;
  EXPECT_NE(part.find("A seam around that part"), std::string::npos) << part;
  // Most of it: more seams, not a seam around it.
  const Triangles corner = trianglesWhere(square, [](const Eigen::Vector3d& centre) { return centre.x() > 0.9; });
  const std::vector<UncoveredRegion> most =
      uncoveredRegions(square, targetCoverage(square, square.V, corner, 1.0).distances, 1.0, UpAxis{}, 0.03, 0.01);
  ASSERT_EQ(most.size(), 1u);
  EXPECT_GT(most[0].areaFraction, 0.8);
  const std::string much = uncoveredMessage(most[0]);
  EXPECT_NE(much.find("falls short of much of the target"), std::string::npos) << much;
  EXPECT_NE(much.find("More seams"), std::string::npos) << much;
}

TEST(DistanceJson, ReportLeadsWithTheWorseWayAndListsWhatIsLeftOut) {
  const TriMesh square = grid(20, 20, [](int i) { return i / 20.0; });
  const SurfaceProjector projector(square);
  const Triangles left = trianglesWhere(square, [](const Eigen::Vector3d& c) { return c.x() < 0.5; });
  const TwoWayDistance d = measureDistance(square, projector, square.V, left, UpAxis{});
  const nlohmann::json j = distanceReportJson(d);
  EXPECT_DOUBLE_EQ(j["rms"].get<double>(), d.targetToInflated.summary.rms);
  EXPECT_DOUBLE_EQ(j["target_to_inflated"]["max"].get<double>(), d.targetToInflated.summary.max);
  EXPECT_DOUBLE_EQ(j["inflated_to_target"]["rms"].get<double>(), d.inflatedToTarget.rms);
  ASSERT_EQ(j["uncovered"].size(), d.uncovered.size());
  ASSERT_FALSE(d.uncovered.empty());
  EXPECT_EQ(j["uncovered"][0]["where"].get<std::string>(), d.uncovered[0].where);
  EXPECT_EQ(j["uncovered"][0]["position"].size(), 3u);
  EXPECT_EQ(j["uncovered"][0]["message"].get<std::string>(), uncoveredMessage(d.uncovered[0]));
  EXPECT_EQ(j["uncovered"][0]["helps"].get<std::string>(), uncoveredRemedy(d.uncovered[0]));
}

TEST(UncoveredRegions, WhatHelpsIsJudgedFromTheShape) {
  // The unit sphere as the target, against three shapes a balloon could take.
  const TriMesh sphere = test::loadShared("sphere.obj");
  const SurfaceProjector projector(sphere);
  const auto messages = [&](const TriMesh& target, const SurfaceProjector& p, const Vertices& shape) {
    std::string all;
    for (const UncoveredRegion& r : measureDistance(target, p, shape, sphere.F, UpAxis{}).uncovered)
      all += uncoveredMessage(r) + "\n";
    return all;
  };
  // Too flat (a two-piece balloon of a round body): the target's poles lie off its flat sides, where the
  // target is thick. A gusset helps.
  Vertices flat = sphere.V;
  flat.col(2) *= 0.5;
  const std::string tooFlat = messages(sphere, projector, flat);
  EXPECT_NE(tooFlat.find("too flat"), std::string::npos) << tooFlat;
  EXPECT_NE(tooFlat.find("A gusset"), std::string::npos) << tooFlat;
  EXPECT_EQ(uncoveredRemedy(measureDistance(sphere, projector, flat, sphere.F, UpAxis{}).uncovered.at(0)),
            "a gusset or more panels");
  // A balloon that has a gusset and is still too flat: a wider one, not another.
  const UncoveredRegion gusseted =
      measureDistance(sphere, projector, flat, sphere.F, UpAxis{}, nullptr, true).uncovered.at(0);
  EXPECT_EQ(uncoveredRemedy(gusseted), "a wider gusset or more panels");
  EXPECT_NE(uncoveredMessage(gusseted).find("too flat"), std::string::npos) << uncoveredMessage(gusseted);
  EXPECT_NE(uncoveredMessage(gusseted).find("A wider gusset"), std::string::npos) << uncoveredMessage(gusseted);
  // Over a hollow: the target dented at +x, the shape the round sphere. An internal connection helps.
  TriMesh dented = sphere;
  for (int v = 0; v < dented.numVertices(); ++v)
    if (dented.V(v, 0) > 0.6) dented.V(v, 0) = 0.6 - 0.8 * (dented.V(v, 0) - 0.6);
  const SurfaceProjector dentedProjector(dented);
  const std::string hollow = messages(dented, dentedProjector, sphere.V);
  EXPECT_NE(hollow.find("bulges over a hollow"), std::string::npos) << hollow;
  EXPECT_NE(hollow.find("An internal connection"), std::string::npos) << hollow;
  EXPECT_EQ(hollow.find("A gusset"), std::string::npos) << hollow;
  // Past a flat side: a box, the shape its front side bulged out by a third of its depth (a box cushion sewn along its
  // creases). The same help, named for what it is.
  const TriMesh box = test::boxShape(0.6, 0.4, 0.2);
  const SurfaceProjector boxProjector(box);
  Vertices bulged = box.V;
  for (int v = 0; v < box.numVertices(); ++v)
    if (box.V(v, 2) > 0.099)
      bulged(v, 2) += 0.07 * std::cos(test::kPi * box.V(v, 0) / 0.6) * std::cos(test::kPi * box.V(v, 1) / 0.4);
  std::string past;
  for (const UncoveredRegion& r : measureDistance(box, boxProjector, bulged, box.F, UpAxis{}).uncovered)
    past += uncoveredMessage(r) + "\n";
  EXPECT_NE(past.find("bulges past a flat side of the target"), std::string::npos) << past;
  EXPECT_NE(past.find("An internal connection"), std::string::npos) << past;
  EXPECT_EQ(past.find("hollow"), std::string::npos) << past;
  // A thin fin (the target flattened across y) sticking out of the flat sides of a flat shape (flattened along
  // z): both of the fin's sides are left out, so a seam around it helps, not a gusset.
  TriMesh fin = sphere;
  fin.V.col(1) *= 0.1;
  const SurfaceProjector finProjector(fin);
  const std::string thin = messages(fin, finProjector, flat);
  EXPECT_NE(thin.find("A seam around"), std::string::npos) << thin;
  EXPECT_EQ(thin.find("A gusset"), std::string::npos) << thin;
}

}  // namespace
}  // namespace billow
