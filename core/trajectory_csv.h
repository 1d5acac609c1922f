#pragma once
// --trajectory output: CSV with header `engine,profile,step,t,id,x,y,vx,vy`, one row per ball per
// sample, step 0 being the initial state; a scene that rotates adds `w,angle` (rad/s, rad). `engine` and `profile` are the result JSON's fields of
// the same names, so the two join on them. Numbers are printed round-trip exact (shortest form that reads
// back to the same double), so metrics can be recomputed from the file independently.
#include <cstdio>
#include <string>

#include "state.h"

namespace ballbench {

class TrajectoryCsv {
 public:
  // Throws InputError if it cannot be opened. `rotation`: the states carry w and angle. The rows
  // go to `tmp` (default: a temporary file of this process's own beside `path`), renamed to `path`
  // by close(); a writer destroyed without close() removes it.
  TrajectoryCsv(const std::string& path, bool rotation, const std::string& tmp = "");
  ~TrajectoryCsv();
  TrajectoryCsv(const TrajectoryCsv&) = delete;
  TrajectoryCsv& operator=(const TrajectoryCsv&) = delete;

  void write(const std::string& engine, const std::string& profile, long step, const State& s);
  // Flushes and renames into place: "" if it did, else why writing failed ("File too large"), the
  // rows then removed and whatever was at the path kept. Throws InputError if the rename fails.
  std::string finish();
  void close();  // finish(), a failed write thrown as InputError naming the path

 private:
  std::string path_, tmp_;
  std::FILE* f_ = nullptr;
  int write_errno_ = 0;  // the first failed write's errno (ENOSPC, EFBIG), for the message
  bool rotation_;
};

}  // namespace ballbench
