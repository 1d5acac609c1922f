#pragma once
// A section's figures of one kind (and scene: "" for none), as Markdown images with their captions.
#include <string>
#include <vector>

#include "markdown_buffer.h"
#include "report_writer.h"

namespace ballbench {

inline void put_figures(MarkdownBuffer& put, const std::vector<Figure>& figures, FigureKind kind,
                        const std::string& scene) {
  for (const Figure& f : figures)
    if (f.kind == kind && f.scene == scene) put("![{}]({})\n\n*{}*\n\n", f.caption, f.file, f.caption);
}

}  // namespace ballbench
