#pragma once
// Everything one exact run holds, as plain data: the model and the balls (exact_world.h), the
// neighbour grid, the event queue, the balls to re-predict, the scratch of cluster settling and of
// sleeping, and the clock. The stages (exact_events.h, exact_cluster.h, exact_sleep.h,
// exact_friction.h) are free functions over it; the Engine adapter (exact.cpp) only holds one.
#include "scene.h"
#include "solver/exact.h"
#include "solver/exact_cluster.h"
#include "solver/exact_grid.h"
#include "solver/exact_queue.h"
#include "solver/exact_sleep.h"
#include "solver/exact_world.h"

namespace ballbench {

struct ExactSim {
  ExactModel model;
  ExactBalls balls;
  ExactGrid grid;
  EventQueue queue;
  Repredictions repredict;
  ClusterScratch cluster;
  SleepScratch sleep;
  double now = 0;   // time of the event being processed (s)
  double time = 0;  // time of the last completed step (s)

  // The scene's balls at rest in their cells, each with its first event predicted.
  ExactSim(const Scene& scene, const ExactSettings& settings);
};

}  // namespace ballbench
