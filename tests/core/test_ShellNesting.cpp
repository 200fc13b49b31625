// The shells of a surface and their nesting (core/mesh/ShellNesting.h): a hollow ball's void is
// a cavity and is filled, with a ball loose inside it; a body beside it and a body embedded in
// solid material are kept; a part without a cavity comes back unchanged.
#include "mesh/AnalyticShapes.h"
#include "mesh/ShellNesting.h"
#include "mesh/SurfaceCheck.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

using namespace geolattice;

namespace {

/// `part`'s shells appended to `into`; turned inside out when `inward`.
void append(TriangleSurface& into, const TriangleSurface& part, bool inward = false) {
  const int offset = static_cast<int>(into.points.size());
  into.points.insert(into.points.end(), part.points.begin(), part.points.end());
  for (auto t : part.triangles) {
    if (inward) {
      std::swap(t[1], t[2]);
    }
    into.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  }
}

double sphereVolume(double r) {
  return 4.0 / 3.0 * M_PI * r * r * r;
}

}  // namespace

TEST(ShellNesting, AHollowBallsVoidIsFilledWithWhatIsLooseInIt) {
  TriangleSurface part;
  append(part, sphereSurface(Vec3::Zero(), 20, 4));                   // the ball
  append(part, sphereSurface(Vec3::Zero(), 14, 4), /*inward=*/true);  // its void
  append(part, sphereSurface(Vec3(0, 0, -8), 3, 3));                  // a ball loose in the void
  append(part, sphereSurface(Vec3(40, 0, 0), 5, 3));                  // a body beside it
  const ShellNesting nesting = nestShells(part);
  ASSERT_EQ(nesting.shells, 4);
  int cavities = 0;
  for (int s = 0; s < nesting.shells; ++s) {
    cavities += nesting.isCavity(s) ? 1 : 0;
  }
  EXPECT_EQ(cavities, 1);

  const double before = checkSurface(part).signedVolume;
  const int beforeTriangles = static_cast<int>(part.triangles.size());
  const CavityFilling filled = fillCavities(part);
  EXPECT_EQ(filled.cavities, 1);
  EXPECT_EQ(filled.enclosedBodies, 1);
  EXPECT_EQ(filled.removedTriangles, beforeTriangles - static_cast<int>(part.triangles.size()));
  const SurfaceCheckReport after = checkSurface(part);
  EXPECT_TRUE(after.isClosedManifold());
  // The void's volume is solid now; the loose ball's is part of it (no longer counted twice).
  const double icosphere = 0.99;  // a level-4 icosphere holds 99.4 % of its sphere's volume
  EXPECT_GT(after.signedVolume, before);
  EXPECT_NEAR(after.signedVolume, sphereVolume(20) + sphereVolume(5),
              (1 - icosphere) * (sphereVolume(20) + sphereVolume(5)));
  // Every point is used by a triangle (the removed shells' points are gone).
  std::vector<char> used(part.points.size(), 0);
  for (const auto& t : part.triangles) {
    used[t[0]] = used[t[1]] = used[t[2]] = 1;
  }
  for (size_t v = 0; v < used.size(); ++v) {
    ASSERT_TRUE(used[v]) << "point " << v << " is used by no triangle";
  }
  EXPECT_EQ(nestShells(part).shells, 2);
}

TEST(ShellNesting, APartWithoutACavityIsLeftAsItIs) {
  TriangleSurface part;
  append(part, boxSurface(Vec3(30, 30, 30), 5));
  append(part, sphereSurface(Vec3(15, 15, 15), 5, 3));  // embedded, outward: solid either way
  const TriangleSurface before = part;
  const CavityFilling filled = fillCavities(part);
  EXPECT_EQ(filled.cavities, 0);
  EXPECT_EQ(filled.enclosedBodies, 0);
  EXPECT_EQ(part.triangles, before.triangles);
  EXPECT_EQ(part.points.size(), before.points.size());
  const ShellNesting nesting = nestShells(part);
  ASSERT_EQ(nesting.shells, 2);
  EXPECT_FALSE(nesting.isCavity(0));
  EXPECT_FALSE(nesting.isCavity(1));
  // A single inside-out body is not a cavity (nothing holds it): it is not removed.
  TriangleSurface inverted;
  append(inverted, sphereSurface(Vec3::Zero(), 10, 3), /*inward=*/true);
  EXPECT_EQ(fillCavities(inverted).cavities, 0);
  EXPECT_EQ(inverted.triangles.size(), sphereSurface(Vec3::Zero(), 10, 3).triangles.size());
}
