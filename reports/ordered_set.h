#pragma once
// The distinct values of a sequence in the order they first appear: engines, scenes, knobs and
// ball counts in the order the results list them, for tables and figure legends.
#include <algorithm>
#include <vector>

namespace ballbench {

template <class T>
void add_once(std::vector<T>& seen, const T& value) {
  if (std::find(seen.begin(), seen.end(), value) == seen.end()) seen.push_back(value);
}

}  // namespace ballbench
