#pragma once
// `home-seed`: a faithful port of the 2017 thesis's MATLAB programs (appendix 1, balls in a box;
// appendix 2, the bowl). It exists to reproduce and measure the thesis's problems (balls stuck in
// walls and in each other, fast balls jumping through), so none of them is fixed here.
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "engine.h"

namespace ballbench {

// "per-ball": one in-ball flag per ball (appendix 1, and its initial-overlap check);
// "per-pair": one flag per pair (appendix 2).
enum class SeedFlags { per_ball, per_pair };

// Declared as settings in home_seed.cpp's settings table.
struct HomeSeedSettings {
  SeedFlags flags = SeedFlags::per_ball;
  // Put a ball that ends up outside the box back inside it (appendix 2, lines 105-116).
  bool clamp = false;
};

EngineEntry home_seed_engine();

}  // namespace ballbench
