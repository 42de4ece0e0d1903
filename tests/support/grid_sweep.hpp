// The sweep tests' study (sweep_test.cpp, sweep_file_test.cpp).
#pragma once

#include <filesystem>
#include <string>

#include "support/run_helpers.hpp"

namespace cic::testing {

// A 2 x 2 grid (GP.elitism 0 1, Neural.sampleAverageCount 1 2) with 3 repeats,
// seeds from 4, of tiny HyperGP runs on R0.
inline std::string grid_sweep_text(const std::filesystem::path& study, int generations = 3) {
    return tiny_sweep_text("tiny", study, 6, generations, 2.5,
                           "<grid>\n    <vary key=\"GP.elitism\">0 1</vary>\n"
                           "    <vary key=\"Neural.sampleAverageCount\">1 2</vary>\n  </grid>",
                           3, 4);
}

} // namespace cic::testing
