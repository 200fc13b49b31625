// core/summary/PrintSummary: the slicer numbers of a toolpath, on a hand-made path.
#include "common/Error.h"
#include "summary/PrintSummary.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace geolattice;

namespace {
/// A 10 mm print move at 10 mm/s on layer 0 (sub-graph 3), a 5 mm air move up at 50 mm/s, a
/// 6 mm perimeter move at 20 mm/s on layer 1 (sub-graph 4) and a zero-length move.
PrintSummaryInput handMadePath() {
  PrintSummaryInput in;
  in.points = {{0, 0, 0}, {10, 0, 0}, {10, 0, 5}, {10, 6, 5}, {10, 6, 5}};
  in.feedRate = {0, 10, 50, 20, 0};  // the first point's and a zero-length move's are not used
  in.moveKind = {0, 0, 2, 1, 1};
  in.layer = {0, 0, -1, 1, 1};
  in.subgraph = {3, 3, -1, 4, 4};
  in.filamentLength = 100.0;
  in.filamentDiameter = 1.75;
  return in;
}
}  // namespace

TEST(PrintSummary, LengthsTimesAndFilamentOfAHandMadePath) {
  const PrintSummary s = summarizePrint(handMadePath(), PrintSummaryOptions{});
  EXPECT_EQ(s.points, 5);
  EXPECT_EQ(s.layers, 2);
  EXPECT_EQ(s.subgraphs, 2);
  EXPECT_DOUBLE_EQ(s.printLength, 16.0);
  EXPECT_DOUBLE_EQ(s.airLength, 5.0);
  EXPECT_DOUBLE_EQ(s.printSeconds, 10.0 / 10.0 + 6.0 / 20.0);
  EXPECT_DOUBLE_EQ(s.airSeconds, 5.0 / 50.0);
  EXPECT_DOUBLE_EQ(s.filamentLength, 100.0);
  // 100 mm of 1.75 mm filament = 240.5 mm³ = 0.2405 cm³; PLA 1.24 g/cm³.
  EXPECT_NEAR(s.filamentMass, 100.0 * M_PI * 0.875 * 0.875 * 1e-3 * 1.24, 1e-12);
  EXPECT_NEAR(s.filamentMass, 0.298, 1e-3);
  PrintSummaryOptions petg;
  petg.filamentDensity = 1.27;
  EXPECT_NEAR(summarizePrint(handMadePath(), petg).filamentMass, 0.298 * 1.27 / 1.24, 1e-3);
}

TEST(PrintSummary, BadInputIsNamed) {
  auto expectError = [](const PrintSummaryInput& in, const PrintSummaryOptions& o,
                        const std::string& text) {
    try {
      summarizePrint(in, o);
      ADD_FAILURE() << "no error for " << text;
    } catch (const GeoLatticeError& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  PrintSummaryInput in = handMadePath();
  in.feedRate[2] = 0.0;
  expectError(in, {}, "toolpath point 2 has feed rate");
  in = handMadePath();
  in.layer.pop_back();
  expectError(in, {}, "different lengths");
  PrintSummaryOptions o;
  o.filamentDensity = -1;
  expectError(handMadePath(), o, "filament density must be > 0");
  EXPECT_EQ(summarizePrint(PrintSummaryInput{}, {}).points, 0);  // an empty path sums to zero
}
