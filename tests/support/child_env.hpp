// Environment prefixes for tests that start child processes.
#pragma once

#include <cstdlib>
#include <string>

namespace cic::testing {

// `env ASAN_OPTIONS=...:detect_leaks=0 ` for children that load third-party runtimes
// (Mesa's GL drivers under xvfb-run, Open MPI's components under mpirun). Those
// dlopen modules, keep allocations for the process lifetime and dlclose the modules
// at exit, so LeakSanitizer reports frames from `<unknown module>` that no
// suppression file can name. Our own code on the same paths stays leak-checked by
// the tests that run it without those runtimes. Outside a sanitizer build the
// option is ignored.
inline std::string without_leak_check() {
    const char* current = std::getenv("ASAN_OPTIONS");
    std::string options = current ? current : "";
    if (!options.empty()) options += ":";
    return "env ASAN_OPTIONS='" + options + "detect_leaks=0' ";
}

} // namespace cic::testing
