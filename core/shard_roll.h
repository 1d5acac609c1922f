#pragma once
// The shards `ballbench merge` is given of one plan (a sweep's, a match's): each shard once, none
// missing, none interrupted. Whether two shards are of the same plan is the caller's to judge.
#include <string>
#include <vector>

namespace ballbench {

class ShardRoll {
 public:
  // `names`: every shard's file, for messages; `count`: the plan's shard count.
  ShardRoll(int count, std::vector<std::string> names);
  // Takes the k-th file as shard `index`; throws InputError naming it if the index is not one of
  // the plan's, was taken already, or the shard was interrupted (`interrupted` names the signal).
  void take(size_t k, int index, const std::string& interrupted);
  // Throws InputError naming the first shard not taken.
  void check_complete() const;

 private:
  int count_;
  std::vector<std::string> names_, seen_;
};

}  // namespace ballbench
