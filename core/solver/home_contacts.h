#pragma once
// The contacts home's events path solves by sequential impulses (Catto, "Iterative Dynamics with
// Temporal Coherence", GDC 2005): the contact pass's at the start of a step, warm started from the
// last step's impulses, and each resting cluster's in the event loop. Which target each contact
// gets, and why: make_contact below and core/solver/README.md, steps 3, 5 and 6.
#include <cstdint>
#include <vector>

#include "solver/contact.h"
#include "solver/home_step.h"
#include "solver/home_world.h"
#include "solver/warm_start.h"

namespace ballbench {

// A contact of the contact pass and of the cluster solves. With friction it also holds a
// tangential impulse, bounded by the friction coefficient times the normal impulse (Coulomb's law as
// sequential impulses: Catto, GDC 2005), in the tangent (-n_y, n_x).
struct PassContact : Contact {
  double target;  // least normal velocity wanted after the solve (m/s)
  bool moved;     // an impulse was applied (warm start or solve): both velocities may have changed
  double tangent_impulse = 0;  // accumulated friction impulse (N s); 0 without friction
  double tangent_mass = 0;     // effective mass along the tangent (rough_impact.h; kg)
};

class RestingContacts {
 public:
  RestingContacts() = default;
  // n balls. Elastic scenes have no contact pass, but a grazing event that rounds to a resting
  // impact still solves its cluster.
  explicit RestingContacts(int n);

  void clear() { contacts_.clear(); }
  size_t size() const { return contacts_.size(); }

  // make_contact's contact for pair (i, j) at separation (dx, dy), |d|^2 = d2 > 0, relative
  // velocity (wx, wy) and radius sum rs, into `c`; false if there is none. Reads the state only,
  // so the parts of a screen call it in parallel.
  bool make_pair_contact(const HomeWorld& w, const EventStep& s, int i, int j, double dx, double dy, double d2,
                         double wx, double wy, double rs, double horizon, bool close_overlap, PassContact& c) const;
  // Warm start: the impulse contact c ended the last contact pass with, if it had one. Only looked
  // up: the impulses are applied in solve_pass, in the contacts' order.
  void find_warm_impulse(PassContact& c) const {
    if (const WarmStart::Entry* e = warm_.entry(c.i, c.j)) c.impulse = e->impulse, c.tangent_impulse = e->tangent, c.moved = true;
  }
  // find_warm_impulse for the contacts from `first` on.
  void find_warm_impulses(size_t first) {
    for (size_t k = first; k < contacts_.size(); ++k) find_warm_impulse(contacts_[k]);
  }
  void append(const std::vector<PassContact>& found) { contacts_.insert(contacts_.end(), found.begin(), found.end()); }

  // Adds a contact for every wall within max(touching, reach) of ball i (m).
  void add_wall_contacts(const HomeWorld& w, const EventStep& s, int i, double reach, double horizon, bool close_overlap);
  // Adds the contact of pair (i, j) if their gap is below max(touching, reach); returns whether it was.
  bool add_pair_contact(const HomeWorld& w, const EventStep& s, int i, int j, double reach, double horizon,
                        bool close_overlap);

  // Sweeps over the contacts until every one is within `tolerance` of its target or `sweeps` ran.
  // Returns the largest approach beyond a target left after the last sweep (m/s).
  double solve(HomeWorld& w, int sweeps, double tolerance);
  // The contact pass's solve: the warm-start impulses applied, `sweeps` of solve, both balls of
  // every contact that moved them marked active (their velocities changed after the screen), and
  // the impulses kept for the next step's warm start.
  void solve_pass(HomeWorld& w, EventStep& s, int sweeps);

  // The balls were renumbered (new_number[old ball]): the warm-start impulses follow them.
  void renumbered(const int* new_number) { warm_.renumber(new_number, false, warm_entries_); }

 private:
  bool make_contact(const HomeWorld& w, const EventStep& s, int i, int j, double nx, double ny, double vn, double gap,
                    double touch, double horizon, bool close_overlap, PassContact& c) const;
  void add_contact(const HomeWorld& w, const EventStep& s, int i, int j, double nx, double ny, double gap, double touch,
                   double horizon, bool close_overlap);
  double solve_friction(HomeWorld& w, PassContact& c);

  std::vector<PassContact> contacts_;
  std::vector<int> live_;        // contacts a sweep after the first still visits (see solve)
  std::vector<uint8_t> degree_;  // per ball: its contacts in the solve, saturating at 2; 0 between solves
  WarmStart warm_;               // impulses at the end of the last contact pass
  std::vector<WarmStart::Entry> warm_entries_;  // for rebuilding warm_
};

}  // namespace ballbench
