#pragma once
// Where and when tunnelling and sticking happened: one record per counted event, for the
// trajectory viewer (reports/viewer_page.h) and anyone reading a run's JSON. The counts in
// the result's metrics stay the totals; a run keeps only its first kEventsKept records.
#include <cstddef>
#include <string>

namespace ballbench {

enum class EventKind { TunnelWall, TunnelPair, StickWall, StickPair };

// "tunnel-wall", "tunnel-pair", "stick-wall", "stick-pair": the names in the JSON and the viewer.
const char* event_kind_name(EventKind kind);
// The kind of a name above; throws InputError for any other.
EventKind event_kind_from_name(const std::string& name);

struct Event {
  EventKind kind = EventKind::TunnelWall;
  // Tunnelling: the step whose motion showed it. Sticking: the step of the sample that counted the
  // episode (the tolerance was exceeded for stuck_samples samples before it).
  long step = 0;
  double t = 0;  // the simulated time of that step's state (s)
  int i = 0;     // the ball; a pair's first ball (i < j)
  int j = -1;    // a pair's second ball; -1 for a wall
  // Where (m): a wall escape, where the ball's straight step crosses the box; a pass-through, the
  // midpoint of the two centres at their closest approach along the straight steps; a stuck ball,
  // its centre; a stuck pair, the midpoint of the two centres.
  double x = 0, y = 0;

  bool operator==(const Event&) const = default;
};

// A run keeps its first events only: a broken engine can tunnel millions of times, and 200 events
// already cover every episode of a run worth looking at without letting a results file or a
// viewer page grow with the run's length.
inline constexpr std::size_t kEventsKept = 200;

}  // namespace ballbench
