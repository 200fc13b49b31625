#ifndef GLTestDefaults_h
#define GLTestDefaults_h
/**
 * @file GLTestDefaults.h
 * @brief Test helpers for the filters' DefaultsAndPrintSelf tests: the shared nozzle block's
 * defaults compared with core's NozzleModel (stated once, there), and "Print() mentions these".
 */
#include "vtkGLNozzle.h"

#include "nozzle/NozzleModel.h"

#include <gtest/gtest.h>
#include <vtkObject.h>

#include <cmath>
#include <initializer_list>
#include <sstream>
#include <string>

/// The nozzle block of a filter (vtkGLNozzleAlgorithm::GetNozzle) holds core's defaults; its
/// lengths say 0 where core's are unbounded (infinity).
inline void expectCoreNozzleDefaults(vtkGLNozzle* nozzle) {
  ASSERT_NE(nozzle, nullptr);
  const geolattice::NozzleModel core;
  auto property = [](double value) {
    return std::isfinite(value) ? value : 0.0;
  };
  EXPECT_EQ(nozzle->GetNozzleAngle(), core.halfAngleDeg);
  EXPECT_EQ(nozzle->GetNozzleLength(), property(core.length));
  EXPECT_EQ(nozzle->GetHolderRadius(), core.holderRadius);
  EXPECT_EQ(nozzle->GetHolderLength(), property(core.holderLength));
  EXPECT_EQ(nozzle->GetTipClearance(), core.tipClearance);
  EXPECT_EQ(nozzle->GetTipFaceRadius(), core.tipFaceRadius);
  EXPECT_EQ(nozzle->GetFaceContact(), core.faceContact);
}

/// Each of `texts` appears in object->Print().
inline void expectPrintMentions(vtkObject* object, std::initializer_list<std::string> texts) {
  std::ostringstream os;
  object->Print(os);
  for (const std::string& text : texts) {
    EXPECT_NE(os.str().find(text), std::string::npos) << text << " not in:\n" << os.str();
  }
}

#endif
