#include "lammps/library_engine.h"

#include <lammps/library.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lammps/settings_record.h"

extern char** environ;

namespace ballbench::lammps {
namespace {

// Open MPI settings for this process's own MPI, started as a singleton by the first
// lammps_open_no_mpi: without them it starts an `orted` daemon and probes every network transport
// (measured: ~0.5 s per process); one rank needs only its own loopback (btl self, pml ob1). Each is
// set only where the environment does not set it already.
constexpr const char* kSingletonMca[][2] = {
    {"OMPI_MCA_ess_singleton_isolated", "1"}, {"OMPI_MCA_pml", "ob1"}, {"OMPI_MCA_btl", "self"}, {"OMPI_MCA_osc", "pt2pt"}};

std::set<std::string> environment_names() {
  std::set<std::string> names;
  for (char** e = environ; *e; ++e) names.emplace(*e, std::strcspn(*e, "="));
  return names;
}

// The library's error path exits the process (Debian's build has no LAMMPS_EXCEPTIONS): screen
// and log output off stdout (it carries ballbench's tables and JSON), and no log.cite file.
// MPI_Init reads the environment once, at the first open, and adds variables of its own
// (OMPI_MCA_ess=singleton, OMPI_COMMAND, PMIX_...) that would make an mpirun started from this
// process (ranks > 1) take itself for part of this job and fail: every variable that first open
// set is taken out again.
void* open_lammps() {
  static bool mpi_started = false;  // by an earlier open in this process or in the one it was forked from
  const bool first = !mpi_started && !std::getenv("OMPI_COMM_WORLD_SIZE");
  std::set<std::string> before;
  if (first) {
    before = environment_names();
    for (const auto& [key, value] : kSingletonMca) ::setenv(key, value, 0);
  }
  std::vector<std::string> args = {"ballbench", "-screen", "none", "-log", "none", "-nocite"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  void* h = lammps_open_no_mpi(static_cast<int>(argv.size()), argv.data(), nullptr);
  mpi_started = true;
  if (first)
    for (const std::string& name : environment_names())
      if (!before.count(name)) ::unsetenv(name.c_str());
  if (!h) throw std::runtime_error("lammps: lammps_open_no_mpi returned no instance");
  return h;
}

class LibraryEngine final : public Engine {
 public:
  LibraryEngine(const Scene& scene, const LammpsSettings& s, const Plan& plan)
      : scene_(scene), s_(s), plan_(plan), dt_(scene.dt), h_(open_lammps()) {
    version_ = lammps_version(h_);
    lammps_commands_string(h_, (head_commands() + box_commands(scene)).c_str());
    const int n = scene.n();
    std::vector<int> id(n), type(n, 1);
    std::vector<double> x(3 * n, 0.0), v(3 * n, 0.0), radius(n), mass(n);
    for (int i = 0; i < n; ++i) {
      id[i] = i + 1;
      x[3 * i] = scene.initial.pos(i, 0), x[3 * i + 1] = scene.initial.pos(i, 1);
      v[3 * i] = scene.initial.vel(i, 0), v[3 * i + 1] = scene.initial.vel(i, 1);
      radius[i] = scene.radius(i), mass[i] = scene.mass(i);
    }
    const int made = lammps_create_atoms(h_, n, id.data(), type.data(), x.data(), v.data(), nullptr, 0);
    if (made != n) {
      lammps_close(h_);
      throw std::runtime_error(fmt::format("lammps: lammps_create_atoms made {} of {} atoms", made, n));
    }
    lammps_scatter_atoms(h_, const_cast<char*>("radius"), 1, 1, radius.data());
    lammps_scatter_atoms(h_, const_cast<char*>("rmass"), 1, 1, mass.data());
    if (rotation_) {
      // Spins about z in one scatter of omega (3 per atom, x and y 0), as the radii and masses.
      std::vector<double> omega(3 * n, 0.0);
      for (int i = 0; i < n; ++i) omega[3 * i + 2] = scene.spin(i);
      lammps_scatter_atoms(h_, const_cast<char*>("omega"), 1, 3, omega.data());
      w_.resize(n), angle_.setZero(n);
      for (int i = 0; i < n; ++i) w_(i) = scene.spin(i);
    }
    lammps_commands_string(h_, body_commands(scene, plan).c_str());
    buf_.resize(3 * static_cast<size_t>(n));
  }

  ~LibraryEngine() override { lammps_close(h_); }
  LibraryEngine(const LibraryEngine&) = delete;
  LibraryEngine& operator=(const LibraryEngine&) = delete;

  void step(double dt) override {
    if (dt != dt_) {  // a step of another size: its own sub-step count and DEM step
      const long n = substeps_for(dt, plan_.model);
      if (n > s_.max_substeps)
        throw std::runtime_error(fmt::format("lammps: a step of {} s needs {} DEM sub-steps, above max_substeps = {}", dt,
                                             n, s_.max_substeps));
      plan_.substeps = static_cast<int>(n), plan_.dem_dt = dt / static_cast<double>(n), dt_ = dt;
      lammps_command(h_, const_cast<char*>(fmt::format("timestep {}", num(plan_.dem_dt)).c_str()));
      set_up_ = false;  // the integrator reads the timestep in its setup
    }
    // The first run sets up (neighbour lists, forces); later ones continue it exactly as one long
    // run would, so `pre no` skips the setup; `post no` skips the timing summary.
    const std::string run = fmt::format("run {} {}post no", plan_.substeps, set_up_ ? "pre no " : "");
    lammps_command(h_, const_cast<char*>(run.c_str()));
    set_up_ = true;
    t_ += dt;
    if (rotation_) {
      // LAMMPS's spheres carry no orientation: the angle is the adapter's, the trapezoid of the
      // spins at the step's two ends (exact for a constant spin; for pictures).
      gather_omega();
      const int n = scene_.n();
      for (int i = 0; i < n; ++i) {
        const double w = buf_[3 * i + 2];
        angle_(i) += 0.5 * (w_(i) + w) * dt;
        w_(i) = w;
      }
    }
  }

  void read(State& out) const override {
    const int n = scene_.n();
    out.t = t_;
    out.resize(n, rotation_);
    if (rotation_) out.w = w_, out.angle = angle_;  // as of the last step (the initial spins before the first)
    lammps_gather_atoms(h_, const_cast<char*>("x"), 1, 3, buf_.data());
    double z = 0;
    for (int i = 0; i < n; ++i) out.pos(i, 0) = buf_[3 * i], out.pos(i, 1) = buf_[3 * i + 1], z = std::max(z, std::abs(buf_[3 * i + 2]));
    lammps_gather_atoms(h_, const_cast<char*>("v"), 1, 3, buf_.data());
    for (int i = 0; i < n; ++i) out.vel(i, 0) = buf_[3 * i], out.vel(i, 1) = buf_[3 * i + 1], z = std::max(z, std::abs(buf_[3 * i + 2]));
    out_of_plane_ = z;
  }

  nlohmann::json settings() const override {
    nlohmann::json j = settings_record(scene_, s_, plan_);
    j["derived"]["library_version"] = version_;
    return j;
  }
  double out_of_plane() const override { return out_of_plane_; }
  int state_stride() const override { return s_.sample_every; }

 private:
  void gather_omega() const { lammps_gather_atoms(h_, const_cast<char*>("omega"), 1, 3, buf_.data()); }

  Scene scene_;
  LammpsSettings s_;
  Plan plan_;
  double dt_;
  void* h_;
  int version_ = 0;
  bool set_up_ = false;
  double t_ = 0;
  bool rotation_ = scene_.features().rotation;  // spins set, read back and integrated into angles
  Eigen::VectorXd w_, angle_;  // omega z after the last step (rad/s), and its integral (rad)
  mutable std::vector<double> buf_;  // 3 per atom, in id order
  mutable double out_of_plane_ = 0;  // the largest |z| or |vz| of the last read
};

}  // namespace

std::unique_ptr<Engine> make_library_engine(const Scene& scene, const LammpsSettings& s, const Plan& plan) {
  return std::make_unique<LibraryEngine>(scene, s, plan);
}

}  // namespace ballbench::lammps
