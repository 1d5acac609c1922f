// The closed-form checks as data: read back as written (an infinite figure included), and an
// engine whose handshake claims a capability that a closed form refutes is marked wherever the
// report shows it: the checks' table, its scene's table, the answer.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "conform_result.h"
#include "input_error.h"
#include "made_run.h"
#include "report_text.h"
#include "report_writer.h"
#include "result.h"

namespace ballbench {
namespace {

ConformResult checks() {
  ConformResult c;
  c.rows = {{"honest", "default", "slide-to-roll-disk", 0.05, 0.001, ConformVerdict::pass, "", ""},
            {"liar", "default", "slide-to-roll-disk", 0.05, 0.5, ConformVerdict::fail, "friction", ""},
            {"liar", "default", "gas-energy", 0.01, HUGE_VAL, ConformVerdict::fail, "", ""},
            {"plain", "default", "slide-to-roll-disk", 0.05, std::nullopt, ConformVerdict::refused, "", "no friction"}};
  return c;
}

TEST(ConformReport, TheChecksReadBackAsWritten) {
  const ConformResult back = conform_from_json(to_json(checks()));
  ASSERT_EQ(back.rows.size(), 4u);
  EXPECT_EQ(back.rows[1].refuted, "friction");
  EXPECT_TRUE(back.rows[2].figure && std::isinf(*back.rows[2].figure));
  EXPECT_FALSE(back.rows[3].figure);
  EXPECT_EQ(back.rows[3].verdict, ConformVerdict::refused);
  EXPECT_EQ(refuted_claims(back, "liar"), std::vector<std::string>{"friction"});
  EXPECT_TRUE(refuted_claims(back, "honest").empty());
  nlohmann::json bad = to_json(checks());
  bad["rows"][0]["verdict"] = "fine";
  EXPECT_THROW(conform_from_json(bad), InputError);
}

TEST(ConformReport, AnEngineWhoseClaimIsRefutedIsMarkedInItsScenesTable) {
  ReportInputs in;
  in.run = nlohmann::json::object();
  in.conform = checks();
  for (const char* engine : {"honest", "liar"}) in.results.push_back(made_run(engine, "box", 2, 10));
  const auto pages = render_report(in);
  const std::string scene = page_text(pages, "scenes/box.md"), engines = page_text(pages, "pages/engines.md");
  EXPECT_NE(scene.find("| liar [⚠ friction refuted](../pages/engines.md#closed-form-checks) | default |"),
            std::string::npos)
      << scene;
  EXPECT_NE(scene.find("| honest | default |"), std::string::npos) << scene;
  EXPECT_NE(engines.find("| liar | 0 | 2 | 0 | **friction** | slide-to-roll-disk 0.5 > 0.05; gas-energy inf > 0.01 |"),
            std::string::npos)
      << engines;
  EXPECT_NE(engines.find("| plain | 0 | 0 | 1 |"), std::string::npos) << engines;
}

}  // namespace
}  // namespace ballbench
