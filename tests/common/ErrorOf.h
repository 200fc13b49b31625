#pragma once
/// @file ErrorOf.h
/// @brief The message of the GeoLatticeError a call throws, for tests of error messages.
#include "common/Error.h"

#include <gtest/gtest.h>

#include <string>

/// Message of the GeoLatticeError thrown by f, or "" if none was thrown.
template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const geolattice::GeoLatticeError& e) {
    return e.what();
  }
  return "";
}

/// The same, and a test failure when f does not throw.
template <typename F>
std::string expectedErrorOf(F&& f) {
  try {
    f();
  } catch (const geolattice::GeoLatticeError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a GeoLatticeError";
  return {};
}
