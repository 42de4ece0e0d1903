#pragma once
// Settings of the symbolic-regression experiment (thesis 6.2.1): the plain
// struct lives with the other settings (io/settings.hpp), below this layer.
#include "cic/io/settings.hpp"

namespace cic::symreg {

using SymregConfig = io::SymregConfig;

} // namespace cic::symreg
