#include "run_status.h"

#include <ostream>

#include "enum_words.h"

namespace ballbench {
namespace {

constexpr EnumWords<RunStatus, 9> kWords{"run status",
                                         {{
                                             {RunStatus::ok, "ok"},
                                             {RunStatus::diverged, "diverged"},
                                             {RunStatus::failed, "failed"},
                                             {RunStatus::unsupported, "unsupported"},
                                             {RunStatus::interrupted, "interrupted"},
                                             {RunStatus::crashed, "crashed"},
                                             {RunStatus::timed_out, "timed out"},
                                             {RunStatus::missed, "missed"},
                                             {RunStatus::over_cost, "over cost"},
                                         }}};

}  // namespace

const char* run_status_text(RunStatus s) { return kWords.word(s); }

RunStatus run_status_from_text(std::string_view text) { return kWords.value(text); }

std::ostream& operator<<(std::ostream& os, RunStatus s) { return os << run_status_text(s); }

}  // namespace ballbench
