// GL Auto Orient and the pipeline's choice by the real toolpath, on the bundled branching Y:
// a candidate rank re-places the part from the cached search (no second search); with a nozzle
// that collides everywhere, ChooseOrientationByToolpath runs the next candidates and keeps the
// one that collides least.
#include "vtkGLAutoOrient.h"

#include "GLPrintPipeline.h"
#include "GLTestArrays.h"
#include "GLTestErrorObserver.h"
#include "vtkGLArrayNames.h"

#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <string>

namespace {
const std::string kData = GEOLATTICE_TESTDATA;

void fewCandidates(GLPrintPipeline& p) {
  p.Reader->SetFileName((kData + "/y_shape.obj").c_str());
  p.Orientation->SetOrient(vtkGLAutoOrient::AUTO);
  p.Orientation->SetSphereCandidates(12);
  p.Orientation->SetHullCandidates(4);
  p.Orientation->SetEvaluationTets(5000);
}
}  // namespace

TEST(vtkGLAutoOrient, ACandidateRankRePlacesThePartFromTheCachedSearch) {
  GLPrintPipeline p;
  fewCandidates(p);
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(p.Orientation);
  ASSERT_TRUE(p.Orientation->Update(0, nullptr)) << errors->Errors();
  vtkDataObject* out = p.Orientation->GetOutputDataObject(0);
  const double seconds = fieldValue(out, geolattice::arrays::OrientSeconds);
  const double up0[3] = {fieldValue(out, geolattice::arrays::OrientUp, 0),
                         fieldValue(out, geolattice::arrays::OrientUp, 1),
                         fieldValue(out, geolattice::arrays::OrientUp, 2)};
  EXPECT_EQ(fieldValue(out, geolattice::arrays::OrientChosenRank), 0);

  p.Orientation->SetCandidateRank(1);
  ASSERT_TRUE(p.Orientation->Update(0, nullptr)) << errors->Errors();
  out = p.Orientation->GetOutputDataObject(0);
  EXPECT_EQ(fieldValue(out, geolattice::arrays::OrientChosenRank), 1);
  EXPECT_EQ(fieldValue(out, geolattice::arrays::OrientSeconds), seconds);  // the same search
  double difference = 0;
  for (int k = 0; k < 3; ++k) {
    difference += std::abs(fieldValue(out, geolattice::arrays::OrientUp, k) - up0[k]);
  }
  EXPECT_GT(difference, 1e-3);              // another side up
  p.Orientation->SetCandidateRank(100000);  // clamped to the last candidate
  ASSERT_TRUE(p.Orientation->Update(0, nullptr));
  EXPECT_EQ(
      fieldValue(p.Orientation->GetOutputDataObject(0), geolattice::arrays::OrientChosenRank),
      fieldValue(p.Orientation->GetOutputDataObject(0), geolattice::arrays::OrientCandidates) - 1);

  // Another parameter searches again.
  p.Orientation->SetCandidateRank(0);
  p.Orientation->SetMinBaseArea(12);
  ASSERT_TRUE(p.Orientation->Update(0, nullptr));
  EXPECT_NE(fieldValue(p.Orientation->GetOutputDataObject(0), geolattice::arrays::OrientSeconds),
            seconds);
}

TEST(vtkGLAutoOrient, AsManyCandidatesAreRefinedAsTheToolpathMayTry) {
  // Only refined candidates are tried, so --orient-tries 12 must refine 12 (it refined the
  // default 4 and tried 5 on topopt); fewer tries keep the default.
  GLPrintPipeline p;
  p.Orientation->SetOrient(vtkGLAutoOrient::AUTO);
  const int byDefault = geolattice::OrientOptions{}.refineCandidates;
  p.OrientationTries = byDefault + 8;
  p.MatchOrientationToPrint();
  EXPECT_EQ(p.Orientation->GetRefineCandidates(), byDefault + 8);
  p.OrientationTries = 2;
  p.MatchOrientationToPrint();
  EXPECT_EQ(p.Orientation->GetRefineCandidates(), byDefault);
}

TEST(vtkGLAutoOrient, TheToolpathChoosesAmongTheSearchsBestCandidates) {
  GLPrintPipeline p;
  fewCandidates(p);
  p.Nozzle->SetNozzleAngle(80);  // so wide that every orientation collides
  p.LatticeInfill->SetAlphaWidth(8);
  p.LatticeInfill->SetBetaWidth(8);
  p.Slicer->SetLayerInterval(1.2);
  p.Slicer->SetFirstLayerOffset(1.2);
  p.MatchOrientationToPrint();
  vtkNew<GLTestErrorObserver> errors;
  errors->Observe(p.ToolpathVerifier);
  std::vector<int> started;
  const auto tries = p.ChooseOrientationByToolpath(
      3, [&](const GLPrintPipeline::OrientationTry& t) { started.push_back(t.rank); });
  // The three best besides the part as placed, and the placement where it ranks (the Y stands
  // on its feet): four tries in rank order, as nothing is collision-free.
  ASSERT_EQ(tries.size(), 4u) << errors->Errors();
  std::vector<int> after;
  for (size_t k = 1; k < tries.size(); ++k) {
    after.push_back(tries[k].rank);
  }
  EXPECT_EQ(started, after);
  auto* table = vtkPolyData::SafeDownCast(p.Orientation->GetOutputDataObject(1));
  ASSERT_NE(table, nullptr);
  auto* rank = table->GetPointData()->GetArray(geolattice::arrays::OrientRank);
  auto* source = vtkStringArray::SafeDownCast(
      table->GetPointData()->GetAbstractArray(geolattice::arrays::OrientSource));
  auto* pedestal = table->GetPointData()->GetArray(geolattice::arrays::Pedestal);
  ASSERT_TRUE(rank && source && pedestal);
  int placementRank = -1;
  for (vtkIdType i = 0; i < table->GetNumberOfPoints(); ++i) {
    if (source->GetValue(i) == "keep" && pedestal->GetTuple1(i) == 0) {
      placementRank = static_cast<int>(rank->GetTuple1(i));
    }
  }
  size_t best = 0;
  int placements = 0;
  for (size_t k = 0; k < tries.size(); ++k) {
    if (k > 0) {
      EXPECT_GT(tries[k].rank, tries[k - 1].rank);
    }
    placements += tries[k].rank == placementRank;
    EXPECT_TRUE(tries[k].ok);
    EXPECT_GT(tries[k].colliding, 0);
    EXPECT_GT(tries[k].stations, tries[k].colliding);
    if (tries[k].colliding < tries[best].colliding) {
      best = k;
    }
  }
  EXPECT_EQ(placements, 1);
  EXPECT_EQ(tries.back().rank, std::max(3, placementRank));
  EXPECT_EQ(p.Orientation->GetCandidateRank(), tries[best].rank);
  // Keep: nothing to try; one try is the search's best only.
  p.Orientation->SetOrient(vtkGLAutoOrient::KEEP);
  EXPECT_TRUE(p.ChooseOrientationByToolpath(3).empty());
  p.Orientation->SetOrient(vtkGLAutoOrient::AUTO);
  EXPECT_TRUE(p.ChooseOrientationByToolpath(1).empty());
}
