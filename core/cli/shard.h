#pragma once
// `--shard I/N` (sweep, report): a deterministic share of a plan's work, so N machines (a Slurm job
// array, GNU parallel over ssh) run one plan between them and `ballbench merge` joins the results.
// Shard I takes the plan's items k with k % N == I - 1, so each shard mixes every engine.
#include <string>

namespace ballbench::cli {

struct Shard {
  int index = 1, count = 1;  // 1/1: the whole plan
  bool all() const { return count == 1; }
  bool takes(size_t item) const { return static_cast<int>(item % static_cast<size_t>(count)) == index - 1; }
};

// A command's default output: "STEM.json", or "STEM.shardIofN.json" for a shard.
std::string shard_file_name(const std::string& stem, const Shard& shard);

// "I/N" with whole numbers 1 <= I <= N; throws InputError naming `option` otherwise.
Shard parse_shard(const std::string& text, const std::string& option = "--shard");

}  // namespace ballbench::cli
