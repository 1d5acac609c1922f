#pragma once
// The trajectory viewer: a self-contained HTML page (reports/viewer/viewer.html, compiled in) with
// the runs of one scene side by side, played back from their frames (Result::series::frames), with
// the tracks of the first balls, every tunnelling and sticking event (Result::events) where and
// when it happened, and energy over time; each run in its engine's colour and its profile's line
// style (palette.h), and no path of the machine that made it. `ballbench report` writes one per
// seed scene, `ballbench view` one for any run file.
#include <string>
#include <vector>

#include "result.h"
#include "scene.h"

namespace ballbench {

// What a page of every engine of a scene may weigh (bytes): a few MB open at once in a browser,
// and small enough to keep beside the report. Frames take kViewerFrameBudget of it; events (at
// most kEventsKept per run), energy series and the page itself the rest.
inline constexpr double kViewerPageBytes = 4e6;
inline constexpr double kViewerFrameBudget = 3.5e6;

// RunOptions::frames for `runs` runs of `scene` on one page: as many as the frame budget holds (a
// frame costs every ball's two coordinates, whole numbers of 0.1 mm as wide as the container
// makes them), at most one per step.
int viewer_frames(const Scene& scene, int runs);

// When a run that did not end ok stopped (s): the step it diverged at, else its last completed one.
// Its last frame may come before (frames are every few steps), so pages and GIFs say this time.
double stop_time(const Result& r);

// The page for `runs`: every run of one scene, some with frames. Throws InputError when they are
// of different scenes or none has frames.
std::string viewer_page(const std::vector<const Result*>& runs);

}  // namespace ballbench
