#pragma once
// A fork-join loop on threads, for pure per-item work in one process
// (symbolic regression's evaluations). Robot evaluations use worker
// processes instead (process_pool.hpp): ODE's global state forbids threads.
#include <cstddef>
#include <functional>

namespace cic {

// Runs fn(i) for i in [0, n) on `threads` threads (1 = inline). Exceptions are
// rethrown (the first by index). For pure, deterministic per-item work.
void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& fn);

// Number of hardware threads, at least 1.
int hardware_threads();

} // namespace cic
