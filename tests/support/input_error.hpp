#pragma once
// The message of the cic::InputError that `f` throws, or "(no cic::InputError)".
#include <string>

#include "cic/core/error.hpp"

namespace cic::testing {

template <class F>
std::string input_error(F f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no cic::InputError)";
}

} // namespace cic::testing
