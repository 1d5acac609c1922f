#include "recorded_reference.h"

#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <exception>
#include <thread>

#include <fmt/format.h>

#include "interrupt.h"
#include "isolated_run.h"
#include "scene_digest.h"

namespace ballbench {
namespace {

// What the recording child tells its parent, at the start of the shared block.
struct Header {
  long recorded = -1;     // the last scene step whose state is written
  long failed_step = -1;
  bool spins = false;     // its states carry w and angle (as read at step 0)
  bool reshaped = false;  // a later state was read in another shape: the recording is not used
  char failure[1024] = {};
};

// Room per state: t, then x, y, vx, vy, w and angle of each ball (w and angle only written where
// the reference reads them: a state is replayed in the shape it was read).
long state_doubles(int n) { return 1 + long(n) * 6; }

void put(const State& s, bool spins, double* out) {
  const int n = s.n();
  *out++ = s.t;
  for (int i = 0; i < n; ++i) *out++ = s.pos(i, 0), *out++ = s.pos(i, 1), *out++ = s.vel(i, 0), *out++ = s.vel(i, 1);
  for (int i = 0; i < (spins ? n : 0); ++i) *out++ = s.w(i), *out++ = s.angle(i);
}

State get(const double* in, int n, bool spins) {
  State s;
  s.resize(n, spins);
  s.t = *in++;
  for (int i = 0; i < n; ++i) s.pos(i, 0) = *in++, s.pos(i, 1) = *in++, s.vel(i, 0) = *in++, s.vel(i, 1) = *in++;
  for (int i = 0; i < (spins ? n : 0); ++i) s.w(i) = *in++, s.angle(i) = *in++;
  return s;
}

// The child: steps the reference as a run would beside an engine, writing each scene step's state.
[[noreturn]] void record_in_child(const Scene& scene, const ReferenceChoice& choice, long steps, Header* header,
                                  double* states, long doubles) {
  Scene ref_scene = scene;
  ref_scene.dt = scene.dt / choice.substeps;
  long k = 0;
  try {
    auto engine = choice.entry->create(ref_scene, choice.entry->info.profiles.front(),
                                       merged_settings(scene, choice.entry->info.name, {}));
    State s;
    for (; k <= steps; ++k) {
      if (k > 0)
        for (int sub = 0; sub < choice.substeps; ++sub) engine->step(ref_scene.dt);
      engine->read(s);
      const bool spins = s.w.size() == scene.n() && s.angle.size() == scene.n();
      if (k == 0) header->spins = spins;
      if (s.n() != scene.n() || spins != header->spins || (!spins && (s.w.size() > 0 || s.angle.size() > 0))) {
        header->reshaped = true;
        break;
      }
      put(s, spins, states + k * doubles);
      header->recorded = k;
    }
  } catch (const std::exception& e) {
    header->failed_step = k;
    std::snprintf(header->failure, sizeof header->failure, "%s", e.what());
  }
  ::_exit(0);
}

// Waits for the child until it exits, the time limit passes or an interrupt comes (then kills it).
// True where it exited by itself.
bool wait_for(pid_t pid, double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  for (;;) {
    int status = 0;
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) return WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (done < 0) return false;
    if (interrupt_signal() || std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

class ReplayedReference : public Engine {
 public:
  explicit ReplayedReference(std::shared_ptr<const RecordedReference> recorded) : rec_(std::move(recorded)) {}

  void step(double) override {
    if (++sub_ < rec_->substeps) return;
    sub_ = 0, ++k_;
    if (k_ == rec_->failed_step) throw std::runtime_error(rec_->failure);
    if (k_ >= long(rec_->states.size())) throw std::runtime_error("stepped past the recorded reference");
  }
  void read(State& out) const override { out = rec_->states.at(size_t(k_)); }
  nlohmann::json settings() const override { return {{"replayed", rec_->engine}}; }

 private:
  std::shared_ptr<const RecordedReference> rec_;
  int sub_ = 0;
  long k_ = 0;
};

}  // namespace

ReferenceChoice choose_reference(const Scene& scene, const RunOptions& options) {
  ReferenceChoice c;
  c.entry = options.reference;
  if (!c.entry) return c;
  if (const std::string why = unsupported_reason(c.entry->info, scene); !why.empty()) {
    const EngineEntry* stand_in = options.converged_reference;
    if (stand_in && unsupported_reason(stand_in->info, scene).empty()) {
      c.entry = stand_in, c.substeps = kConvergedSubsteps;
    } else {
      c.skipped = fmt::format("error against the reference: {}, and no converged run stands in", why);
      c.entry = nullptr;
    }
  }
  return c;
}

std::shared_ptr<const RecordedReference> record_reference(const Scene& scene, const RunOptions& options,
                                                          double timeout_s) {
  const ReferenceChoice choice = choose_reference(scene, options);
  if (!choice.entry || scene.n() <= 0) return nullptr;
  const long steps = options.steps >= 0 ? options.steps : scene.steps();
  const long doubles = state_doubles(scene.n());
  const double bytes = double(steps + 1) * double(doubles) * sizeof(double) + sizeof(Header);
  if (steps < 0 || bytes > kMaxRecordedReferenceBytes) return nullptr;
  void* block = ::mmap(nullptr, size_t(bytes), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (block == MAP_FAILED) return nullptr;
  auto* header = new (block) Header;
  auto* states = reinterpret_cast<double*>(static_cast<char*>(block) + sizeof(Header));
  std::shared_ptr<RecordedReference> rec;
  const pid_t pid = ::fork();
  if (pid == 0) {
    close_inherited_files(-1);
    record_in_child(scene, choice, steps, header, states, doubles);
  }
  if (pid > 0 && wait_for(pid, timeout_s) && !header->reshaped) {
    rec = std::make_shared<RecordedReference>();
    rec->engine = choice.entry->info.name;
    rec->scene_digest = scene_digest(scene);
    rec->substeps = choice.substeps, rec->dt = scene.dt, rec->steps = steps;
    rec->failed_step = header->failed_step;
    rec->failure.assign(header->failure, strnlen(header->failure, sizeof header->failure));
    rec->states.reserve(size_t(header->recorded + 1));
    for (long k = 0; k <= header->recorded; ++k)
      rec->states.push_back(get(states + k * doubles, scene.n(), header->spins));
  }
  ::munmap(block, size_t(bytes));
  return rec;
}

bool recording_fits(const RecordedReference& recorded, const Scene& scene, const ReferenceChoice& choice,
                    long steps) {
  return choice.entry && recorded.engine == choice.entry->info.name && recorded.substeps == choice.substeps &&
         recorded.dt == scene.dt && recorded.steps >= steps && recorded.scene_digest == scene_digest(scene);
}

std::unique_ptr<Engine> replay_reference(std::shared_ptr<const RecordedReference> recorded) {
  return std::make_unique<ReplayedReference>(std::move(recorded));
}

}  // namespace ballbench
