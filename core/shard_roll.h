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
  // Takes the k-th file as shard `index`, made by `build` (run_context's "build"); throws
  // InputError naming it if the index is not one of the plan's, was taken already, the shard was
  // interrupted (`interrupted` names the signal), or another build made an earlier shard.
  void take(size_t k, int index, const std::string& interrupted, const std::string& build);
  // Throws InputError naming the first shard not taken.
  void check_complete() const;

 private:
  int count_;
  std::vector<std::string> names_, seen_;
  std::string build_, build_file_;
};

// Every item of a plan (a sweep's points, a match's searches, by label) once among the items the
// merged shards hold: throws InputError naming the first one missing, doubled or not planned.
// An empty plan (a file written before plans were recorded) checks nothing.
void check_plan_covered(const std::vector<std::string>& planned, const std::vector<std::string>& merged,
                        const std::string& what);

}  // namespace ballbench
