#include "process_engine.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "input_error.h"
#include "protocol_client.h"

namespace ballbench {
namespace {

double& handshake_limit_s() {
  static double limit = 1e300;
  return limit;
}

// The processes of one engine entry that finished a run and wait for the next scene. Threads
// take and return them at once (a search's tries in parallel); each takes only one it started.
struct ProcessPool {
  ProcessEngineSpec spec;
  std::vector<std::string> settings_keys;

  std::unique_ptr<ProtocolClient> take() {
    {
      std::lock_guard lock(mutex_);
      // A fork's inherited copy, or one whose process failed or ended, serves nobody.
      std::erase_if(idle_, [](const auto& c) { return !c->usable() || c->has_exited(); });
      const auto mine = std::find_if(idle_.begin(), idle_.end(), [](const auto& c) { return c->serves_this_thread(); });
      if (mine != idle_.end()) {
        std::unique_ptr<ProtocolClient> c = std::move(*mine);
        idle_.erase(mine);
        return c;
      }
    }
    auto c = std::make_unique<ProtocolClient>(spec.command, spec.cwd, spec.timeout_s);
    c->send_hello();
    c->hello_reply();
    return c;
  }
  void give_back(std::unique_ptr<ProtocolClient> c) {
    std::lock_guard lock(mutex_);
    idle_.push_back(std::move(c));
  }

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<ProtocolClient>> idle_;
};

class ProcessEngine final : public Engine {
 public:
  ProcessEngine(std::shared_ptr<ProcessPool> pool, std::unique_ptr<ProtocolClient> client, nlohmann::json settings)
      : pool_(std::move(pool)), client_(std::move(client)), settings_(std::move(settings)) {}

  ~ProcessEngine() override {
    client_->unbound();  // the next run sets its own
    if (!broken_ && !batch_.failure && client_->usable()) pool_->give_back(std::move(client_));
  }
  ProcessEngine(const ProcessEngine&) = delete;
  ProcessEngine& operator=(const ProcessEngine&) = delete;

  void step(double dt) override {
    try {
      if (!client_->batches()) {
        charge(client_->step(dt, state_));
      } else {
        if (next_ == batch_.done) take_batch(dt);
        if (dt != batch_dt_)
          throw std::logic_error(fmt::format("a step of {} s asked of a batch stepped at {} s", dt, batch_dt_));
        std::swap(state_, batch_.states[size_t(next_)]);
        charge(batch_.times[size_t(next_++)]);
      }
      have_state_ = true;
      if (planned_ > 0) --planned_;
    } catch (...) {
      broken_ = true;  // the process is in an unknown state: never reused
      throw;
    }
  }

  void plan_steps(long steps) override { planned_ = std::max(0L, steps); }
  void bound_step(std::optional<std::chrono::steady_clock::time_point> wall_end, std::optional<double> cpu_s) override {
    client_->bound(wall_end, cpu_s);
  }

  void read(State& out) const override {
    if (!have_state_) {
      try {
        client_->read(state_);
      } catch (...) {
        broken_ = true;
        throw;
      }
      have_state_ = true;
    }
    out = state_;
  }

  nlohmann::json settings() const override {
    nlohmann::json s = settings_;
    // How the harness reached it: the command and the protocol are part of what produced the result.
    s["process"] = {{"command", pool_->spec.command},
                    {"cwd", pool_->spec.cwd},
                    {"protocol", client_->protocol()},
                    {"reply_timeout_s", pool_->spec.timeout_s},
                    {"cost_clock", client_->measures_wait()
                                       ? "its own step time less its wait for a core (/proc/PID/schedstat)"
                                       : "its own step time (this OS does not say how long it waited for a core)"}};
    return s;
  }

  std::optional<double> own_step_seconds() const override { return own_s_; }
  std::optional<double> own_step_cpu_seconds() const override { return alone_s_; }

 private:
  void charge(const ProtocolClient::StepTime& t) { own_s_ += t.own_s, alone_s_ += t.alone_s; }

  // The next steps, all of dt, in one request; the failure after the last step that arrived is
  // raised at the step it stopped.
  void take_batch(double dt) {
    if (batch_.failure) std::rethrow_exception(batch_.failure);
    const int count = batch_size();
    const auto t0 = std::chrono::steady_clock::now();
    client_->steps(dt, count, batch_);
    round_trip_per_step_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / count;
    batch_dt_ = dt, next_ = 0, last_batch_ = count;
    if (batch_.done == 0) std::rethrow_exception(batch_.failure);
  }

  // Twice the last batch, from one step: a run that stops early (a miss at step 3) steps little
  // past it. At most kMaxBatchSteps, the steps the caller plans, kMaxBatchBytes of states, and
  // about kBatchSeconds of the last round trips' pace: a batch never holds a reply long.
  int batch_size() const {
    constexpr long kMaxBatchSteps = 64;
    constexpr size_t kMaxBatchBytes = 4 << 20;
    constexpr double kBatchSeconds = 0.05;
    long k = std::min(2L * last_batch_, kMaxBatchSteps);
    if (planned_ >= 0) k = std::min(k, planned_);
    k = std::min<long>(k, long(kMaxBatchBytes / std::max<size_t>(1, client_->state_bytes())));
    if (round_trip_per_step_s_ > 0) k = std::min(k, long(kBatchSeconds / round_trip_per_step_s_));
    return int(std::max(1L, k));
  }

  std::shared_ptr<ProcessPool> pool_;
  std::unique_ptr<ProtocolClient> client_;
  nlohmann::json settings_;
  mutable State state_;  // the state after the last step: each step's reply carries it
  mutable bool have_state_ = false, broken_ = false;
  double own_s_ = 0, alone_s_ = 0;
  // Protocol 3: the steps taken ahead in one request, the next to hand out, and what sizes the next.
  ProtocolClient::Batch batch_;
  int next_ = 0;
  double batch_dt_ = 0;
  long last_batch_ = 0, planned_ = -1;  // planned_: steps the caller still takes (-1: not said)
  double round_trip_per_step_s_ = 0;
};

std::string display_name(const ProcessEngineSpec& spec) {
  if (!spec.name.empty()) return spec.name;
  return fmt::format("process:{}", fmt::join(spec.command, " "));
}

// An entry for an engine whose process could not start or answer.
EngineEntry broken_entry(const ProcessEngineSpec& spec, const std::string& why) {
  EngineEntry e;
  e.info.name = display_name(spec);
  e.info.version = "-";
  e.info.summary = fmt::format("external engine process ({})", spec.source);
  e.info.profiles = {"default"};
  e.info.costly_runs = true;
  // Each costs a process start and tens of microseconds per ball-step, which the report's bench run
  // would pay many times: the step benchmark stops at 10^3 balls.
  e.info.bench.sizes = {.free_balls = 1000, .fluid_balls = 1000, .settled_balls = 1000};
  // A registered engine that cannot run here (say, Node is not installed) is listed as unavailable
  // and its rows are unsupported; one named on the command line is a failed row with the reason.
  if (!spec.name.empty()) e.info.unavailable = why;
  e.create = [why](const Scene&, const std::string&, const nlohmann::json&) -> std::unique_ptr<Engine> {
    throw std::runtime_error(why);
  };
  return e;
}

EngineEntry working_entry(const ProcessEngineSpec& spec, Handshake h, std::unique_ptr<ProtocolClient> first) {
  auto pool = std::make_shared<ProcessPool>();
  pool->spec = spec;
  pool->settings_keys = h.settings_keys;
  first->set_reply_timeout(spec.timeout_s);  // its handshake's limit may have been a command's shorter one
  pool->give_back(std::move(first));
  EngineEntry e;
  e.info = std::move(h.info);
  e.info.own_process = true;
  if (!spec.name.empty()) e.info.name = spec.name;
  const std::string name = e.info.name;
  const std::vector<std::string> profiles = e.info.profiles;
  e.create = [pool, name, profiles](const Scene& scene, const std::string& profile, const nlohmann::json& settings) {
    if (std::find(profiles.begin(), profiles.end(), profile) == profiles.end())
      throw InputError(fmt::format("{}: unknown profile '{}' (known: {})", name, profile, fmt::join(profiles, ", ")));
    for (const auto& [key, value] : settings.items())
      if (std::find(pool->settings_keys.begin(), pool->settings_keys.end(), key) == pool->settings_keys.end())
        throw InputError(fmt::format("settings.{}.{}: unknown setting{} (known: {})", name, key,
                                     did_you_mean(key, pool->settings_keys), fmt::join(pool->settings_keys, ", ")));
    std::unique_ptr<ProtocolClient> client = pool->take();
    nlohmann::json effective;
    try {
      effective = client->load_scene(scene, profile, settings);
    } catch (const SceneUnsupported&) {  // a refusal in order: the process serves the next scene
      if (client->usable()) pool->give_back(std::move(client));
      throw;
    }
    return std::unique_ptr<Engine>(std::make_unique<ProcessEngine>(pool, std::move(client), std::move(effective)));
  };
  return e;
}

}  // namespace

void limit_handshake_seconds(double seconds) { handshake_limit_s() = seconds; }

std::vector<EngineEntry> process_engine_entries(const std::vector<ProcessEngineSpec>& specs) {
  std::vector<std::unique_ptr<ProtocolClient>> clients(specs.size());
  std::vector<std::string> errors(specs.size());
  for (size_t k = 0; k < specs.size(); ++k) {
    try {
      clients[k] = std::make_unique<ProtocolClient>(specs[k].command, specs[k].cwd,
                                                    std::min(specs[k].timeout_s, handshake_limit_s()));
      clients[k]->send_hello();
    } catch (const std::exception& e) {
      errors[k] = e.what();
    }
  }
  std::vector<EngineEntry> out;
  for (size_t k = 0; k < specs.size(); ++k) {
    if (errors[k].empty()) {
      try {
        Handshake h = clients[k]->hello_reply(true);  // before any run: a stop request ends the wait
        out.push_back(working_entry(specs[k], std::move(h), std::move(clients[k])));
        continue;
      } catch (const std::exception& e) {
        errors[k] = e.what();
      }
    }
    out.push_back(broken_entry(specs[k], errors[k]));
  }
  return out;
}

EngineEntry process_engine_entry(const ProcessEngineSpec& spec) { return process_engine_entries({spec}).front(); }

ProcessEngineSpec parse_process_engine(const std::string& text) {
  ProcessEngineSpec spec;
  std::istringstream in(text.substr(text.find(':') + 1));
  for (std::string word; in >> word;) spec.command.push_back(word);
  if (spec.command.empty()) throw InputError(fmt::format("--engine '{}': no command after 'process:'", text));
  spec.source = "--engine";
  return spec;
}

}  // namespace ballbench
