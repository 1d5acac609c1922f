#pragma once
// The text of a rendered report for tests: every page joined, or one page.
#include <string>
#include <vector>

#include "report_writer.h"

namespace ballbench {

// Every page, REPORT.md first, each after a line "<!-- PATH -->".
inline std::string all_pages(const std::vector<ReportPage>& pages) {
  std::string out;
  for (const ReportPage& p : pages) out += "<!-- " + p.path + " -->\n" + p.text;
  return out;
}

// The page at `path` ("scenes/pile.md"), or "" where the report has none.
inline std::string page_text(const std::vector<ReportPage>& pages, const std::string& path) {
  for (const ReportPage& p : pages)
    if (p.path == path) return p.text;
  return "";
}

}  // namespace ballbench
