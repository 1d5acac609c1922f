#include "page_links.h"

#include <cctype>
#include <filesystem>
#include <map>

namespace ballbench {
namespace {

// "../" for each folder between the report's folder and the page's.
std::string up_from(const std::string& page) {
  std::string up;
  for (char c : page)
    if (c == '/') up += "../";
  return up;
}

bool is_external(const std::string& target) {
  return target.find("://") != std::string::npos || target.starts_with('/') || target.starts_with("mailto:");
}

// The link from `page` to `target` (both relative to the report's folder).
std::string relative_link(const std::string& page, const std::string& target) {
  namespace fs = std::filesystem;
  if (fs::path(page).parent_path() == fs::path(target).parent_path()) return fs::path(target).filename().string();
  return up_from(page) + target;
}

}  // namespace

std::string heading_anchor(const std::string& heading) {
  std::string out;
  for (char c : heading)
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') out += static_cast<char>(std::tolower(c));
    else if (c == ' ') out += '-';
  return out;
}

std::vector<std::string> page_anchors(const std::string& markdown) {
  std::vector<std::string> anchors;
  size_t at = 0;
  bool fenced = false;
  while (at < markdown.size()) {
    const size_t end = std::min(markdown.find('\n', at), markdown.size());
    const std::string line = markdown.substr(at, end - at);
    if (line.starts_with("```")) fenced = !fenced;
    if (!fenced && line.starts_with('#')) {
      const size_t text = line.find_first_not_of('#');
      if (text != std::string::npos && line[text] == ' ') anchors.push_back(heading_anchor(line.substr(text + 1)));
    }
    at = end + 1;
  }
  return anchors;
}

void resolve_links(std::vector<ReportPage>& pages) {
  std::map<std::string, std::string> page_of;  // anchor -> the first page that holds it
  for (const ReportPage& p : pages)
    for (const std::string& a : page_anchors(p.text)) page_of.emplace(a, p.path);
  for (ReportPage& p : pages) {
    std::string out;
    size_t at = 0;
    for (size_t open; (open = p.text.find("](", at)) != std::string::npos;) {
      const size_t start = open + 2, close = p.text.find(')', start);
      if (close == std::string::npos) break;
      std::string target = p.text.substr(start, close - start);
      if (target.starts_with('#')) {
        const auto it = page_of.find(target.substr(1));
        if (it != page_of.end() && it->second != p.path) target = relative_link(p.path, it->second) + target;
      } else if (!is_external(target)) {
        target = up_from(p.path) + target;
      }
      out.append(p.text, at, start - at);
      out += target;
      at = close;
    }
    out.append(p.text, at);
    p.text = std::move(out);
  }
}

}  // namespace ballbench
