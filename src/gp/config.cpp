// Depths that follow from the GP settings (see config.hpp).
#include "cic/gp/config.hpp"

namespace cic::gp {

int levels(const GpConfig& cfg, InitMethod method, int depth) {
    return depth + (method == InitMethod::Ptc1 && cfg.ptc1_root_depth == 0 ? 1 : 0);
}

int GpConfig::generated_tree_levels() const { return levels(*this, init_method, max_init_depth); }

int GpConfig::generated_forest_depth() const {
    return forest_depth == ForestDepth::Sum ? trees_per_genotype * generated_tree_levels() : generated_tree_levels();
}

} // namespace cic::gp
