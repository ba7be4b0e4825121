// Well-formedness of the markup the reports write (HTML and SVG), without an XML library: tags
// close in order, and every '&' starts one of the entities the writer may use.
#pragma once

#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>
#include <vector>

namespace covmap::report::testing {

// `void_elements` never close (<meta>, <br>); a declaration (<!DOCTYPE>, <?xml ...?>) is skipped.
// `entities`: the alternation of entity names allowed after '&' ("amp|lt|gt").
inline void expect_well_formed_markup(const std::string& markup, const std::set<std::string>& void_elements,
                                      const std::string& entities) {
  std::vector<std::string> open;
  const std::regex tag(R"(<(/?)([A-Za-z!?][\w:-]*)[^>]*?(/?)>)");
  for (auto it = std::sregex_iterator(markup.begin(), markup.end(), tag); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    const std::string name = m[2];
    if (name.front() == '!' || name.front() == '?' || void_elements.count(name)) continue;
    if (m[1] == "/") {
      ASSERT_FALSE(open.empty()) << "stray </" << name << ">";
      ASSERT_EQ(open.back(), name);
      open.pop_back();
    } else if (m[3] != "/") {
      open.push_back(name);
    }
  }
  EXPECT_TRUE(open.empty()) << "unclosed <" << (open.empty() ? "" : open.back()) << ">";
  EXPECT_FALSE(std::regex_search(markup, std::regex("&(?!(" + entities + ");)")));
}

}  // namespace covmap::report::testing
