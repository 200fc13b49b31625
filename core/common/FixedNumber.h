#pragma once
/// @file FixedNumber.h
/// @brief Numbers for machine programs: fixed point, at most `decimals` decimals, trailing zeros
/// and a trailing point removed, never an exponent (RS274NGC would read "1e3" as an E word) and
/// never "-0". std::to_chars (correctly rounded, like printf's %.Nf, but without the locale and
/// format parsing): the writers print millions of them.
#include <charconv>
#include <string>

namespace geolattice {

/// Appends v to out (see the file comment).
inline void appendFixed(std::string& out, double v, int decimals) {
  char buf[400];  // a double's integer part has at most 309 digits
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  char* end = r.ptr;
  if (decimals > 0) {
    while (end[-1] == '0') {
      --end;
    }
    if (end[-1] == '.') {
      --end;
    }
  }
  if (end - buf == 2 && buf[0] == '-' && buf[1] == '0') {
    out += '0';
    return;
  }
  out.append(buf, end);
}

inline std::string fixedNumber(double v, int decimals) {
  std::string s;
  appendFixed(s, v, decimals);
  return s;
}

}  // namespace geolattice
