// The report's pages link as if each sat in the report's folder; resolve_links makes each link right
// for the page it landed on: files one folder up from a page under pages/, a heading's anchor to the
// page that holds it.
#include <gtest/gtest.h>

#include "page_links.h"

namespace ballbench {
namespace {

TEST(PageLinks, AnAnchorLeadsToThePageThatHoldsItsHeading) {
  std::vector<ReportPage> pages = {
      {"REPORT.md", "r", "# r\n\n[the pile](#equal-accuracy-pile) and [here](#r)\n"},
      {"scenes/pile.md", "pile", "# `pile`\n\n## Equal accuracy: `pile`\n\nBack [to the answer](#r), [terms](#profiles).\n"},
      {"pages/terms.md", "t", "# Terms\n\n## Profiles\n\nSee [pile](#equal-accuracy-pile).\n"},
  };
  resolve_links(pages);
  EXPECT_EQ(pages[0].text, "# r\n\n[the pile](scenes/pile.md#equal-accuracy-pile) and [here](#r)\n");
  EXPECT_NE(pages[1].text.find("[to the answer](../REPORT.md#r)"), std::string::npos) << pages[1].text;
  EXPECT_NE(pages[1].text.find("[terms](../pages/terms.md#profiles)"), std::string::npos) << pages[1].text;
  EXPECT_NE(pages[2].text.find("[pile](../scenes/pile.md#equal-accuracy-pile)"), std::string::npos) << pages[2].text;
}

TEST(PageLinks, AFileIsReachedFromThePagesFolderAndAnAddressIsLeftAlone) {
  std::vector<ReportPage> pages = {
      {"REPORT.md", "r", "![front](figures/fronts.png) [a](https://x.org/a.md) [s](../scenarios/README.md)\n"},
      {"scenes/pile.md", "p", "![front](figures/pile-front.png) [json](results/pile.json) [a](https://x.org/a.md) "
                              "[s](../scenarios/README.md#accuracy) [gone](#no-such-heading)\n"},
  };
  resolve_links(pages);
  EXPECT_EQ(pages[0].text, "![front](figures/fronts.png) [a](https://x.org/a.md) [s](../scenarios/README.md)\n");
  EXPECT_EQ(pages[1].text, "![front](../figures/pile-front.png) [json](../results/pile.json) [a](https://x.org/a.md) "
                           "[s](../../scenarios/README.md#accuracy) [gone](#no-such-heading)\n");
}

TEST(PageLinks, HeadingsInCodeBlocksAreNotAnchors) {
  EXPECT_EQ(page_anchors("# One `a`\n\n```sh\n# a comment\n```\n## Two: b\n"),
            (std::vector<std::string>{"one-a", "two-b"}));
}

}  // namespace
}  // namespace ballbench
