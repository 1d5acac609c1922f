#include "lammps/mpi_engine.h"

#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "data_file.h"
#include "lammps/settings_record.h"
#include "process/child_process.h"

namespace ballbench::lammps {
namespace {

namespace fs = std::filesystem;

// A sample may take long (thousands of DEM steps per step, k steps); the runner's --timeout is what
// bounds a run, so this only keeps a wedged mpirun from blocking forever.
constexpr auto kSampleDeadline = std::chrono::hours(24);
constexpr size_t kOutputLinesKept = 12;  // of lmp's screen output, for error messages
constexpr const char* kMarker = "ballbench-sample ";

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out.flush()) throw std::runtime_error(fmt::format("lammps: cannot write {}", path.string()));
}

class MpiEngine final : public Engine {
 public:
  MpiEngine(const Scene& scene, const LammpsSettings& s, const Plan& plan) : scene_(scene), s_(s), plan_(plan) {
    state_ = scene.initial;
    state_.resize(scene.n(), rotation_);
    state_.pos = scene.initial.pos, state_.vel = scene.initial.vel;
    if (rotation_) {
      for (int i = 0; i < scene.n(); ++i) state_.w(i) = scene.spin(i);
      state_.angle.setZero();
    }
  }

  ~MpiEngine() override {
    child_.reset();  // closes lmp's stdin: its input ends and mpirun exits
    if (owned_dir_) {
      std::error_code ec;
      fs::remove_all(dir_, ec);
    }
  }
  MpiEngine(const MpiEngine&) = delete;
  MpiEngine& operator=(const MpiEngine&) = delete;

  // Counts the step; every sample_every steps runs them all in LAMMPS and reads the dump back.
  void step(double dt) override {
    if (dt != scene_.dt)
      throw std::runtime_error(fmt::format("lammps (ranks {}): steps the scene's dt {} s only, not {} s", s_.ranks, scene_.dt, dt));
    ++pending_;
    if (pending_ >= s_.sample_every) sample();
  }

  // A run that ends between samples is sampled here (its last few steps are then outside step()'s
  // timing).
  void read(State& out) const override {
    if (pending_ > 0) const_cast<MpiEngine*>(this)->sample();
    out = state_;
  }

  nlohmann::json settings() const override {
    nlohmann::json j = settings_record(scene_, s_, plan_);
    j["derived"]["command"] = command_line();
    if (!dir_.empty()) j["derived"]["files"] = dir_.string();
    return j;
  }
  int state_stride() const override { return s_.sample_every; }

 private:
  std::vector<std::string> command_line() const {
    std::vector<std::string> argv = {"env"};
    if (::geteuid() == 0)  // Open MPI refuses root without both
      argv.insert(argv.end(), {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"});
    argv.insert(argv.end(), {s_.mpirun, "-np", std::to_string(s_.ranks)});
    // Without a hostfile every rank runs here, one per core unless oversubscribed: more ranks than
    // cores is allowed (slower, never refused); a hostfile's slots say where ranks go.
    if (!s_.hostfile.empty()) argv.insert(argv.end(), {"--hostfile", s_.hostfile});
    else argv.push_back("--oversubscribe");
    const std::string input = dir_.empty() ? "WORKDIR/in.ballbench" : (dir_ / "in.ballbench").string();  // made by start()
    argv.insert(argv.end(), {s_.lmp, "-in", input, "-log", "none", "-echo", "none", "-nocite"});
    return argv;
  }

  // The folder, the input and data files, and the process. The input ends by reading further
  // commands from lmp's standard input, which mpirun forwards to rank 0.
  void start() {
    if (s_.workdir.empty()) {
      dir_ = make_work_folder("ballbench-lammps"), owned_dir_ = true;
    } else {
      dir_ = fs::absolute(s_.workdir);
      fs::create_directories(dir_);
    }
    write_file(dir_ / "balls.data", data_file(scene_));
    write_file(dir_ / "masses.txt", masses_file(scene_));
    write_file(dir_ / "in.ballbench", head_commands() +
                                          read_balls_commands((dir_ / "balls.data").string(), (dir_ / "masses.txt").string()) +
                                          body_commands(scene_, plan_) + "include /dev/stdin\n");
    child_ = std::make_unique<ChildProcess>(command_line(), dir_.string());
  }

  void sample() {
    if (!child_) start();
    const long steps = pending_;
    done_ += steps;
    pending_ = 0;
    const fs::path dump = dir_ / "sample.dump";
    // The first run sets up; later ones continue it as one long run would (pre no).
    const std::string commands = fmt::format(
        "run {} {}post no\nwrite_dump all custom {} id x y vx vy{} modify sort id format float %.17g\nprint \"{}{}\"\n",
        steps * plan_.substeps, set_up_ ? "pre no " : "", dump.string(), rotation_ ? " omegaz" : "", kMarker, done_);
    set_up_ = true;
    const auto deadline = ChildProcess::Clock::now() + kSampleDeadline;
    const std::string marker = kMarker + std::to_string(done_);
    try {
      child_->write(commands, deadline);
      for (std::string line; (line = child_->read_line(deadline, 1 << 16)) != marker;) {
        output_.push_back(line);
        if (output_.size() > kOutputLinesKept) output_.pop_front();
      }
    } catch (const ChildProcessError& e) {
      throw std::runtime_error(fmt::format("lammps: {} (at the sample of step {}); lmp's output ended: {}", e.what(), done_,
                                           fmt::join(output_, " | ")));
    }
    read_dump(dump, steps);
  }

  // ITEM: TIMESTEP / NUMBER OF ATOMS / BOX BOUNDS (3 lines) / ATOMS id x y vx vy [omegaz], sorted
  // by id, `steps` after the sample before. LAMMPS's spheres carry no orientation: the angle is the
  // adapter's, the trapezoid of the spins of this sample and the one before (for pictures).
  void read_dump(const fs::path& path, long steps) {
    std::ifstream in(path);
    std::string line;
    long atoms = -1;
    while (std::getline(in, line)) {
      if (line == "ITEM: NUMBER OF ATOMS") in >> atoms;
      if (line.rfind("ITEM: ATOMS", 0) == 0) break;
    }
    if (atoms != scene_.n())
      throw std::runtime_error(fmt::format("lammps: {} holds {} atoms, not the scene's {}", path.string(), atoms, scene_.n()));
    for (int i = 0; i < scene_.n(); ++i) {
      long id = 0;
      if (!(in >> id >> state_.pos(i, 0) >> state_.pos(i, 1) >> state_.vel(i, 0) >> state_.vel(i, 1)) || id != i + 1)
        throw std::runtime_error(fmt::format("lammps: {}: atom line {} unreadable or out of id order", path.string(), i + 1));
      if (rotation_) {
        double w = 0;
        if (!(in >> w)) throw std::runtime_error(fmt::format("lammps: {}: atom line {} has no omegaz", path.string(), i + 1));
        state_.angle(i) += 0.5 * (state_.w(i) + w) * static_cast<double>(steps) * scene_.dt;
        state_.w(i) = w;
      }
    }
    state_.t = static_cast<double>(done_) * scene_.dt;
  }

  Scene scene_;
  LammpsSettings s_;
  Plan plan_;
  bool rotation_ = scene_.features().rotation;  // omega z dumped, read back and integrated into angles
  fs::path dir_;
  bool owned_dir_ = false;
  std::unique_ptr<ChildProcess> child_;
  bool set_up_ = false;
  long pending_ = 0;  // steps asked for since the last sample
  long done_ = 0;     // steps sampled
  State state_;       // the last sample
  std::deque<std::string> output_;
};

}  // namespace

std::unique_ptr<Engine> make_mpi_engine(const Scene& scene, const LammpsSettings& s, const Plan& plan) {
  return std::make_unique<MpiEngine>(scene, s, plan);
}

}  // namespace ballbench::lammps
