// describeLocation (mesh/location.hpp): the words that place every segmentation and pattern problem on the
// shape. The words must be read as the target stands on its up axis (a Z-up file's top is its +z side, and its
// front is -y), or a designer is sent to the wrong side of the model.
#include <gtest/gtest.h>

#include <string>

#include "mesh/location.hpp"

using namespace billow;

namespace {

const Eigen::Vector3d kLo(0, 0, 0), kHi(1, 1, 1);

std::string at(double x, double y, double z, const char* up = "+y") {
  UpAxis axis;
  EXPECT_TRUE(parseUpAxis(up, axis)) << up;
  return describeLocation(Eigen::Vector3d(x, y, z), kLo, kHi, axis);
}

}  // namespace

TEST(Location, TheCentreOfTheBoxIsTheMiddle) {
  EXPECT_EQ(at(0.5, 0.5, 0.5), "near the middle of the shape");
  // The middle third on every axis is still the middle.
  EXPECT_EQ(at(0.4, 0.6, 0.35), "near the middle of the shape");
}

TEST(Location, YUpNamesHeightThenSideThenDepth) {
  // Y up is the file's own frame: +y top, +x right, +z front; the words come in that order.
  EXPECT_EQ(at(0.9, 0.9, 0.9), "near the top right front of the shape");
  EXPECT_EQ(at(0.1, 0.1, 0.1), "near the bottom left back of the shape");
  EXPECT_EQ(at(0.5, 0.9, 0.5), "near the top of the shape");
  EXPECT_EQ(at(0.1, 0.5, 0.5), "near the left of the shape");
  EXPECT_EQ(at(0.5, 0.5, 0.9), "near the front of the shape");
  EXPECT_EQ(at(0.9, 0.1, 0.5), "near the bottom right of the shape");
}

TEST(Location, ThirdsOfABoxAwayFromTheOriginAreMeasuredFromItsCorners) {
  // Box x in [10, 40]: thirds at 20 and 30.
  const Eigen::Vector3d lo(10, -5, 100), hi(40, 5, 102);
  EXPECT_EQ(describeLocation({19, 0, 101}, lo, hi), "near the left of the shape");
  EXPECT_EQ(describeLocation({21, 0, 101}, lo, hi), "near the middle of the shape");
  EXPECT_EQ(describeLocation({31, 4, 100.1}, lo, hi), "near the top right back of the shape");
}

TEST(Location, AFlatBoxHasNoWordForItsFlatAxis) {
  // A box of zero depth: every point is in the middle of it along z.
  const Eigen::Vector3d lo(0, 0, 0), hi(1, 1, 0);
  EXPECT_EQ(describeLocation({0.9, 0.9, 0}, lo, hi), "near the top right of the shape");
  EXPECT_EQ(describeLocation({0.5, 0.5, 0}, lo, hi), "near the middle of the shape");
}

TEST(Location, YDownTurnsTheShapeOverAboutX) {
  // Up is -y: the file's +y is the bottom; x stays right, so (a proper rotation) +z is now the back.
  EXPECT_EQ(at(0.9, 0.9, 0.9, "-y"), "near the bottom right back of the shape");
  EXPECT_EQ(at(0.5, 0.1, 0.1, "-y"), "near the top front of the shape");
}

TEST(Location, ZUpReadsPlusZAsTopAndMinusYAsFront) {
  // Standing on +z with x to the right, the viewer's direction is x cross z = -y: low y is the front.
  EXPECT_EQ(at(0.5, 0.5, 0.9, "+z"), "near the top of the shape");
  EXPECT_EQ(at(0.5, 0.1, 0.5, "+z"), "near the front of the shape");
  EXPECT_EQ(at(0.5, 0.9, 0.5, "+z"), "near the back of the shape");
  EXPECT_EQ(at(0.9, 0.1, 0.1, "+z"), "near the bottom right front of the shape");
  // Up is -z: the file's +z is the bottom, and the front turns to +y.
  EXPECT_EQ(at(0.5, 0.9, 0.9, "-z"), "near the bottom front of the shape");
}

TEST(Location, XUpReadsPlusXAsTopAndMinusYAsRight) {
  // Standing on +x with z to the viewer, right is up x viewer = x cross z = -y.
  EXPECT_EQ(at(0.9, 0.5, 0.5, "+x"), "near the top of the shape");
  EXPECT_EQ(at(0.5, 0.1, 0.5, "+x"), "near the right of the shape");
  EXPECT_EQ(at(0.1, 0.9, 0.9, "+x"), "near the bottom left front of the shape");
  // Up is -x: +x is the bottom and +y the right.
  EXPECT_EQ(at(0.9, 0.9, 0.5, "-x"), "near the bottom right of the shape");
}

TEST(Location, PointsOutsideTheBoxTakeTheNearestThird) {
  EXPECT_EQ(at(0.5, 1.7, 0.5), "near the top of the shape");
  EXPECT_EQ(at(-2, 0.5, 0.5), "near the left of the shape");
}
