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
#include <vtkPolyData.h>

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
  // The three best, then the part as placed when it ranks lower (the Y stands on its feet).
  ASSERT_GE(tries.size(), 3u) << errors->Errors();
  ASSERT_LE(tries.size(), 4u);
  std::vector<int> after;
  for (size_t k = 1; k < tries.size(); ++k) {
    after.push_back(tries[k].rank);
  }
  EXPECT_EQ(started, after);
  size_t best = 0;
  for (size_t k = 0; k < tries.size(); ++k) {
    EXPECT_EQ(tries[k].rank, k < 3 ? static_cast<int>(k) : tries[k].rank);
    EXPECT_TRUE(tries[k].ok);
    EXPECT_GT(tries[k].colliding, 0);
    EXPECT_GT(tries[k].stations, tries[k].colliding);
    if (tries[k].colliding < tries[best].colliding) {
      best = k;
    }
  }
  EXPECT_EQ(p.Orientation->GetCandidateRank(), tries[best].rank);
  if (tries.size() == 4) {
    EXPECT_GT(tries[3].rank, 2);
    EXPECT_EQ(tries[3].pedestal, 0);
  }
  // Keep: nothing to try; one try is the search's best only.
  p.Orientation->SetOrient(vtkGLAutoOrient::KEEP);
  EXPECT_TRUE(p.ChooseOrientationByToolpath(3).empty());
  p.Orientation->SetOrient(vtkGLAutoOrient::AUTO);
  EXPECT_TRUE(p.ChooseOrientationByToolpath(1).empty());
}
