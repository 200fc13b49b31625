#pragma once
/// @file Error.h
/// @brief The one exception type core/ throws. Filters catch it and turn it into
/// vtkErrorMacro + an empty output; the CLI prints what() as one line on stderr.
#include <stdexcept>
#include <string>

namespace geolattice {

/// @class GeoLatticeError
/// @brief A failure with a message that names the problem (file, array, parameter, ...).
class GeoLatticeError : public std::runtime_error {
public:
  explicit GeoLatticeError(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace geolattice
