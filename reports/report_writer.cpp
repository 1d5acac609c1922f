#include "report_writer.h"

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "accuracy_section.h"
#include "calibration_section.h"
#include "engines_section.h"
#include "friction_section.h"
#include "frontier_section.h"
#include "ordered_set.h"
#include "page_links.h"
#include "scaling_section.h"
#include "scene_section.h"
#include "summary_section.h"
#include "sweep_section.h"
#include "terms_section.h"

namespace ballbench {
namespace {

using Figures = std::vector<Figure>;

// A page of evidence that is not a scene's: its file, its title and what it holds (empty: no page).
struct SectionPage {
  const char* path;
  const char* title;
  std::string (*body)(const ReportInputs&, const Figures&);
};

std::string sweeps(const ReportInputs& in, const Figures& figures) {
  std::string md;
  for (const SweepResult& sw : in.sweeps) md += sweep_section(sw, figures);
  return md;
}

std::string frontiers(const ReportInputs& in, const Figures& figures) {
  std::string md;
  for (const FrontierResult& f : in.frontiers) md += frontier_section(f, figures);
  return md;
}

const SectionPage kSectionPages[] = {
    {"pages/friction.md", "Friction",
     [](const ReportInputs& in, const Figures&) { return friction_section(in.results, table_scenes(in)); }},
    {"pages/work-precision.md", "Work against precision", sweeps},
    {"pages/stability.md", "Stability frontiers", frontiers},
    {"pages/scaling.md", "Scaling and the harness's overhead", scaling_section},
    {"pages/calibration.md", "Restitution calibration",
     [](const ReportInputs& in, const Figures&) { return in.calibration ? calibration_section(*in.calibration) : ""; }},
    {"pages/engines.md", "Engines, settings, machine", [](const ReportInputs& in, const Figures&) { return engines_section(in); }},
    {"pages/terms.md", "Terms", [](const ReportInputs& in, const Figures&) { return terms_section(in); }},
};

// The scenes with a page: the equal-accuracy scenes in the suite's order, then those with a table.
std::vector<std::string> page_scenes(const ReportInputs& in) {
  std::vector<std::string> scenes;
  for (const MatchResult& m : in.matches) add_once(scenes, m.scene);
  for (const std::string& s : table_scenes(in)) add_once(scenes, s);
  return scenes;
}

const MatchResult* match_of(const ReportInputs& in, const std::string& scene) {
  for (const MatchResult& m : in.matches)
    if (m.scene == scene) return &m;
  return nullptr;
}

ReportPage scene_page(const ReportInputs& in, const std::string& scene, const Figures& figures) {
  const MatchResult* m = match_of(in, scene);
  ReportPage page{scene_page_path(scene), fmt::format("`{}`", scene), ""};
  const std::string use_case = m && !m->use_case.empty() ? ": " + m->use_case : "";
  page.text = fmt::format("# `{}`{}\n\n", scene, use_case);
  if (const std::string line = scene_line(in, scene); !line.empty()) page.text += line + ".\n\n";
  if (m) page.text += accuracy_section(in, *m, figures);
  page.text += scene_section(in, scene, figures);
  return page;
}

// REPORT.md: the answer, then where the evidence is.
ReportPage front_page(const ReportInputs& in, const Figures& figures, const std::vector<ReportPage>& pages) {
  std::string md = "# ballbench report\n\n" + summary_section(in, figures);
  md += "## The evidence\n\n";
  std::vector<std::string> scenes, sections;
  for (const ReportPage& p : pages)
    (p.path.starts_with(kScenePagePrefix) ? scenes : sections).push_back(fmt::format("[{}]({})", p.title, p.path));
  if (!scenes.empty()) md += fmt::format("- One page per scene: {}.\n", fmt::join(scenes, ", "));
  if (!sections.empty()) md += fmt::format("- {}.\n", fmt::join(sections, ", "));
  md += "\nEvery number comes from the JSON files in [results/](results/), which the pages link to; the metrics are "
        "computed by the harness from the engines' states, never taken from an engine. Regenerate with "
        "`scripts/report` (`scripts/report --full` for the complete evidence).\n";
  return {"REPORT.md", "ballbench report", md};
}

}  // namespace

std::string scene_page_path(const std::string& scene) { return std::string(kScenePagePrefix) + scene + ".md"; }

std::vector<ReportPage> render_report(const ReportInputs& in, const Figures& figures) {
  std::vector<ReportPage> pages;
  for (const std::string& scene : page_scenes(in)) pages.push_back(scene_page(in, scene, figures));
  for (const SectionPage& s : kSectionPages)
    if (std::string body = s.body(in, figures); !body.empty())
      pages.push_back({s.path, s.title, fmt::format("# {}\n\n{}", s.title, body)});
  pages.insert(pages.begin(), front_page(in, figures, pages));
  resolve_links(pages);
  return pages;
}

}  // namespace ballbench
