#pragma once
// Result files: whole-file writes that a reader never sees half done (the text goes to PATH.tmp,
// then a rename), and JSON reads that fail with one line naming the file.
#include <exception>
#include <string>

#include <nlohmann/json.hpp>

#include "input_error.h"

namespace ballbench {

// Creates the parent folders; throws InputError naming `path` and `what` ("the results file") if
// the file cannot be written.
void write_file_atomically(const std::string& path, const std::string& text, const std::string& what);

// Throws InputError naming the file and `what` if it cannot be opened or is not JSON.
nlohmann::json parse_json_file(const std::string& path, const std::string& what);
std::string json_shape_error(const std::string& path, const std::string& what, const std::exception& e);

// parse_json_file, then `convert` (JSON -> value); a field missing or of the wrong type is an
// InputError naming the file too.
template <class Convert>
auto read_json_file(const std::string& path, const std::string& what, Convert convert) {
  const nlohmann::json j = parse_json_file(path, what);
  try {
    return convert(j);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(json_shape_error(path, what, e));
  }
}

}  // namespace ballbench
