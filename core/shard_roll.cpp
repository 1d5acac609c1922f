#include "shard_roll.h"

#include <fmt/format.h>

#include "input_error.h"

namespace ballbench {

ShardRoll::ShardRoll(int count, std::vector<std::string> names)
    : count_(count), names_(std::move(names)), seen_(count + 1) {}

void ShardRoll::take(size_t k, int index, const std::string& interrupted) {
  if (index < 1 || index > count_)
    throw InputError(fmt::format("merge: {}: shard {}/{} is not a shard", names_[k], index, count_));
  if (!seen_[index].empty())
    throw InputError(fmt::format("merge: {} and {} are both shard {}/{}", seen_[index], names_[k], index, count_));
  if (!interrupted.empty())
    throw InputError(fmt::format("merge: {} was interrupted ({}); run its shard again", names_[k], interrupted));
  seen_[index] = names_[k];
}

void ShardRoll::check_complete() const {
  for (int i = 1; i <= count_; ++i)
    if (seen_[i].empty()) throw InputError(fmt::format("merge: shard {}/{} is missing", i, count_));
}

}  // namespace ballbench
