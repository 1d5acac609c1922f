#include "trajectory_csv.h"

#include <cerrno>
#include <filesystem>

#include <fmt/format.h>

#include "data_file.h"
#include "input_error.h"

namespace ballbench {

TrajectoryCsv::TrajectoryCsv(const std::string& path, bool rotation, const std::string& tmp)
    : path_(path), rotation_(rotation) {
  try {
    tmp_ = tmp.empty() ? create_temp_beside(temp_base(path), "the trajectory") : tmp;
  } catch (const InputError&) {
    throw InputError(fmt::format("--trajectory {}: cannot open for writing", path));
  }
  f_ = std::fopen(tmp_.c_str(), "w");
  if (!f_) {
    std::error_code ec;
    if (tmp.empty()) std::filesystem::remove(tmp_, ec);
    throw InputError(fmt::format("--trajectory {}: cannot open for writing", path));
  }
  std::fputs(rotation ? "engine,profile,step,t,id,x,y,vx,vy,w,angle\n" : "engine,profile,step,t,id,x,y,vx,vy\n", f_);
}

TrajectoryCsv::~TrajectoryCsv() {
  if (!f_) return;
  std::fclose(f_);
  std::error_code ec;
  std::filesystem::remove(tmp_, ec);
}

void TrajectoryCsv::write(const std::string& engine, const std::string& profile, long step, const State& s) {
  fmt::memory_buffer buf;
  for (int i = 0; i < s.n(); ++i) {
    fmt::format_to(std::back_inserter(buf), "{},{},{},{},{},{},{},{},{}", engine, profile, step, s.t, i, s.pos(i, 0),
                   s.pos(i, 1), s.vel(i, 0), s.vel(i, 1));
    if (rotation_) fmt::format_to(std::back_inserter(buf), ",{},{}\n", s.w(i), s.angle(i));
    else buf.push_back('\n');
  }
  if (std::fwrite(buf.data(), 1, buf.size(), f_) != buf.size() && !write_errno_) write_errno_ = errno;
}

std::string TrajectoryCsv::finish() {
  if (!f_) return "";
  const bool ok = std::fflush(f_) == 0 && !std::ferror(f_);
  if (!ok && !write_errno_) write_errno_ = errno;
  const bool closed = std::fclose(f_) == 0;
  if (!closed && !write_errno_) write_errno_ = errno;
  f_ = nullptr;
  std::error_code ec;
  if (!ok || !closed) {
    std::filesystem::remove(tmp_, ec);
    return write_error_text(write_errno_);
  }
  try {
    move_file_into_place(tmp_, path_, "the trajectory");
  } catch (const InputError&) {
    std::filesystem::remove(tmp_, ec);
    throw;
  }
  return "";
}

void TrajectoryCsv::close() {
  if (const std::string why = finish(); !why.empty())
    throw InputError(fmt::format("--trajectory {}: writing failed: {}", path_, why));
}

}  // namespace ballbench
