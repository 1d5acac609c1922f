// One look per run across figures, the viewer and the GIFs (reports/palette.h).
#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <string>

#include "palette.h"
#include "registry.h"

namespace ballbench {
namespace {

TEST(Palette, EveryEngineOfTheRegistryHasAColourOfItsOwn) {
  std::set<std::string> colours;
  for (const std::string& engine : engine_names()) {
    const RunStyle s = run_style(engine, "default");
    EXPECT_TRUE(std::regex_match(s.colour, std::regex("#[0-9A-Fa-f]{6}"))) << engine << ": " << s.colour;
    EXPECT_TRUE(colours.insert(s.colour).second) << engine << " shares " << s.colour;
  }
  EXPECT_GE(colours.size(), 11u);
}

TEST(Palette, TheProfileIsTheLineStyleTheFirstSolid) {
  for (const std::string& engine : engine_names()) {
    if (!is_builtin_engine(engine)) continue;  // the others' profiles come from their processes
    const std::vector<std::string>& profiles = find_engine(engine).info.profiles;
    std::set<int> dashes;
    for (size_t k = 0; k < profiles.size(); ++k) {
      const RunStyle s = run_style(engine, profiles[k]);
      EXPECT_EQ(s.colour, run_style(engine, "default").colour) << engine << "/" << profiles[k];
      EXPECT_EQ(s.dash == 1, k == 0) << engine << "/" << profiles[k] << " dash " << s.dash;
      EXPECT_TRUE(dashes.insert(s.dash).second) << engine << "/" << profiles[k] << " looks like another profile";
      EXPECT_GE(s.dash, 1);
      EXPECT_LE(s.dash, kDashTypes);
    }
  }
}

TEST(Palette, UnknownNamesGetAStableLook) {
  const RunStyle a = run_style("someone-elses-engine", "fast"), b = run_style("someone-elses-engine", "fast");
  EXPECT_EQ(a.colour, b.colour);
  EXPECT_EQ(a.dash, b.dash);
  EXPECT_GE(a.dash, 2);  // not the look of a first profile
  EXPECT_LE(a.dash, kDashTypes);
  EXPECT_EQ(run_style("box2d", "stock-sleep").dash, 4);
  EXPECT_NE(track_colour(0), track_colour(1));
}

}  // namespace
}  // namespace ballbench
