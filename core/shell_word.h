#pragma once
// A word as a POSIX shell reads it back: the commands the harness prints (a run that reproduces a
// point, the command line a result was made by) must run as printed, whatever a path holds.
#include <string>

namespace ballbench {

// `word` as is where the shell takes it literally, else in single quotes (a quote inside as '\'').
std::string shell_word(const std::string& word);

}  // namespace ballbench
