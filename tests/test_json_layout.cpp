// The results files' JSON text: what it reads back as, and its lines.
#include <gtest/gtest.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "json_layout.h"

namespace ballbench {
namespace {

TEST(JsonLayout, ReadsBackAsWrittenWithNumbersOnOneLine) {
  const nlohmann::json j = nlohmann::json::parse(R"([{"a": [[1.5, -2], [3, null]], "b": {"c": "x\ny", "d": []},
    "e": [{"f": 1}, 2], "g": {}, "h": [0.1, 1e300]}, 7])");
  const std::string text = json_layout(j);
  EXPECT_EQ(nlohmann::json::parse(text), j);
  EXPECT_NE(text.find("\"a\": [[1.5,-2],[3,null]]"), std::string::npos) << text;  // numbers: one line
  EXPECT_NE(text.find("    \"e\": [\n      {\n        \"f\": 1\n      },\n      2\n    ]"), std::string::npos) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 17) << text;  // a line per key and element, but numbers
}

}  // namespace
}  // namespace ballbench
