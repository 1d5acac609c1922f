// The home solver's own data structures, against brute force: the warm-start table and the grid's
// walk over its edge cells.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "fork_join.h"
#include "solver/home_grid.h"
#include "solver/warm_start.h"

namespace ballbench {
namespace {

TEST(WarmStart, FindsEveryStoredContactAndNothingElse) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> ball(0, 2000), partner(-4, 2000);
  std::map<std::pair<int, int>, double> stored;
  while (stored.size() < 3000) stored[{ball(rng), partner(rng)}] = 0.5 + static_cast<double>(stored.size());
  std::vector<WarmStart::Entry> entries;
  for (const auto& [key, impulse] : stored) entries.push_back({key.first, key.second, impulse});
  std::shuffle(entries.begin(), entries.end(), rng);

  WarmStart warm;
  warm.assign(entries);
  for (const auto& [key, impulse] : stored) EXPECT_EQ(warm.find(key.first, key.second), impulse);
  int absent = 0;
  for (int k = 0; k < 20000; ++k) {
    const int i = ball(rng), j = partner(rng);
    if (stored.count({i, j})) continue;
    ++absent;
    EXPECT_LT(warm.find(i, j), 0) << i << ", " << j;
  }
  EXPECT_GT(absent, 10000);

  std::map<std::pair<int, int>, double> seen;
  warm.for_each([&](const WarmStart::Entry& e) { EXPECT_TRUE(seen.emplace(std::make_pair(e.i, e.j), e.impulse).second); });
  EXPECT_EQ(seen, stored);

  warm.assign({});
  EXPECT_LT(warm.find(entries[0].i, entries[0].j), 0);
  int left = 0;
  warm.for_each([&](const WarmStart::Entry&) { ++left; });
  EXPECT_EQ(left, 0);
}

// The parallel counting sort gives the serial sort's slots on any number of parts, whether the
// balls come in random order (most are strays: in another part's cells) or nearly in cell order
// (renumbered a few steps ago: few strays), and whatever the cell size.
TEST(HomeGrid, ParallelSortGivesTheSerialSlots) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coord(-40.0, 40.0), jitter(-0.6, 0.6);
  const int n = 4000;
  Eigen::MatrixX2d pos(n, 2);
  for (int i = 0; i < n; ++i) pos(i, 0) = coord(rng), pos(i, 1) = coord(rng);
  for (bool near_sorted : {false, true}) {
    if (near_sorted) {  // cell order, then every ball moved a little
      ForkJoin one(1);
      HomeGrid sorter;
      sorter.build(pos, Eigen::VectorXd(), 1.5, one, false);
      Eigen::MatrixX2d moved(n, 2);
      for (int s = 0; s < n; ++s) moved.row(s) = pos.row(sorter.id()[s]) + Eigen::RowVector2d(jitter(rng), jitter(rng));
      pos = moved;
    }
    for (double cell : {0.9, 1.5, 6.0}) {
      ForkJoin one(1);
      HomeGrid serial;
      serial.build(pos, Eigen::VectorXd(), cell, one, true);
      for (int threads : {2, 3}) {
        ForkJoin pool(threads);
        HomeGrid grid;
        grid.build(pos, Eigen::VectorXd(), cell, pool, true);
        ASSERT_EQ(grid.cells(), serial.cells());
        for (int c = 0; c <= grid.cells(); ++c)
          ASSERT_EQ(grid.first(c), serial.first(c)) << "cell " << c << ", " << threads << " parts";
        for (int s = 0; s < n; ++s) {
          ASSERT_EQ(grid.id()[s], serial.id()[s]) << "slot " << s << ", " << threads << " parts, cell " << cell
                                                  << (near_sorted ? ", nearly sorted" : ", random order");
          ASSERT_EQ(grid.x()[s], pos(grid.id()[s], 0));  // the copy in slot order
          ASSERT_EQ(grid.y()[s], pos(grid.id()[s], 1));
        }
      }
    }
  }
}

// for_each_slot_beyond visits every ball beyond the four thresholds, each slot once, on one part
// and on two (the grid's parallel sort), whatever the cell size.
TEST(HomeGrid, EdgeWalkFindsEveryBallBeyondTheThresholds) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(-50.0, 50.0);
  const int n = 3000;
  Eigen::MatrixX2d pos(n, 2);
  for (int i = 0; i < n; ++i) pos(i, 0) = coord(rng), pos(i, 1) = coord(rng);
  for (int threads : {1, 2}) {
    ForkJoin pool(threads);
    for (double cell : {0.7, 3.0, 11.0, 200.0}) {
      HomeGrid grid;
      grid.build(pos, Eigen::VectorXd(), cell, pool, false);
      for (double margin : {0.0, 2.5, 9.0, 60.0}) {
        const double ax = -50 + margin, bx = 50 - margin, ay = -50 + margin, by = 50 - margin;
        std::multiset<int> visited;
        grid.for_each_slot_beyond(ax, bx, ay, by, [&](int s) { visited.insert(grid.id()[s]); });
        for (int i = 0; i < n; ++i) {
          const double x = pos(i, 0), y = pos(i, 1);
          const bool beyond = x <= ax || x >= bx || y <= ay || y >= by;
          EXPECT_LE(visited.count(i), 1u) << "ball " << i << " visited twice";
          if (beyond) {
            EXPECT_EQ(visited.count(i), 1u) << "ball " << i << " at (" << x << ", " << y << "), cell " << cell
                                            << ", margin " << margin << ", threads " << threads;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace ballbench
