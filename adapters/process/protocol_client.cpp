#include "protocol_client.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <string_view>

#include <fmt/format.h>

#include "input_error.h"

namespace ballbench {
namespace {

static_assert(std::endian::native == std::endian::little, "the protocol's doubles are little-endian, as this machine's");

constexpr size_t kMaxReplyLine = 1 << 20;  // a handshake or settings reply; states come as binary blocks

std::vector<double> column(const Eigen::Ref<const Eigen::VectorXd>& v) { return {v.data(), v.data() + v.size()}; }

std::string excerpt(const std::string& s) {
  std::string out = s.substr(0, 80);
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20) c = '?';
  return s.size() > 80 ? out + "..." : out;
}

// Two clocks read a step: the engine's around its step call, the harness's around the request and
// its reply. The first lies inside the second; this much (s) is left for their granularity.
constexpr double kStepClockTolerance = 1e-6;

// Capabilities by the keys the handshake uses; an unknown key is an error (a typo would silently
// keep a default).
Capabilities capabilities_from(const nlohmann::json& j, int protocol) {
  Capabilities c = default_capabilities(protocol);
  const std::pair<const char*, bool*> keys[] = {
      {"open_space", &c.open_space},         {"gravity", &c.gravity},
      {"per_ball_radius", &c.per_ball_radius}, {"per_ball_mass", &c.per_ball_mass},
      {"any_restitution", &c.any_restitution}, {"friction", &c.friction},
      {"continuous_collision", &c.continuous_collision}, {"deterministic", &c.deterministic}};
  if (!j.is_object()) throw std::runtime_error("'capabilities' is not an object");
  for (const auto& [key, value] : j.items()) {
    const auto it = std::find_if(std::begin(keys), std::end(keys), [&](const auto& k) { return key == k.first; });
    if (it == std::end(keys)) throw std::runtime_error(fmt::format("unknown capability '{}'", key));
    if (!value.is_boolean()) throw std::runtime_error(fmt::format("capability '{}' is not true or false", key));
    *it->second = value.get<bool>();
  }
  return c;
}

// A list of names, each once (a name given twice is taken once), none empty or holding a control
// character.
std::vector<std::string> strings_from(const nlohmann::json& j, const char* what, bool allow_empty) {
  if (!j.is_array() || (!allow_empty && j.empty())) throw std::runtime_error(fmt::format("'{}' is not a list of names", what));
  std::vector<std::string> out;
  for (const auto& s : j) {
    if (!s.is_string() || s.get<std::string>().empty()) throw std::runtime_error(fmt::format("'{}' holds a non-name", what));
    const std::string name = s.get<std::string>();
    if (has_control_character(name))
      throw std::runtime_error(fmt::format("'{}' holds '{}', a name with a control character", what, printable(name, 80)));
    if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
  }
  return out;
}

// The string field `key` of a reply ("" if optional and left out); the field named if it is not one.
std::string text_field(const nlohmann::json& j, const char* key, bool required) {
  const auto it = j.find(key);
  if (it == j.end()) {
    if (required) throw std::runtime_error(fmt::format("'{}' is missing", key));
    return "";
  }
  if (!it->is_string()) throw std::runtime_error(fmt::format("'{}' is not a string but {}", key, excerpt(it->dump())));
  return it->get<std::string>();
}

// Free text for `list` and the report, on one line.
std::string one_line_text(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  return s;
}

// The handshake's "speed_cap": {"what": NAME} with one of "m_per_s" (a speed), "m_per_step" (a
// distance per step call: the speed is it over dt) or "setting" (the key of its effective settings
// that holds the speed, in m/s). A cap the harness cannot read is refused, not ignored.
std::function<std::optional<SpeedCap>(double, const nlohmann::json&)> speed_cap_from(
    const nlohmann::json& j, const std::vector<std::string>& settings_keys) {
  if (!j.is_object()) throw std::runtime_error("'speed_cap' is not an object");
  const std::string what = one_line_text(text_field(j, "what", true));
  int given = 0;
  for (const char* k : {"m_per_s", "m_per_step", "setting"}) given += j.contains(k);
  if (given != 1) throw std::runtime_error("'speed_cap' needs exactly one of 'm_per_s', 'm_per_step' and 'setting'");
  if (j.contains("setting")) {
    const std::string key = text_field(j, "setting", true);
    if (std::find(settings_keys.begin(), settings_keys.end(), key) == settings_keys.end())
      throw std::runtime_error(fmt::format("'speed_cap' reads setting '{}', which is not in 'settings_keys'", excerpt(key)));
    return [key, what](double, const nlohmann::json& settings) -> std::optional<SpeedCap> {
      const auto v = settings.find(key);
      if (v == settings.end() || !v->is_number() || !(v->get<double>() > 0)) return std::nullopt;
      return SpeedCap{v->get<double>(), what};
    };
  }
  const char* key = j.contains("m_per_s") ? "m_per_s" : "m_per_step";
  if (!j[key].is_number() || !(j[key].get<double>() > 0) || !std::isfinite(j[key].get<double>()))
    throw std::runtime_error(fmt::format("'speed_cap.{}' is not a number above 0", key));
  const double value = j[key].get<double>();
  const bool per_step = key == std::string("m_per_step");
  return [value, per_step, what](double dt, const nlohmann::json&) -> std::optional<SpeedCap> {
    return SpeedCap{per_step ? value / dt : value, what};
  };
}

}  // namespace

Capabilities default_capabilities(int protocol) {
  Capabilities c;  // core/engine.h's defaults, which protocol version 1 kept
  if (protocol >= 2) c.friction = false;  // an engine claims rotation only by saying so
  return c;
}

ProtocolClient::ProtocolClient(const std::vector<std::string>& argv, const std::string& cwd, double timeout_s)
    : child_(argv, cwd), wait_(child_.pid()), timeout_s_(timeout_s) {}

void ProtocolClient::send_hello() {
  const nlohmann::json hello = {{"op", "hello"}, {"protocol", kProtocolVersion}};
  child_.write(hello.dump() + "\n", ChildProcess::Clock::now() + std::chrono::duration_cast<ChildProcess::Clock::duration>(
                                                                    std::chrono::duration<double>(timeout_s_)));
}

Handshake ProtocolClient::hello_reply(bool stop_on_interrupt) {
  const nlohmann::json j = reply("hello", stop_on_interrupt);
  try {
    const nlohmann::json version = j.value("protocol", nlohmann::json());
    if (!version.is_number_integer() || version.get<int>() < kOldestProtocolVersion ||
        version.get<int>() > kProtocolVersion)
      throw std::runtime_error(fmt::format("it speaks protocol version {}, the harness {} (and {} to {})",
                                           excerpt(version.dump()), kProtocolVersion, kOldestProtocolVersion,
                                           kProtocolVersion));
    Handshake h;
    h.protocol = protocol_ = version.get<int>();
    h.info.name = text_field(j, "name", true);
    h.info.version = one_line_text(text_field(j, "version", true));
    h.info.summary = one_line_text(text_field(j, "summary", false));
    h.info.limits = one_line_text(text_field(j, "limits", false));
    if (!j.contains("capabilities")) throw std::runtime_error("'capabilities' is missing");
    h.info.caps = capabilities_from(j["capabilities"], protocol_);
    if (!j.contains("profiles")) throw std::runtime_error("'profiles' is missing");
    h.info.profiles = strings_from(j["profiles"], "profiles", false);
    for (const std::string& p : h.info.profiles)
      if (p == "all") throw std::runtime_error("'profiles' holds 'all', which --profile uses for every profile");
    const std::string precision = j.contains("precision") ? text_field(j, "precision", true) : "double";
    if (precision != "double" && precision != "float")
      throw std::runtime_error(fmt::format("'precision' is '{}', not \"double\" or \"float\"", excerpt(precision)));
    float_precision_ = precision == "float";
    h.info.costly_runs = true;  // every run starts the engine's process (a Node engine: 0.1 to 0.4 s)
    h.info.bench.sizes = {.free_balls = 1000, .fluid_balls = 1000, .settled_balls = 1000};  // as process_engine.cpp's
    h.settings_keys = strings_from(j.value("settings_keys", nlohmann::json::array()), "settings_keys", true);
    const nlohmann::json knobs = j.contains("sweep_knobs") ? j["sweep_knobs"] : nlohmann::json::array();
    if (!knobs.is_array()) throw std::runtime_error("'sweep_knobs' is not a list");
    for (const auto& k : knobs) {
      if (!k.is_object()) throw std::runtime_error("'sweep_knobs' holds an entry that is not {\"key\": ..., \"values\": [...]}");
      const std::string key = text_field(k, "key", true);
      if (std::find(h.settings_keys.begin(), h.settings_keys.end(), key) == h.settings_keys.end())
        throw std::runtime_error(fmt::format("'sweep_knobs' varies '{}', which is not in 'settings_keys'", excerpt(key)));
      if (!k.contains("values") || !k["values"].is_array() || k["values"].empty())
        throw std::runtime_error(fmt::format("'sweep_knobs' entry '{}' has no list of 'values'", excerpt(key)));
      h.info.sweep_knobs.push_back({key, k.at("values")});
    }
    if (j.contains("speed_cap")) h.info.speed_cap = speed_cap_from(j["speed_cap"], h.settings_keys);
    const auto fields = strings_from(j.value("state_fields", nlohmann::json::array({"id", "x", "y", "vx", "vy"})), "state_fields", false);
    for (const char* need : {"id", "x", "y", "vx", "vy"})
      if (std::find(fields.begin(), fields.end(), need) == fields.end())
        throw std::runtime_error(fmt::format("'state_fields' lacks '{}'", need));
    if (h.info.name.empty() || h.info.name.find_first_of(" ,.=:/") != std::string::npos ||
        has_control_character(h.info.name) || h.info.name == "all")
      throw std::runtime_error(fmt::format("name '{}' is empty, 'all', or holds a control character or one of ' ,.=:/'",
                                           printable(h.info.name, 80)));
    return h;
  } catch (const nlohmann::json::exception& e) {
    throw child_.failure(fmt::format("sent a handshake the harness cannot read: {}", e.what()));
  } catch (const ChildProcessError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw child_.failure(fmt::format("sent a handshake the harness cannot use: {}", e.what()));
  }
}

nlohmann::json ProtocolClient::load_scene(const Scene& scene, const std::string& profile, const nlohmann::json& settings) {
  nlohmann::json container = {{"kind", scene.container.kind == ContainerKind::Box ? "box" : "none"}};
  if (scene.container.kind == ContainerKind::Box)
    container["min"] = {scene.container.min.x(), scene.container.min.y()},
    container["max"] = {scene.container.max.x(), scene.container.max.y()};
  rotation_ = scene.features().rotation;
  nlohmann::json balls = {{"n", scene.n()},
                                {"x", column(scene.initial.pos.col(0))},
                                {"y", column(scene.initial.pos.col(1))},
                                {"vx", column(scene.initial.vel.col(0))},
                                {"vy", column(scene.initial.vel.col(1))},
                                {"radius", column(scene.radius)},
                                {"mass", column(scene.mass)}};
  if (rotation_) {  // each ball's initial spin (rad/s); none for a scene that does not rotate
    Eigen::VectorXd spins(scene.n());
    for (int i = 0; i < scene.n(); ++i) spins(i) = scene.spin(i);
    balls["w"] = column(spins);
  }
  const nlohmann::json message = {
      {"op", "scene"},
      {"profile", profile},
      {"settings", settings.is_object() ? settings : nlohmann::json::object()},
      {"scene",
       {{"name", scene.name},
        {"dt", scene.dt},
        {"gravity", {scene.gravity.x(), scene.gravity.y()}},
        {"restitution", scene.restitution},
        {"friction", scene.friction},
        {"inertia", inertia_name(scene.inertia)},
        {"inertia_factor", inertia_factor(scene.inertia)},
        {"rotation", rotation_},
        {"container", container},
        {"balls", balls}}}};
  n_ = scene.n();
  steps_ = 0, t_ = 0;
  const nlohmann::json j = request(message, "scene");
  if (j.contains("settings") && !j["settings"].is_object())
    throw child_.failure(fmt::format("sent garbage in reply to 'scene': 'settings' is not an object but {}",
                                     excerpt(j["settings"].dump())));
  return j.contains("settings") ? j["settings"] : nlohmann::json::object();
}

ProtocolClient::StepTime ProtocolClient::step(double dt, State& out) {
  const auto sent = ChildProcess::Clock::now();
  const nlohmann::json j = request({{"op", "step"}, {"dt", dt}, {"read", true}}, "step");
  const double round_trip = std::chrono::duration<double>(ChildProcess::Clock::now() - sent).count();
  ++steps_, t_ += dt;
  const auto it = j.find("step_s");
  if (it == j.end())
    throw child_.failure(fmt::format("sent garbage in reply to 'step' {}: no step time 'step_s' in '{}'", steps_,
                                     excerpt(j.dump())));
  const double own = checked_step_time(*it, round_trip);
  read_state(j, out, "step");
  return {own, own * (1 - wait_share(round_trip))};
}

void ProtocolClient::steps(double dt, int count, Batch& out) {
  out.done = 0;
  out.failure = nullptr;
  if (out.states.size() < size_t(count)) out.states.resize(size_t(count)), out.times.resize(size_t(count));
  const auto sent = ChildProcess::Clock::now();
  const nlohmann::json j = request({{"op", "steps"}, {"dt", dt}, {"count", count}}, "steps");
  const double round_trip = std::chrono::duration<double>(ChildProcess::Clock::now() - sent).count();
  const long first = steps_ + 1;
  const auto it = j.find("step_s");
  if (it == j.end() || !it->is_array() || it->size() > size_t(count))
    throw child_.failure(fmt::format("sent garbage in reply to 'steps' {} to {}: 'step_s' is not a list of at most {} "
                                     "step times in '{}'",
                                     first, first + count - 1, count, excerpt(j.dump())));
  const int done = static_cast<int>(it->size());
  std::string stopped;  // the engine's word for the step after the last it did
  if (done < count) {
    const auto e = j.find("error");
    if (e == j.end())
      throw child_.failure(fmt::format("sent {} step time(s) in reply to 'steps' {} to {}, and no 'error' saying why it "
                                       "stopped short",
                                       done, first, first + count - 1));
    stopped = e->is_string() ? e->get<std::string>() : e->dump();
  }
  const double waited = wait_share(round_trip);
  double sum = 0;
  try {
    const StateLayout layout = done > 0 ? state_layout(j, "steps", size_t(done)) : StateLayout{};
    for (int k = 0; k < done; ++k) {
      ++steps_, t_ += dt;
      const double own = checked_step_time((*it)[size_t(k)], round_trip);
      // Steps in one round trip are spent inside it together.
      if (!((sum += own) <= round_trip + kStepClockTolerance))
        throw child_.failure(fmt::format("reported step times summing to {:.6g} s for steps {} to {}, longer than the "
                                         "round trip the harness measured for them ({:.6g} s, tolerance {:g} s): its "
                                         "own timing cannot be used",
                                         sum, first, steps_, round_trip, kStepClockTolerance));
      read_block(layout, size_t(k), out.states[size_t(k)], "steps");
      out.times[size_t(k)] = {own, own * (1 - waited)};
      out.done = k + 1;
    }
  } catch (...) {
    out.failure = std::current_exception();
    return;
  }
  if (done < count)
    out.failure = std::make_exception_ptr(std::runtime_error(
        fmt::format("engine process {} refused 'steps' at step {}: {}", child_.label(), steps_ + 1, stopped)));
}

// The engine's own step time is checked against the harness's clock: it is spent inside the
// round trip, so it can be neither 0 nor longer than it (kStepClockTolerance for two clocks).
double ProtocolClient::checked_step_time(const nlohmann::json& value, double round_trip) {
  if (!value.is_number())
    throw child_.failure(fmt::format("sent garbage in reply to a step: step {}'s time 'step_s' is {}, not a number",
                                     steps_, excerpt(value.dump())));
  const double own = value.get<double>();
  if (!(own > 0) || !(own <= round_trip + kStepClockTolerance))
    throw child_.failure(fmt::format("reported a step time of {:.6g} s for step {}, which is {} the round trip the "
                                     "harness measured for it ({:.6g} s, tolerance {:g} s): its own timing cannot be "
                                     "used",
                                     own, steps_, own > 0 ? "longer than" : "not above 0 and so not within", round_trip,
                                     kStepClockTolerance));
  return own;
}

// The process waits for a core only while it has work: between two replies that is this round
// trip, so the wait's share of it is the share of its steps that other work took.
double ProtocolClient::wait_share(double round_trip) const {
  return round_trip > 0 ? std::clamp(wait_since_s_ / round_trip, 0.0, 1.0) : 0.0;
}

// The state's time is the steps' dts summed, to a relative 1e-9 and the round-off of summing them
// (in float for an engine whose handshake says "precision": "float"): a state of another step (a
// reply sent twice, a step skipped) or a clock of its own is an error, not a shifted trajectory.
void ProtocolClient::check_time(double t, const char* op) {
  const double eps = float_precision_ ? 0x1p-23 : 0x1p-52;
  const double tolerance = std::abs(t_) * (1e-9 + static_cast<double>(steps_) * eps) + 1e-12;
  if (std::isfinite(t) && std::abs(t - t_) <= tolerance) return;
  throw child_.failure(fmt::format("sent a state at t = {} s in reply to '{}' after {} step(s), whose dts sum to {} s "
                                   "(a reply sent twice, a step skipped, or another clock: one reply per request, t "
                                   "the simulated time)",
                                   t, op, steps_, t_));
}

void ProtocolClient::read(State& out) { read_state(request({{"op", "read"}}, "read"), out, "read"); }

nlohmann::json ProtocolClient::request(const nlohmann::json& message, const char* op) {
  const auto deadline = ChildProcess::Clock::now() + std::chrono::duration_cast<ChildProcess::Clock::duration>(
                                                          std::chrono::duration<double>(timeout_s_));
  // Every reply so far was taken: anything waiting now is a reply no request asked for.
  if (child_.has_unread_output())
    throw child_.failure(fmt::format("sent more than one reply before '{}' was asked (one reply per request)", op));
  child_.write(message.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n", deadline);
  return reply(op);
}

nlohmann::json ProtocolClient::reply(const char* op, bool stop_on_interrupt) {
  const auto deadline = ChildProcess::Clock::now() + std::chrono::duration_cast<ChildProcess::Clock::duration>(
                                                          std::chrono::duration<double>(timeout_s_));
  const std::string line = child_.read_line(deadline, kMaxReplyLine, stop_on_interrupt);
  if (const auto w = wait_.waited_s()) wait_since_s_ = *w - waited_s_, waited_s_ = *w;
  const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("ok") || !j["ok"].is_boolean())
    throw child_.failure(fmt::format("sent garbage in reply to '{}': '{}' is not a JSON object with \"ok\"", op, excerpt(line)));
  if (j["ok"].get<bool>()) return j;
  const nlohmann::json& e = j.contains("error") ? j["error"] : nlohmann::json("(no message)");
  const nlohmann::json& k = j.contains("kind") ? j["kind"] : nlohmann::json("engine");
  const std::string error = e.is_string() ? e.get<std::string>() : e.dump();
  const std::string kind = k.is_string() ? k.get<std::string>() : k.dump();
  if (kind == "settings") throw InputError(error);  // the user's settings: "settings.ENGINE.KEY: why"
  if (kind == "unsupported" && std::string_view(op) == "scene") throw SceneUnsupported(error);
  if (kind != "engine" && kind != "unavailable" && kind != "unsupported")
    throw child_.failure(fmt::format("sent garbage in reply to '{}': error kind '{}' (engine, settings, unsupported or "
                                     "unavailable) with '{}'",
                                     op, excerpt(kind), excerpt(error)));
  throw std::runtime_error(fmt::format("engine process {} refused '{}': {}", child_.label(), op, error));
}

ProtocolClient::StateLayout ProtocolClient::state_layout(const nlohmann::json& reply, const char* op, size_t states) {
  const auto it = reply.find("state");
  std::vector<std::string> fields;
  StateLayout l;
  try {
    if (it == reply.end()) throw std::runtime_error("no 'state'");
    if (!it->is_object()) throw std::runtime_error("'state' is not an object");
    for (const char* key : {"n", "t", "fields"})
      if (!it->contains(key)) throw std::runtime_error(fmt::format("'{}' is missing", key));
    if (!it->at("n").is_number_integer()) throw std::runtime_error("'n' is not a whole number");
    l.n = it->at("n").get<long>();
    // One state: t is its time; several (a reply to 'steps'): t lists each one's.
    const nlohmann::json& t = it->at("t");
    if (std::string_view(op) != "steps") {
      if (!t.is_number()) throw std::runtime_error("'t' is not a number");
      l.t = {t.get<double>()};
    } else {
      if (!t.is_array() || t.size() != states)
        throw std::runtime_error(fmt::format("'t' is not a list of {} times, one per step done", states));
      for (const auto& v : t) {
        if (!v.is_number()) throw std::runtime_error("'t' holds a non-number");
        l.t.push_back(v.get<double>());
      }
    }
    fields = strings_from(it->at("fields"), "fields", false);
  } catch (const std::exception& e) {
    throw child_.failure(fmt::format("sent garbage in reply to '{}': {} in '{}'", op, e.what(), excerpt(reply.dump())));
  }
  if (l.n != n_) throw child_.failure(fmt::format("sent a state of {} balls in reply to '{}'; the scene has {}", l.n, op, n_));
  constexpr size_t kMaxFields = 16;  // id, x, y, vx, vy and room for more (w, ...), not a memory bomb
  if (fields.size() > kMaxFields)
    throw child_.failure(fmt::format("sent a state of {} fields in reply to '{}' (at most {})", fields.size(), op, kMaxFields));
  const auto col = [&](const char* name) -> long {
    const long c = std::find(fields.begin(), fields.end(), name) - fields.begin();
    return c == static_cast<long>(fields.size()) ? -1 : c;
  };
  for (const char* need : {"id", "x", "y", "vx", "vy"})
    if (col(need) < 0) throw child_.failure(fmt::format("sent a state without '{}' in reply to '{}'", need, op));
  // A scene that rotates needs every ball's angular velocity and angle back (PROTOCOL.md, States).
  if (rotation_)
    for (const char* need : {"w", "angle"})
      if (col(need) < 0)
        throw child_.failure(fmt::format(
            "sent a state without '{}' in reply to '{}'; the scene rotates (friction or spin), so its states need 'w' and 'angle'",
            need, op));
  l.id = col("id"), l.x = col("x"), l.y = col("y"), l.vx = col("vx"), l.vy = col("vy");
  if (rotation_) l.w = col("w"), l.angle = col("angle");
  l.fields = fields.size();
  return l;
}

void ProtocolClient::read_block(const StateLayout& l, size_t k, State& out, const char* op) {
  const long n = l.n;
  block_.resize(l.fields * static_cast<size_t>(n));
  const auto deadline = ChildProcess::Clock::now() + std::chrono::duration_cast<ChildProcess::Clock::duration>(
                                                          std::chrono::duration<double>(timeout_s_));
  child_.read_bytes(block_.data(), block_.size() * sizeof(double), deadline);
  check_time(l.t[k], op);
  out.t = l.t[k];
  out.resize(static_cast<int>(n), rotation_);
  const double* ids = block_.data() + l.id * n;
  const double *x = block_.data() + l.x * n, *y = block_.data() + l.y * n;
  const double *vx = block_.data() + l.vx * n, *vy = block_.data() + l.vy * n;
  const double *w = rotation_ ? block_.data() + l.w * n : nullptr;
  const double *angle = rotation_ ? block_.data() + l.angle * n : nullptr;
  seen_.assign(static_cast<size_t>(n), 0);
  for (long r = 0; r < n; ++r) {
    const double id = ids[r];
    if (!(id >= 0 && id < static_cast<double>(n) && id == std::floor(id)) || seen_[static_cast<size_t>(id)])
      throw child_.failure(
          fmt::format("sent garbage in reply to '{}': ball id {} at row {} is not a new index below {}", op, id, r, n));
    const long i = static_cast<long>(id);
    seen_[static_cast<size_t>(i)] = 1;
    out.pos(i, 0) = x[r], out.pos(i, 1) = y[r], out.vel(i, 0) = vx[r], out.vel(i, 1) = vy[r];
    if (rotation_) out.w(i) = w[r], out.angle(i) = angle[r];
  }
}

void ProtocolClient::read_state(const nlohmann::json& reply, State& out, const char* op) {
  read_block(state_layout(reply, op, 1), 0, out, op);
}

}  // namespace ballbench
