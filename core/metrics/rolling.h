#pragma once
// A ball on the floor of a box under gravity, with Coulomb friction mu: what it must end doing,
// in closed form from the scene (scenes that ask, [metrics] rolling = true), each ball on its own:
// the scene keeps its balls from meeting each other or a side wall, which no closed form here covers.
// - Speed: friction, gravity and the floor's push all act along lines through the contact point
//   under the centre, so the ball's angular momentum about that point, m r v + I w, is kept, from
//   the first contact through any impact to rolling (v = -w r): with I = k m r^2,
//     v_roll = (v0 - k r w0) / (1 + k)
//   (the bowling-ball problem, e.g. Kleppner and Kolenkow, An Introduction to Mechanics, ch. 7).
//   Slide to roll (w0 = 0): v0 / (1 + k).
// - Time to roll: sliding, friction mu m g slows the contact point's slip u = v + w r by
//   mu g (1 + 1 / k) per second, so it rolls |u| / (mu g (1 + 1 / k)) after its first contact
//   (slide to roll: v0 k / ((1 + k) mu g)). A ball dropped with restitution 0 meets the floor at
//   v_i = sqrt(vy0^2 + 2 g h); the impact's Coulomb impulse law (Brach, "Rigid body collisions",
//   J. Appl. Mech. 56, 1989; core/solver/rough_impact.h) stops the slip if mu m v_i reaches the
//   tangential impulse that needs, m k |u0| / (1 + k), and otherwise takes mu v_i (1 + 1 / k) off it.
//   A ball that bounces (restitution above 0, starting above the floor) has no closed form here.
#include <optional>

#include "scene.h"

namespace ballbench {

struct RollingClosedForm {
  double speed = 0;                    // v_roll (m/s, along x)
  std::optional<double> time_to_roll;  // (s); none for a ball that bounces
};

// Ball i of a scene that asks for `rolling` (a floor, friction above 0: scene_loader.cpp checks).
RollingClosedForm rolling_closed_form(const Scene& scene, int i);

}  // namespace ballbench
