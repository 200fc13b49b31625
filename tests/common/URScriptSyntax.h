#pragma once
/// @file URScriptSyntax.h
/// @brief The URScript syntax check shared by the core program tests and the writer filter tests.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <string>

/// The URScript rules every generated file must satisfy (issue 8: balanced def/end, one def
/// named defName (empty: any lower-case name), pose literals of 6 numbers with at most 6
/// decimals, t= and r= numbers, lines at most maxLine long); returns the number of movel commands.
inline size_t checkURScriptSyntax(const std::string& text, const std::string& defName,
                                  size_t maxLine) {
  std::istringstream in(text);
  std::string line;
  int depth = 0, defs = 0;
  size_t movels = 0;
  const std::regex number("-?[0-9]+(\\.[0-9]{1,6})?");
  const std::regex pose("p\\[([^\\]]*)\\]");
  bool first = true;
  while (std::getline(in, line)) {
    EXPECT_LE(line.size(), maxLine) << line;
    if (first && !defName.empty()) {
      EXPECT_EQ(line, "def " + defName + "():");
      first = false;
    }
    if (line.rfind("def ", 0) == 0) {
      ++depth;
      ++defs;
      EXPECT_TRUE(std::regex_match(line, std::regex("def [a-z][a-z_0-9]*\\(\\):"))) << line;
    } else if (line == "end") {
      --depth;
      EXPECT_GE(depth, 0);
    } else if (!line.empty()) {
      EXPECT_EQ(line.rfind("  ", 0), 0u) << "statements are inside the def: " << line;
      EXPECT_EQ(depth, 1) << line;
    }
    for (std::sregex_iterator it(line.begin(), line.end(), pose), end; it != end; ++it) {
      std::stringstream parts((*it)[1].str());
      std::string part;
      int count = 0;
      while (std::getline(parts, part, ',')) {
        part.erase(0, part.find_first_not_of(' '));
        EXPECT_TRUE(std::regex_match(part, number)) << "bad number '" << part << "' in " << line;
        ++count;
      }
      EXPECT_EQ(count, 6) << line;
    }
    for (const char* key : {"t=", "r="}) {
      const size_t at = line.find(key);
      if (at != std::string::npos) {
        std::string v = line.substr(at + 2);
        v = v.substr(0, v.find_first_of(",)"));
        EXPECT_TRUE(std::regex_match(v, number)) << line;
      }
    }
    movels += line.rfind("  movel(", 0) == 0;
  }
  EXPECT_EQ(depth, 0);
  EXPECT_EQ(defs, 1);
  EXPECT_EQ(text.substr(text.size() - 4), "end\n");
  return movels;
}
