#include "palette.h"

#include <array>
#include <string_view>
#include <utility>

#include <xxhash.h>

namespace ballbench {
namespace {

// Okabe-Ito (black, orange, sky blue, bluish green, blue, vermillion, reddish purple) and Paul
// Tol's muted indigo, olive, purple and wine, and a warm brown: eleven colours that stay apart
// for the common colour-vision deficiencies and on white. Okabe-Ito's yellow is left out: it
// vanishes on a white page.
constexpr std::array<std::pair<std::string_view, std::string_view>, 12> kEngineColours = {{
    {"home", "#0072B2"},       // ours: blue
    {"home-seed", "#777777"},  // the thesis's port: grey
    {"exact", "#000000"},      // the reference: black
    {"box2d", "#E69F00"},
    {"box2d3", "#D55E00"},     // Box2D v3: box2d's orange, deeper
    {"bullet", "#CC79A7"},
    {"chipmunk", "#009E73"},
    {"lammps", "#56B4E9"},
    {"ode", "#661100"},
    {"rapier", "#999933"},
    {"matter", "#332288"},
    {"planck", "#882255"},
}};

// For names not above: Tol's muted colours not used there, and grey.
constexpr std::array<std::string_view, 4> kSpareColours = {"#117733", "#44AA99", "#6699CC", "#AA4499"};

// A profile's line style by its name, the same for every engine that has it: the first profile
// of each engine solid, its alternatives dashed or dotted, the benchmark's sleeping variants
// dash-dot.
constexpr std::array<std::pair<std::string_view, int>, 7> kProfileDashes = {{
    {"default", 1},
    {"tuned", 1},
    {"hooke", 1},
    {"stock", 2},
    {"soft", 2},
    {"hertz", 2},
    {"events", 3},
}};

// A profile's marker (gnuplot's filled pointtypes), by the same rule as its line style.
constexpr std::array<std::pair<std::string_view, int>, 7> kProfilePoints = {{
    {"default", 7}, {"tuned", 7}, {"hooke", 7}, {"stock", 5}, {"soft", 9}, {"hertz", 5}, {"events", 13},
}};

constexpr std::array<std::string_view, 6> kTrackColours = {"#EE3377", "#009988", "#EE7733", "#33BBEE", "#CC3311",
                                                            "#BBBBBB"};

uint64_t name_hash(const std::string& name) { return XXH3_64bits(name.data(), name.size()); }

}  // namespace

RunStyle run_style(const std::string& engine, const std::string& profile) {
  RunStyle style{std::string(kSpareColours[name_hash(engine) % kSpareColours.size()]), 0};
  for (const auto& [name, colour] : kEngineColours)
    if (name == engine) style.colour = colour;
  for (const auto& [name, dash] : kProfileDashes)
    if (name == profile) style.dash = dash;
  if (style.dash == 0)
    style.dash = profile.ends_with("-sleep") ? 4 : 2 + static_cast<int>(name_hash(profile) % (kDashTypes - 1));
  style.point = profile.ends_with("-sleep") ? 11 : 0;
  for (const auto& [name, point] : kProfilePoints)
    if (name == profile) style.point = point;
  if (style.point == 0) style.point = 5 + 2 * static_cast<int>(name_hash(profile) % 5);  // 5, 7, 9, 11 or 13
  return style;
}

std::string track_colour(int ball) { return std::string(kTrackColours[static_cast<size_t>(ball) % kTrackColours.size()]); }

}  // namespace ballbench
