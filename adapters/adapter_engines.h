#pragma once
// The engines of the adapter folders, in the folders' alphabetical order: one entry per folder
// whose CMakeLists.txt called ballbench_adapter(NAME) (adapters/CMakeLists.txt generates the
// definition, adapter_engines.cpp in the build folder).
#include <vector>

#include "engine.h"

namespace ballbench {

std::vector<EngineEntry> adapter_engines();

}  // namespace ballbench
