# Writes OUT, a C++ source defining ballbench::kViewerTemplate as the text of IN (the viewer's page,
# reports/viewer/viewer.html) in a raw string literal, so that `ballbench` needs no file at run time.
# Run at build time by reports/CMakeLists.txt whenever IN changes.
file(READ "${IN}" text)
string(FIND "${text}" ")bbviewer\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${IN} holds the raw string's closing delimiter )bbviewer\"")
endif()
file(WRITE "${OUT}" "// Generated from ${IN} by reports/viewer/embed.cmake: do not edit.\n#include <string_view>\n\nnamespace ballbench {\nextern const std::string_view kViewerTemplate;\nconst std::string_view kViewerTemplate = R\"bbviewer(${text})bbviewer\";\n}  // namespace ballbench\n")
