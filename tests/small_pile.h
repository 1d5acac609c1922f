#pragma once
// A small pile for the equal-accuracy tests: 60 balls settling in a narrow box, 3 s, quick at
// every step the searches try.
namespace ballbench {

inline constexpr const char* kSmallPile = R"(name = "small-pile"
dt = 0.01
duration = 3.0
gravity = [0.0, -9.81]
restitution = 0.3
[container]
min = [-1.0, 0.0]
max = [1.0, 6.0]
[random]
count = 60
radius = 0.1
pos_min = [-0.9, 0.1]
pos_max = [0.9, 5.0]
seed = 3
)";

}  // namespace ballbench
