#pragma once
// The report's pages link to each other and to files beside them. Each section writes its links as
// if it sat in the report's folder: files relative to that folder ("figures/pile-front.png",
// "../scenarios/README.md") and headings by anchor alone ("#equal-accuracy-pile"), whichever page
// holds them. resolve_links then makes every link right for the page it landed on.
#include <string>
#include <vector>

#include "report_writer.h"

namespace ballbench {

// A Markdown heading's anchor as a code host makes it: lower case, punctuation dropped, spaces as '-'.
std::string heading_anchor(const std::string& heading);

// Rewrites each page's links: a relative file path from the report's folder to the page's folder, an
// anchor of a heading on another page to that page and anchor. An anchor no page holds is left as it
// is (a test of the pages finds it).
void resolve_links(std::vector<ReportPage>& pages);

// The anchors of a page's headings, in order.
std::vector<std::string> page_anchors(const std::string& markdown);

}  // namespace ballbench
