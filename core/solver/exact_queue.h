#pragma once
// exact's event queue: each ball's earliest predicted event (contact.h's PredictedEvent), in an
// indexed binary heap with one entry per ball ordered by (time, ball), so the next event is at the
// top and a ball's new prediction moves its one entry up or down. Also the codes of the events a
// ball can have besides a ball or a wall, and the order of a ball's candidates at one time.
#include <vector>

#include "solver/contact.h"

namespace ballbench {

// A ball's events: a pair (j >= 0; cj, the partner's course counter when predicted), a wall
// (wall_partner), or the ball crossing a face of its grid cell (cell_face: of axis 0 or 1, towards
// the lower (0) or upper (1) cell).
constexpr int cell_face(int axis, int up) { return -5 - (2 * axis + up); }
// A rough ball sliding on a wall whose slip reaches zero: it starts to roll (on_roll).
constexpr int kRollEvent = -9;
constexpr bool is_cell_face(int j) { return j <= -5 && j > kRollEvent; }
constexpr int cell_face_axis(int j) { return (-5 - j) >> 1; }
constexpr int cell_face_up(int j) { return (-5 - j) & 1; }

// A ball's candidates at one time in a fixed order: balls by index, then walls, then cell faces,
// then the start of rolling.
inline int event_rank(int j) { return j >= 0 ? 0 : j == kRollEvent ? 3 : is_cell_face(j) ? 2 : 1; }
inline bool sooner(const PredictedEvent& a, const PredictedEvent& b) {
  if (a.t != b.t) return a.t < b.t;
  const int ra = event_rank(a.j), rb = event_rank(b.j);
  if (ra != rb) return ra < rb;
  return ra == 0 ? a.j < b.j : a.j > b.j;  // walls and faces by code, -1 - j and -5 - j
}

class EventQueue {
 public:
  explicit EventQueue(int n) : event_(n), heap_(n), slot_(n) {
    for (int i = 0; i < n; ++i) heap_[i] = i, slot_[i] = i;
  }

  bool empty() const { return heap_.empty(); }
  // The ball whose event comes first.
  int top() const { return heap_[0]; }
  const PredictedEvent& event(int i) const { return event_[i]; }

  // Ball i's new earliest event: its entry moves to its place.
  void set(int i, const PredictedEvent& ev) {
    event_[i] = ev;
    const int n = static_cast<int>(heap_.size());
    int k = slot_[i];
    while (k > 0) {
      const int parent = (k - 1) / 2;
      if (!before(i, heap_[parent])) break;
      heap_[k] = heap_[parent], slot_[heap_[k]] = k;
      k = parent;
    }
    for (;;) {
      int child = 2 * k + 1;
      if (child >= n) break;
      if (child + 1 < n && before(heap_[child + 1], heap_[child])) ++child;
      if (!before(heap_[child], i)) break;
      heap_[k] = heap_[child], slot_[heap_[k]] = k;
      k = child;
    }
    heap_[k] = i, slot_[i] = k;
  }

 private:
  bool before(int a, int b) const {
    const double ta = event_[a].t, tb = event_[b].t;
    return ta < tb || (ta == tb && a < b);
  }

  std::vector<PredictedEvent> event_;  // each ball's earliest predicted event
  std::vector<int> heap_;              // balls, heap-ordered by their events
  std::vector<int> slot_;              // slot_[i]: ball i's position in heap_
};

}  // namespace ballbench
