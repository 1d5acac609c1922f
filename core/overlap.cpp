#include "overlap.h"

#include <cmath>
#include <cstdint>
#include <iterator>
#include <utility>

namespace ballbench {

void overlapping_pairs(const Eigen::MatrixX2d& pos, const Eigen::VectorXd& radius, OverlapScratch& scratch,
                       std::vector<Overlap>& out) {
  out.clear();
  const int n = static_cast<int>(pos.rows());
  if (n < 2) return;
  UniformGrid& grid = scratch.grid;
  grid.build(pos, 2.0 * radius.maxCoeff());
  const int* order = grid.order().data();
  CellOrderedBalls& balls = scratch.balls;
  balls.resize(n);
  balls.gather(order, pos, radius, 0, n);
  const double *x = balls.x.data(), *y = balls.y.data(), *r = balls.r.data();
  // The same pairs in the same order as for_each_candidate_pair (the rest of a ball's cell, the
  // next cell in its row, the three cells of the next row), as runs over the copies.
  grid.for_each_forward_range([&](int a, int begin, int end) {
    const double xa = x[a], ya = y[a], ra = r[a];
    for (int b = begin; b < end; ++b) {
      const double dx = xa - x[b], dy = ya - y[b], rs = ra + r[b], d2 = dx * dx + dy * dy;
      if (d2 < rs * rs) [[unlikely]] {
        const int i = order[a], j = order[b];
        out.push_back({std::min(i, j), std::max(i, j), rs - std::sqrt(d2)});
      }
    }
  });
}

std::optional<std::pair<int, int>> first_overlapping_pair(const Eigen::MatrixX2d& pos, const Eigen::VectorXd& radius) {
  OverlapScratch scratch;
  std::vector<Overlap> found;
  overlapping_pairs(pos, radius, scratch, found);
  if (found.empty()) return std::nullopt;
  auto best = found.front();
  for (const auto& o : found)
    if (o.i < best.i || (o.i == best.i && o.j < best.j)) best = o;
  return std::make_pair(best.i, best.j);
}

namespace {

// splitmix64's finaliser: spreads keys of neighbouring cells over the table.
uint64_t mix(uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

size_t table_size(size_t balls) {
  size_t size = 16;
  while (size < balls + balls / 2) size *= 2;  // at most two thirds full
  return size;
}

}  // namespace

OverlapIndex::OverlapIndex(double cell, size_t expected)
    : cell_(cell), keys_(table_size(expected)), head_(keys_.size(), -1) {
  blocks_.reserve(expected);  // at most a block a ball; untouched room costs no memory
}

size_t OverlapIndex::slot(long long key) const {
  const size_t mask = keys_.size() - 1;
  size_t at = mix(static_cast<uint64_t>(key)) & mask;
  while (head_[at] >= 0 && keys_[at] != key) at = (at + 1) & mask;
  return at;
}

void OverlapIndex::grow() {
  std::vector<long long> keys = std::move(keys_);
  std::vector<int> head = std::move(head_);
  keys_.assign(keys.size() * 2, 0), head_.assign(keys.size() * 2, -1);
  for (size_t k = 0; k < keys.size(); ++k)
    if (head[k] >= 0) {
      const size_t at = slot(keys[k]);
      keys_[at] = keys[k], head_[at] = head[k];
    }
}

void OverlapIndex::insert(const Eigen::Vector2d& p) {
  if (3 * (cells_ + 1) > 2 * keys_.size()) grow();
  const long long k = key(std::llround(std::floor(p.x() / cell_)), std::llround(std::floor(p.y() / cell_)));
  const size_t at = slot(k);
  if (head_[at] < 0) keys_[at] = k, ++cells_;
  if (head_[at] < 0 || blocks_[head_[at]].count == static_cast<int>(std::size(Block{}.ball))) {
    blocks_.push_back(Block{head_[at], 0, {}});
    head_[at] = static_cast<int>(blocks_.size()) - 1;
  }
  Block& b = blocks_[head_[at]];
  b.ball[b.count++] = balls_++;
}

bool OverlapIndex::overlaps(const Eigen::Vector2d& p, double r, const std::vector<Eigen::Vector2d>& pos,
                            const std::vector<double>& radius) const {
  const long long cx = std::llround(std::floor(p.x() / cell_)), cy = std::llround(std::floor(p.y() / cell_));
  for (long long dy = -1; dy <= 1; ++dy)
    for (long long dx = -1; dx <= 1; ++dx)
      for (int b = head_[slot(key(cx + dx, cy + dy))]; b >= 0; b = blocks_[b].next)
        for (int k = 0; k < blocks_[b].count; ++k) {
          const int j = blocks_[b].ball[k];
          const double rs = r + radius[j];
          if ((p - pos[j]).squaredNorm() < rs * rs) return true;
        }
  return false;
}

}  // namespace ballbench
