#include "shard_roll.h"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "input_error.h"

namespace ballbench {

ShardRoll::ShardRoll(int count, std::vector<std::string> names)
    : count_(count), names_(std::move(names)), seen_(count + 1) {}

void ShardRoll::take(size_t k, int index, const std::string& interrupted, const std::string& build) {
  if (index < 1 || index > count_)
    throw InputError(fmt::format("merge: {}: shard {}/{} is not a shard", names_[k], index, count_));
  if (!seen_[index].empty())
    throw InputError(fmt::format("merge: {} and {} are both shard {}/{}", seen_[index], names_[k], index, count_));
  if (!interrupted.empty())
    throw InputError(fmt::format("merge: {} was interrupted ({}); run its shard again", names_[k], interrupted));
  // A merged result is one build's measurement: shards of two builds may differ in what they computed.
  if (build_file_.empty()) build_ = build, build_file_ = names_[k];
  else if (build != build_)
    throw InputError(fmt::format("merge: {} was made by build {}, {} by build {}: run every shard with one ballbench",
                                 names_[k], build.empty() ? "(not recorded)" : build, build_file_,
                                 build_.empty() ? "(not recorded)" : build_));
  seen_[index] = names_[k];
}

void ShardRoll::check_complete() const {
  for (int i = 1; i <= count_; ++i)
    if (seen_[i].empty()) throw InputError(fmt::format("merge: shard {}/{} is missing", i, count_));
}

void check_plan_covered(const std::vector<std::string>& planned, const std::vector<std::string>& merged,
                        const std::string& what) {
  if (planned.empty()) return;
  std::map<std::string, int> count;
  for (const std::string& m : merged) ++count[m];
  for (const std::string& p : planned) {
    const int c = count[p];
    if (c == 0) throw InputError(fmt::format("merge: no shard holds the planned {} {}: run its shard again", what, p));
    if (c > 1) throw InputError(fmt::format("merge: the planned {} {} is in the shards {} times", what, p, c));
  }
  for (const auto& [m, c] : count)
    if (c > 0 && std::find(planned.begin(), planned.end(), m) == planned.end())
      throw InputError(fmt::format("merge: a shard holds {} {}, which the plan does not have", what, m));
}

}  // namespace ballbench
