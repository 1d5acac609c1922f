#pragma once
// The reference recorded once per scene and replayed beside every engine's run. A comparison table
// runs every engine and profile on one scene against the same reference, which on a friction scene
// is a converged run at dt / 64, most of the table's time: run_all records it once, in a child
// process with the runs' time limit (a reference that hangs or crashes costs no more than one run),
// and each run replays it. Where it cannot be recorded (too large, timed out, crashed,
// interrupted), each run steps its own. The figures are the same either way: reading an engine's
// state does not change it, and every run replays the one trajectory.
#include <memory>
#include <string>
#include <vector>

#include "engine.h"
#include "runner.h"
#include "scene.h"
#include "state.h"

namespace ballbench {

// Which reference runs beside a run of `scene`, and how.
struct ReferenceChoice {
  const EngineEntry* entry = nullptr;  // null: none
  int substeps = 1;                    // its steps per scene step (kConvergedSubsteps: a converged run)
  std::string skipped;                 // why none runs where one was asked for ("" otherwise)
};
ReferenceChoice choose_reference(const Scene& scene, const RunOptions& options);

// The reference's states at scene steps 0 .. steps, or up to the step that threw.
struct RecordedReference {
  std::string engine;       // EngineInfo::name of what ran
  std::string scene_digest; // scene_digest() of the scene it ran
  int substeps = 1;
  double dt = 0;            // the scene's step
  long steps = 0;           // the scene steps recorded (states has steps + 1 entries, or fewer on a failure)
  std::vector<State> states;
  long failed_step = -1;    // the scene step whose stepping threw (0: building it), or -1
  std::string failure;      // what it threw
};

// A recording larger than this is not made: each run then steps its own reference.
inline constexpr double kMaxRecordedReferenceBytes = 512.0 * (1 << 20);

// Null where the scene has no reference or it could not be recorded within timeout_s.
std::shared_ptr<const RecordedReference> record_reference(const Scene& scene, const RunOptions& options,
                                                          double timeout_s);

// True where `recorded` is the reference `choice` would run on `scene` for `steps` steps.
bool recording_fits(const RecordedReference& recorded, const Scene& scene, const ReferenceChoice& choice,
                    long steps);

// An engine that replays a recording, stepped as the reference was (substeps per scene step).
std::unique_ptr<Engine> replay_reference(std::shared_ptr<const RecordedReference> recorded);

}  // namespace ballbench
