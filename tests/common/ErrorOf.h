#pragma once
/// @file ErrorOf.h
/// @brief The message of the GeoLatticeError a call throws, for tests of error messages.
#include "common/Error.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>

/// Message of the GeoLatticeError thrown by f, or nothing if none was thrown.
template <typename F>
std::optional<std::string> thrownError(F&& f) {
  try {
    f();
  } catch (const geolattice::GeoLatticeError& e) {
    return std::string(e.what());
  }
  return std::nullopt;
}

/// Message of the GeoLatticeError thrown by f, or "" if none was thrown.
template <typename F>
std::string errorOf(F&& f) {
  return thrownError(f).value_or("");
}

/// The same, and a test failure when f does not throw.
template <typename F>
std::string expectedErrorOf(F&& f) {
  const std::optional<std::string> m = thrownError(f);
  if (!m) {
    ADD_FAILURE() << "expected a GeoLatticeError";
  }
  return m.value_or("");
}
