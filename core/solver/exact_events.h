#pragma once
// exact's event loop: take the earliest predicted event from the queue, check it is still valid
// (its partner has not changed course since), process it (a pair impact, a wall impact, a cell
// crossing, the start of rolling), and predict again for every ball whose course it changed; until
// the next event lies beyond the step's end, where every ball is brought to that time.
namespace ballbench {

struct ExactSim;

// Ball i's earliest event from sim.now on, into the queue.
void predict(ExactSim& sim, int i);
// Processes every event up to t_end (s) and brings every ball there. Throws std::runtime_error
// when a ball exceeds max_events_per_ball or meets a case without a closed form.
void run_events_until(ExactSim& sim, double t_end);

}  // namespace ballbench
