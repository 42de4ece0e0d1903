#pragma once
// Resource bounds: inputs past these are refused with exit 2 before a run
// starts, naming the bound (docs/settings.md, "Limits"). Each sits far above
// every shipped and documented use: the thesis's robots have at most 25
// modules, its populations 50 individuals, its trees tens of nodes.
#include <cstddef>

namespace cic::limits {

inline constexpr std::size_t kMaxModules = 512;           // modules in one robot
inline constexpr std::size_t kMaxNeurons = 4096;          // substrate neurons (inputs + hidden + outputs)
inline constexpr std::size_t kMaxSynapses = 8'000'000;    // potential substrate synapses (all enabled types)
inline constexpr std::size_t kMaxTreeNodes = 100'000;     // nodes in one tree
inline constexpr std::size_t kMaxPopulation = 1'000'000;  // individuals in a population

} // namespace cic::limits
