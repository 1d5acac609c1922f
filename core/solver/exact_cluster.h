#pragma once
// Cluster settling: a slow impact (below rest_velocity) is a ball settling into contact, usually
// among others that touch. Resolved one binary collision at a time, such a contact network needs
// thousands of zero-time collisions (the Gauss-Seidel iteration of one multi-contact impact,
// converging slower the more nearly opposite the contact normals), so it is resolved at once
// instead, as one simultaneous perfectly inelastic impact (Moreau's contact dynamics at one
// instant): the balls touching the pair through awake balls, with their contacts among themselves
// and with walls and sleeping balls, get the impulses that leave no contact closing. Then slow
// balls whose weight is carried fall asleep (exact_sleep.h), and pressed contacts of the others get
// their micro-bounce. Contacts closing faster than rest_velocity are left to the binary events
// that follow at the same time.
//
// A ball in more than kJamEvents collisions within t_c (jammed: falling into a wedge, where each
// binary collision takes only a sliver of its momentum along nearly opposite normals) has its
// contacts settled the same way whatever their speed (`jammed`): a sustained multi-contact, as in
// the TC model, here taken as perfectly inelastic.
#include <cstdint>
#include <vector>

#include "solver/contact.h"
#include "solver/lemke.h"

namespace ballbench {

struct ExactSim;

// A contact of a cluster being settled; j < 0: a wall or a sleeping ball, held still.
struct ClusterContact : Contact {
  double target;  // normal separation speed wanted (m/s)
  bool firm;      // crept to the overlap cap, or pressed: even a slow closing is stopped
  double n(int axis) const { return axis == 0 ? nx : ny; }
};

struct ClusterScratch {
  std::vector<int> members;              // balls of the cluster, in the order they joined
  std::vector<int> position;             // per ball: its index in members
  std::vector<uint32_t> joined_in;       // per ball: the settle it last joined
  uint32_t settle = 0;                   // settles so far
  std::vector<ClusterContact> contacts;  // of the cluster being settled
  std::vector<double> vel_before[2];     // members' velocities before settling
  std::vector<double> vel_inelastic[2];  // after the inelastic pass
  std::vector<double> rebound;           // each contact's micro-bounce target (m/s)
  std::vector<double> coupling, violation, impulse;  // Lemke's A, b and lambda
  LemkeScratch lemke;

  explicit ClusterScratch(int n) : position(n, 0), joined_in(n, 0) {}
};

// Settles the cluster around the impact of balls i and j (j < 0: ball i on a wall) at sim.now.
// Throws std::runtime_error under friction (a frictional multi-contact has no closed form).
void settle_cluster(ExactSim& sim, int i, int j, bool jammed);

}  // namespace ballbench
